#pragma once
// Islands: dynamic bodies connected through touching contacts and joints (static and kinematic
// bodies, and the world, do not join islands, or the whole floor would be one island). An island
// sleeps only as a whole, and wakes as a whole when any of its bodies is awake.

#include "simcore/dynamics/contact_manager.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/dynamics/joint_storage.h"
#include "simcore/world_settings.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace simcore {

class Islands {
public:
    // Union-find over the touching contacts and the joints. Buffers are reused from step to step.
    void build(const BodyStorage& bodies, const std::vector<Contact>& contacts, const JointStorage& joints);

    // Wakes every sleeping body whose island holds an awake body, calling onWake(denseIndex) for
    // each, and counts the awake islands.
    template <typename OnWake>
    void wakeTouchedIslands(BodyStorage& bodies, OnWake&& onWake);

    // Advances each awake dynamic body's slow time and puts to sleep the islands whose every body
    // has been slow for `timeToSleep`. Calls onSleep(denseIndex) for each body put to sleep.
    template <typename OnSleep>
    void sleepRestingIslands(BodyStorage& bodies, const SleepSettings& sleep, float dt, OnSleep&& onSleep);

    std::uint32_t awakeIslandCount() const { return awakeIslandCount_; }

private:
    std::uint32_t find(std::uint32_t i);
    void unite(std::size_t a, std::size_t b);  // dense indices; only dynamic bodies join

    std::vector<std::uint32_t> parent_;
    std::vector<std::uint8_t> islandAwake_;  // by root
    std::vector<float> islandSlowTime_;      // by root: the least slow time of its bodies (s)
    std::uint32_t awakeIslandCount_ = 0;
};

template <typename OnWake>
void Islands::wakeTouchedIslands(BodyStorage& bodies, OnWake&& onWake) {
    const std::size_t n = bodies.size();
    islandAwake_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (bodies.isAwakeDynamic(i)) islandAwake_[find(static_cast<std::uint32_t>(i))] = 1;
    awakeIslandCount_ = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] != MotionType::Dynamic) continue;
        const std::uint32_t root = find(static_cast<std::uint32_t>(i));
        if (root == i && islandAwake_[root]) ++awakeIslandCount_;
        if (!bodies.awake[i] && islandAwake_[root]) {
            bodies.awake[i] = 1;
            bodies.sleepTime[i] = 0.0f;
            onWake(i);
        }
    }
}

template <typename OnSleep>
void Islands::sleepRestingIslands(BodyStorage& bodies, const SleepSettings& sleep, float dt, OnSleep&& onSleep) {
    const std::size_t n = bodies.size();
    const float linear2 = sleep.linearVelocity * sleep.linearVelocity;
    const float angular2 = sleep.angularVelocity * sleep.angularVelocity;
    islandSlowTime_.assign(n, sleep.timeToSleep);
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] != MotionType::Dynamic || !bodies.awake[i]) continue;
        const bool slow = lengthSquared(bodies.linearVelocity[i]) <= linear2 &&
                          lengthSquared(bodies.angularVelocity[i]) <= angular2;
        bodies.sleepTime[i] = slow ? bodies.sleepTime[i] + dt : 0.0f;
        float& islandTime = islandSlowTime_[find(static_cast<std::uint32_t>(i))];
        islandTime = std::min(islandTime, bodies.sleepTime[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] != MotionType::Dynamic || !bodies.awake[i]) continue;
        if (islandSlowTime_[find(static_cast<std::uint32_t>(i))] < sleep.timeToSleep) continue;
        bodies.awake[i] = 0;
        bodies.linearVelocity[i] = Vec3(0.0f);
        bodies.angularVelocity[i] = Vec3(0.0f);
        onSleep(i);
    }
}

}  // namespace simcore
