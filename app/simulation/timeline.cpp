#include "app/simulation/timeline.h"

#include <malloc.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace interplay {
namespace {

// Bytes the C heap has handed out (glibc's count). A world's copy spreads over a dozen containers
// the engine does not expose; the heap's growth while copying it is what it really costs.
std::size_t heapInUse() {
    return mallinfo2().uordblks;
}

}  // namespace

void applyForce(simcore::World& world, const AppliedForce& applied) {
    if (!world.contains(applied.body)) return;
    world.addForce(applied.body, applied.force);
    world.addTorque(applied.body, applied.torque);
    world.wake(applied.body);
}

Timeline::Timeline(std::size_t memoryLimitBytes) : m_memoryLimit(memoryLimitBytes) {}

void Timeline::setMemoryLimit(std::size_t bytes) {
    m_memoryLimit = bytes;
    evictToFit(0);
}

Timeline::Frame Timeline::keyframe(const simcore::World& world) const {
    Frame frame;
    const std::size_t before = heapInUse();
    frame.world = std::make_shared<const simcore::World>(world);
    const std::size_t after = heapInUse();
    frame.bytes = sizeof(Frame) + (after > before ? after - before : 0);
    return frame;
}

void Timeline::record(const simcore::World& world, const std::optional<AppliedForce>& input, bool changed,
                      std::size_t trackedBodies) {
    const bool needsKeyframe = m_frames.empty() || changed || m_framesSinceKeyframe + 1 >= kKeyframeInterval;
    Frame frame = needsKeyframe ? keyframe(world) : Frame{};
    if (!needsKeyframe) frame.bytes = sizeof(Frame);
    frame.step = world.stepCount();
    frame.time = world.simulatedTime();
    frame.input = input;
    frame.trackedBodies = trackedBodies;
    evictToFit(frame.bytes);
    if (m_frames.empty() && !frame.world) {
        // The keyframe this frame stepped from was dropped to make room: it becomes one itself.
        Frame full = keyframe(world);
        full.step = frame.step;
        full.time = frame.time;
        full.input = frame.input;
        full.trackedBodies = frame.trackedBodies;
        frame = std::move(full);
    }
    if (frame.bytes > m_memoryLimit) return;  // not even one frame fits: nothing is held
    m_framesSinceKeyframe = frame.world ? 0 : m_framesSinceKeyframe + 1;
    m_bytes += frame.bytes;
    m_frames.push_back(std::move(frame));
}

void Timeline::clear() {
    m_frames.clear();
    m_bytes = 0;
    m_framesSinceKeyframe = 0;
}

void Timeline::truncateAfter(std::size_t frame) {
    while (m_frames.size() > frame + 1) {
        m_bytes -= m_frames.back().bytes;
        m_frames.pop_back();
    }
    m_framesSinceKeyframe = 0;
    for (auto it = m_frames.rbegin(); it != m_frames.rend() && !it->world; ++it) ++m_framesSinceKeyframe;
}

void Timeline::dropOldest() {
    // The oldest keyframe goes with the frames that step from it.
    do {
        m_bytes -= m_frames.front().bytes;
        m_frames.pop_front();
    } while (!m_frames.empty() && !m_frames.front().world);
    if (m_frames.empty()) m_framesSinceKeyframe = 0;
}

void Timeline::evictToFit(std::size_t incomingBytes) {
    while (!m_frames.empty() && m_bytes + incomingBytes > m_memoryLimit) dropOldest();
}

std::size_t Timeline::keyframeCount() const {
    return static_cast<std::size_t>(std::count_if(m_frames.begin(), m_frames.end(), [](const Frame& f) { return f.world != nullptr; }));
}

double Timeline::secondsCovered() const {
    return m_frames.empty() ? 0.0 : m_frames.back().time - m_frames.front().time;
}

simcore::World Timeline::restore(std::size_t frame) const {
    if (frame >= m_frames.size()) throw std::out_of_range("timeline frame " + std::to_string(frame) + " is not recorded");
    std::size_t first = frame;
    while (!m_frames[first].world) --first;  // the ring always starts with a keyframe
    simcore::World world(*m_frames[first].world);
    for (std::size_t i = first + 1; i <= frame; ++i) {
        if (m_frames[i].input) applyForce(world, *m_frames[i].input);
        world.step();
    }
    return world;
}

}  // namespace interplay
