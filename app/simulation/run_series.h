#pragma once
// The run's measures over time, one sample per step, for the Profiler's plots: energy (kinetic,
// potential, total), the deepest penetration, the largest joint error and the time per stage. The
// samples form a ring of at most capacity() steps (the newest kept, as the timeline keeps its
// newest frames); a run resumed from an earlier step drops the samples after it, as the timeline
// drops its frames. Plain C++ on simcore; the simulation controller owns one and records after
// each step.

#include "simcore/world/profiler.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace simcore {
class World;
}

namespace interplay {

struct RunSample {
    std::uint64_t step = 0;       // the world's step count after the step
    double time = 0.0;            // s, simulated, at the end of the step
    double kineticEnergy = 0.0;   // J
    double potentialEnergy = 0.0; // J, relative to the origin (World::potentialEnergy)
    double maxPenetration = 0.0;  // m, deepest contact overlap when the step began
    double jointError = 0.0;      // m, the largest joint position error after the step
    std::array<double, simcore::kStageCount> stageMs{};  // wall time per stage (ms), kStages order
    double totalMs = 0.0;         // wall time of the whole step (ms)

    double totalEnergy() const { return kineticEnergy + potentialEnergy; }
};

class RunSeries {
public:
    // 18000 steps: five minutes at 60 Hz, about 3 MB of samples.
    static constexpr std::size_t kDefaultCapacity = 18000;

    explicit RunSeries(std::size_t capacity = kDefaultCapacity);

    // Samples `world` as its last step left it; the oldest sample goes when the ring is full.
    void record(const simcore::World& world) { append(sample(world)); }
    // The two halves of record, for samples taken on the thread that steps and kept on another.
    static RunSample sample(const simcore::World& world);
    void append(const RunSample& sample);
    void clear();
    // Drops the samples of steps after `step` (a run resumed from it records a new future).
    void truncateAfterStep(std::uint64_t step);

    std::size_t size() const { return m_samples.size(); }
    bool empty() const { return m_samples.empty(); }
    std::size_t capacity() const { return m_capacity; }
    const RunSample& operator[](std::size_t i) const { return m_samples[i]; }
    const RunSample& front() const { return m_samples.front(); }
    const RunSample& back() const { return m_samples.back(); }
    // The sample whose time is nearest `time` (s), or none when empty.
    std::optional<std::size_t> nearest(double time) const;

private:
    std::deque<RunSample> m_samples;  // oldest first, steps increasing
    std::size_t m_capacity;
};

}  // namespace interplay
