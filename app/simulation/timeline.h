#pragma once
// The run's recorded states, for scrubbing back and forth, stepping back, applying a past pose and
// resuming from one. Every step is a frame. A keyframe (the first frame, every kKeyframeInterval-th
// one, and the first after the world was changed between steps) holds a full copy of the world; the
// frames between hold only the force the owner applied before their step (the grab spring), so a
// frame is restored bit for bit by copying the keyframe before it and stepping on as the run did,
// at most kKeyframeInterval - 1 steps. Full copies, not poses: a run resumed from poses alone would
// lose the contacts' warm starts and the broad phase's tree and leave the recorded run at once.
//
// The frames form a ring bounded by a memory limit: a frame that does not fit drops the oldest
// keyframe with the frames that need it, so the newest are kept. Plain C++ on simcore; the
// controller owns one and records after each step.

#include "simcore/world/world.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>

namespace interplay {

// A force and torque acted on one body over a step (the grab spring), replayed with it.
struct AppliedForce {
    simcore::BodyId body;
    simcore::Vec3 force{0.0f};   // N, at the centre of mass
    simcore::Vec3 torque{0.0f};  // N m
};

// Adds `applied` to the world for its next step and wakes the body, as the run did: the one way
// the run and a replay apply it, so the replay steps through the same bits.
void applyForce(simcore::World& world, const AppliedForce& applied);

class Timeline {
public:
    static constexpr std::size_t kMiB = std::size_t{1} << 20;
    static constexpr std::size_t kDefaultMemoryLimit = 256 * kMiB;
    // Restoring a frame steps at most kKeyframeInterval - 1 times; the copies it saves cost memory.
    static constexpr int kKeyframeInterval = 10;

    explicit Timeline(std::size_t memoryLimitBytes = kDefaultMemoryLimit);

    // Drops the oldest frames that no longer fit.
    void setMemoryLimit(std::size_t bytes);
    std::size_t memoryLimit() const { return m_memoryLimit; }

    // Records `world` as it is now, after the step `input` (if any) acted over. `changed`: the world
    // was changed since the last frame other than by stepping (a body thrown in), so this frame
    // must be a keyframe. `trackedBodies` is kept with the frame for the owner (how many bodies it
    // had ids for then). A frame bigger than the whole limit is not kept.
    void record(const simcore::World& world, const std::optional<AppliedForce>& input, bool changed,
                std::size_t trackedBodies);
    void clear();
    // Drops every frame after `frame` (a run resumed from it records a new future).
    void truncateAfter(std::size_t frame);

    std::size_t frameCount() const { return m_frames.size(); }
    bool empty() const { return m_frames.empty(); }
    std::size_t keyframeCount() const;
    std::uint64_t stepOf(std::size_t frame) const { return m_frames.at(frame).step; }
    double timeOf(std::size_t frame) const { return m_frames.at(frame).time; }
    std::size_t trackedBodiesOf(std::size_t frame) const { return m_frames.at(frame).trackedBodies; }
    bool isKeyframe(std::size_t frame) const { return m_frames.at(frame).world != nullptr; }
    // Simulated seconds from the first frame held to the last.
    double secondsCovered() const;
    // The frames' memory: each frame's record plus each keyframe's world as the heap measured it.
    std::size_t bytesUsed() const { return m_bytes; }

    // The world exactly as it was at `frame` (every bit of its state, so it steps on as the run did).
    simcore::World restore(std::size_t frame) const;

private:
    struct Frame {
        std::uint64_t step = 0;
        double time = 0.0;  // s
        std::optional<AppliedForce> input;
        std::size_t trackedBodies = 0;
        std::shared_ptr<const simcore::World> world;  // keyframes only
        std::size_t bytes = 0;
    };

    Frame keyframe(const simcore::World& world) const;
    void dropOldest();
    void evictToFit(std::size_t incomingBytes);

    std::deque<Frame> m_frames;
    std::size_t m_memoryLimit;
    std::size_t m_bytes = 0;
    int m_framesSinceKeyframe = 0;  // frames recorded after the newest keyframe
};

}  // namespace interplay
