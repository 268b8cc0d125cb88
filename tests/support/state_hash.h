#pragma once
// The determinism tests' fingerprint of a world: every body's pose, velocities and awake flag, in the
// world's body order, hashed bit for bit. Built from a World, or from the bodies of an interplay-run
// report (which prints each float as the double it converts to exactly), so the library, the editor
// and the runner can be compared with one number.

#include "simcore/world/world.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace test_support {

struct BodyState {
    simcore::Vec3 position{0.0f};  // the body's origin, as the runner reports it
    simcore::Quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    simcore::Vec3 linearVelocity{0.0f};
    simcore::Vec3 angularVelocity{0.0f};
    bool awake = false;
};

inline std::vector<BodyState> bodyStates(const simcore::World& world) {
    std::vector<BodyState> states;
    for (const simcore::BodyId id : world.bodyIds()) {
        states.push_back({world.position(id), world.orientation(id), world.linearVelocity(id),
                          world.angularVelocity(id), world.isAwake(id)});
    }
    return states;
}

// FNV-1a over the bits of every float and flag: any bit that differs changes it.
inline std::uint64_t stateHash(const std::vector<BodyState>& states) {
    std::uint64_t hash = 1469598103934665603ull;
    const auto mixByte = [&hash](unsigned char byte) { hash = (hash ^ byte) * 1099511628211ull; };
    const auto mixFloat = [&mixByte](float value) {
        std::uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        for (int shift = 0; shift < 32; shift += 8) mixByte(static_cast<unsigned char>(bits >> shift));
    };
    const auto mixVec = [&mixFloat](const simcore::Vec3& v) {
        mixFloat(v.x);
        mixFloat(v.y);
        mixFloat(v.z);
    };
    for (const BodyState& s : states) {
        mixVec(s.position);
        mixFloat(s.orientation.w);
        mixFloat(s.orientation.x);
        mixFloat(s.orientation.y);
        mixFloat(s.orientation.z);
        mixVec(s.linearVelocity);
        mixVec(s.angularVelocity);
        mixByte(s.awake ? 1 : 0);
    }
    return hash;
}

inline std::uint64_t stateHash(const simcore::World& world) { return stateHash(bodyStates(world)); }

}  // namespace test_support
