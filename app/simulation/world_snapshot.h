#pragma once
// The running world as the views show it, taken when a batch of steps finishes (on the thread that
// stepped it) or, after an edit, when a view next asks: what World::draw emitted then, less the
// shapes (a view keeps what it draws each body with). The viewport draws this rather than the
// world, so drawing never waits for a step in flight. Plain C++ on simcore.

#include "simcore/world/debug_draw.h"
#include "simcore/world/world.h"

#include <cstdint>
#include <vector>

namespace interplay {

class WorldSnapshot {
public:
    struct Body {
        simcore::BodyId id;
        simcore::Transform transform;  // the body's origin and orientation
        simcore::MotionType motion = simcore::MotionType::Static;
        bool awake = false;
    };
    struct Bounds {
        simcore::BodyId body;
        simcore::Aabb box;
        simcore::DebugBoundsKind kind = simcore::DebugBoundsKind::Tight;
    };

    // Every body, and the joints; the bounds and contact points that `overlays` asks for.
    static WorldSnapshot take(const simcore::World& world, const simcore::DebugDrawOptions& overlays);

    // The body's entry, or null (not in the world when the snapshot was taken).
    const Body* find(simcore::BodyId id) const;
    // Hands `drawer` the bounds, contact points and joints `options` asks for, as World::draw did.
    void drawOverlays(simcore::DebugDraw& drawer, const simcore::DebugDrawOptions& options) const;

    std::vector<Body> bodies;
    std::vector<Bounds> bounds;
    std::vector<simcore::DebugContactPoint> contacts;
    std::vector<simcore::DebugJoint> joints;
    std::uint64_t stepCount = 0;
    double simulatedTime = 0.0;  // s

private:
    std::vector<int> m_bodyOfSlot;  // by BodyId::index: index into bodies, or -1
};

}  // namespace interplay
