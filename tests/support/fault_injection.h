#pragma once
// Faults no public call can cause, for the tests of what the editor does when the engine goes
// wrong: World befriends this struct so that a test can leave the state an engine bug would.

#include "simcore/world/world.h"

#include <limits>

namespace simcore {

struct WorldFaultInjection {
    static void poisonLinearVelocity(World& world, BodyId id) {
        world.bodies_.linearVelocity[world.indexOf(id)].x = std::numeric_limits<float>::quiet_NaN();
    }
};

}  // namespace simcore
