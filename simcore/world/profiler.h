#pragma once
// Per-stage timings and counters of the step: part of the engine's API, read by the runner's
// report and the editor's profiler panel.

#include "simcore/world/stages.h"

#include <array>
#include <chrono>
#include <cstdint>

namespace simcore {

struct StepCounters {
    std::uint32_t bodies = 0;
    std::uint32_t dynamicBodies = 0;
    std::uint32_t awakeBodies = 0;
    std::uint32_t pairs = 0;          // broad-phase pairs
    std::uint32_t droppedPairs = 0;   // new overlapping pairs not made this step: a body's contact cap
    std::uint32_t manifolds = 0;      // touching pairs with contact points
    std::uint32_t contactPoints = 0;
    std::uint32_t islands = 0;
    // Times a dynamic body's velocity was cut to the safety bound (1e5 m/s, a quarter turn per
    // substep) this step: more than zero means the simulation is unstable (a torn joint, say).
    std::uint32_t boundedVelocities = 0;
};

struct StepProfile {
    // Wall time per stage (ms), in the order of kStages; a per-substep stage's is summed over the
    // substeps. A skipped stage's is zero, or the time it took to find it had nothing to do.
    std::array<double, kStageCount> stageMs{};
    std::array<StageSkip, kStageCount> skipped{};  // why each stage did not run (Ran when it did)
    bool withWorkers = false;  // the stages that ran, ran on the pool's workers too (WorkerTuner's choice)
    std::array<std::uint32_t, kStageCount> handOvers{};  // jobs it offered the workers (TaskPool::jobsOffered)
    double totalMs = 0.0;                       // wall time of the whole step (ms)
    float maxPenetration = 0.0f;                // deepest contact overlap when the step began (m)
    StepCounters counters;
};

// Adds the elapsed wall time to a slot when it goes out of scope.
class ScopedStageTimer {
public:
    explicit ScopedStageTimer(double& accumulatorMs)
        : accumulatorMs_(accumulatorMs), start_(std::chrono::steady_clock::now()) {}
    ~ScopedStageTimer() {
        const auto end = std::chrono::steady_clock::now();
        accumulatorMs_ += std::chrono::duration<double, std::milli>(end - start_).count();
    }
    ScopedStageTimer(const ScopedStageTimer&) = delete;
    ScopedStageTimer& operator=(const ScopedStageTimer&) = delete;

private:
    double& accumulatorMs_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace simcore
