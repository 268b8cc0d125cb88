#include "app/simulation/world_snapshot.h"

namespace interplay {
namespace {

class Recorder : public simcore::DebugDraw {
public:
    explicit Recorder(WorldSnapshot& snapshot) : m_snapshot(snapshot) {}

    void drawBody(const simcore::DebugBody& body) override {
        m_snapshot.bodies.push_back({body.id, body.transform, body.motion, body.awake});
    }
    void drawBounds(simcore::BodyId body, const simcore::Aabb& box, simcore::DebugBoundsKind kind) override {
        m_snapshot.bounds.push_back({body, box, kind});
    }
    void drawContactPoint(const simcore::DebugContactPoint& point) override { m_snapshot.contacts.push_back(point); }
    void drawJoint(const simcore::DebugJoint& joint) override { m_snapshot.joints.push_back(joint); }

private:
    WorldSnapshot& m_snapshot;
};

}  // namespace

WorldSnapshot WorldSnapshot::take(const simcore::World& world, const simcore::DebugDrawOptions& overlays) {
    WorldSnapshot snapshot;
    snapshot.bodies.reserve(world.bodyCount());
    simcore::DebugDrawOptions options = overlays;
    options.bodies = true;
    options.joints = true;
    Recorder recorder(snapshot);
    world.draw(recorder, options);
    snapshot.stepCount = world.stepCount();
    snapshot.simulatedTime = world.simulatedTime();
    for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
        const std::uint32_t slot = snapshot.bodies[i].id.index;
        if (slot >= snapshot.m_bodyOfSlot.size()) snapshot.m_bodyOfSlot.resize(slot + 1, -1);
        snapshot.m_bodyOfSlot[slot] = static_cast<int>(i);
    }
    return snapshot;
}

const WorldSnapshot::Body* WorldSnapshot::find(simcore::BodyId id) const {
    if (id.index >= m_bodyOfSlot.size() || m_bodyOfSlot[id.index] < 0) return nullptr;
    const Body& body = bodies[static_cast<std::size_t>(m_bodyOfSlot[id.index])];
    return body.id == id ? &body : nullptr;
}

void WorldSnapshot::drawOverlays(simcore::DebugDraw& drawer, const simcore::DebugDrawOptions& options) const {
    for (const Bounds& b : bounds) {
        const bool wanted = b.kind == simcore::DebugBoundsKind::Tight ? options.tightBounds : options.fatBounds;
        if (wanted) drawer.drawBounds(b.body, b.box, b.kind);
    }
    if (options.contacts) {
        for (const simcore::DebugContactPoint& point : contacts) drawer.drawContactPoint(point);
    }
    if (options.joints) {
        for (const simcore::DebugJoint& joint : joints) drawer.drawJoint(joint);
    }
}

}  // namespace interplay
