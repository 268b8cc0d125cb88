// World::draw: a recording DebugDraw receives exactly the world's bodies, bounds, contacts and
// joints, with the values the world's own per-id queries give.

#include "simcore/world/debug_draw.h"
#include "simcore/world/world.h"

#include "support/worlds.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace simcore;
using test_support::addGround;
using test_support::awakeSettings;
using test_support::run;

namespace {

struct RecordedBody {
    BodyId id;
    ShapeType shape;
    Transform transform;
    Vec3 centerOfMass;
    MotionType motion;
    bool awake;
};

struct RecordedBounds {
    BodyId id;
    Aabb box;
    DebugBoundsKind kind;
};

class Recorder : public DebugDraw {
public:
    std::vector<RecordedBody> bodies;
    std::vector<RecordedBounds> bounds;
    std::vector<DebugContactPoint> contacts;
    std::vector<DebugJoint> joints;

    void drawBody(const DebugBody& b) override {
        bodies.push_back({b.id, b.shape.type, b.transform, b.centerOfMass, b.motion, b.awake});
    }
    void drawBounds(BodyId id, const Aabb& box, DebugBoundsKind kind) override { bounds.push_back({id, box, kind}); }
    void drawContactPoint(const DebugContactPoint& p) override { contacts.push_back(p); }
    void drawJoint(const DebugJoint& j) override { joints.push_back(j); }
};

DebugDrawOptions everything() {
    DebugDrawOptions o;
    o.bodies = o.tightBounds = o.fatBounds = o.contacts = o.joints = true;
    return o;
}

BodyId addBox(World& world, const Vec3& position, float halfSize = 0.5f) {
    BodyCreationSettings b;
    b.shape = Shape::box(Vec3(halfSize));
    b.position = position;
    return world.createBody(b);
}

bool near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) { return glm::length(a - b) <= tolerance; }

}  // namespace

class TestDebugDraw : public QObject {
    Q_OBJECT

private slots:
    void optionsOffEmitNothing();
    void bodiesAndBoundsMatchTheWorld();
    void restingBoxHasFourTouchingPoints();
    void hoveringBoxHasSpeculativePoints();
    void jointFramesFollowTheBodies();
};

void TestDebugDraw::optionsOffEmitNothing() {
    World world(awakeSettings());
    addGround(world);
    const BodyId a = addBox(world, Vec3(0.0f, 0.5f, 0.0f));
    JointCreationSettings hinge;
    hinge.type = JointType::Hinge;
    hinge.bodyA = a;
    hinge.anchor = Vec3(0.0f, 1.0f, 0.0f);
    world.createJoint(hinge);
    world.step();

    Recorder recorder;
    world.draw(recorder, DebugDrawOptions{false, false, false, false, false});
    QVERIFY(recorder.bodies.empty() && recorder.bounds.empty() && recorder.contacts.empty() && recorder.joints.empty());

    // The defaults draw the bodies only.
    world.draw(recorder, DebugDrawOptions{});
    QCOMPARE(recorder.bodies.size(), std::size_t{2});
    QVERIFY(recorder.bounds.empty() && recorder.contacts.empty() && recorder.joints.empty());
}

void TestDebugDraw::bodiesAndBoundsMatchTheWorld() {
    WorldSettings settings;  // sleep on: the resting box falls asleep
    World world(settings);
    const BodyId ground = addGround(world);
    const BodyId resting = addBox(world, Vec3(-3.0f, 0.5f, 0.0f));
    const BodyId falling = addBox(world, Vec3(3.0f, 40.0f, 0.0f), 0.25f);
    BodyCreationSettings ball;
    ball.motion = MotionType::Kinematic;
    ball.shape = Shape::sphere(0.3f);
    ball.position = Vec3(0.0f, 5.0f, 2.0f);
    ball.orientation = glm::angleAxis(0.7f, glm::normalize(Vec3(1.0f, 2.0f, 3.0f)));
    const BodyId kinematic = world.createBody(ball);
    const BodyId removed = addBox(world, Vec3(10.0f, 0.5f, 0.0f));
    world.destroyBody(removed);
    run(world, 1.5f);
    QVERIFY2(!world.isAwake(resting) && world.isAwake(falling), "the scene must hold a sleeping and an awake body");

    Recorder recorder;
    world.draw(recorder, everything());
    const std::vector<BodyId> ids = world.bodyIds();
    QCOMPARE(recorder.bodies.size(), ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const RecordedBody& b = recorder.bodies[i];
        QVERIFY(b.id == ids[i]);
        QVERIFY(b.id != removed);
        QCOMPARE(b.shape, world.shape(ids[i]).type);
        QCOMPARE(b.transform.position, world.position(ids[i]));
        QCOMPARE(b.transform.rotation, world.orientation(ids[i]));
        QCOMPARE(b.centerOfMass, world.centerOfMass(ids[i]));
        QCOMPARE(b.motion, world.motionType(ids[i]));
        QCOMPARE(b.awake, world.isAwake(ids[i]));
    }
    QCOMPARE(recorder.bodies[1].id == resting && !recorder.bodies[1].awake, true);
    QCOMPARE(recorder.bodies[3].id == kinematic && recorder.bodies[3].motion == MotionType::Kinematic, true);
    QVERIFY(recorder.bodies[0].id == ground);

    // One tight and one fat box per body; the fat one holds the tight one, with margin.
    QCOMPARE(recorder.bounds.size(), 2 * ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const RecordedBounds& tight = recorder.bounds[2 * i];
        const RecordedBounds& fat = recorder.bounds[2 * i + 1];
        QVERIFY(tight.id == ids[i] && fat.id == ids[i]);
        QCOMPARE(tight.kind, DebugBoundsKind::Tight);
        QCOMPARE(fat.kind, DebugBoundsKind::Fat);
        const Aabb expected = worldBounds(world.shape(ids[i]), {world.position(ids[i]), world.orientation(ids[i])});
        QCOMPARE(tight.box.min, expected.min);
        QCOMPARE(tight.box.max, expected.max);
        QVERIFY(glm::all(glm::lessThan(fat.box.min, tight.box.min)));
        QVERIFY(glm::all(glm::greaterThan(fat.box.max, tight.box.max)));
    }
}

void TestDebugDraw::restingBoxHasFourTouchingPoints() {
    World world(awakeSettings());
    const BodyId ground = addGround(world);
    const BodyId box = addBox(world, Vec3(0.0f, 0.5f, 0.0f));
    run(world, 1.0f);

    Recorder recorder;
    DebugDrawOptions options;
    options.bodies = false;
    options.contacts = true;
    world.draw(recorder, options);
    QCOMPARE(recorder.contacts.size(), std::size_t{4});
    float impulse = 0.0f;
    for (const DebugContactPoint& p : recorder.contacts) {
        QVERIFY((p.bodyA == ground && p.bodyB == box) || (p.bodyA == box && p.bodyB == ground));
        // From A towards B: up if the ground is A.
        const Vec3 up(0.0f, p.bodyA == ground ? 1.0f : -1.0f, 0.0f);
        QVERIFY2(near(p.normal, up), "normal from A towards B");
        // At the bottom corners of the box, on the ground's top face.
        QVERIFY(std::abs(std::abs(p.point.x) - 0.5f) < 1e-3f && std::abs(std::abs(p.point.z) - 0.5f) < 1e-3f);
        QVERIFY(std::abs(p.point.y) < 0.01f);
        QVERIFY(p.separation <= 0.0f && p.separation > -0.01f);
        QVERIFY(!p.speculative);
        QVERIFY(p.normalImpulse > 0.0f);
        impulse += p.normalImpulse;
    }
    // Together the points carry the box's weight over one substep: m g dt / substeps.
    const WorldSettings& s = world.settings();
    const float weightImpulse = world.mass(box) * 9.81f * s.timeStep / static_cast<float>(s.substeps);
    QVERIFY2(std::abs(impulse - weightImpulse) < 0.05f * weightImpulse,
             qPrintable(QString("normal impulses %1, weight over a substep %2").arg(impulse).arg(weightImpulse)));
}

void TestDebugDraw::hoveringBoxHasSpeculativePoints() {
    WorldSettings settings = awakeSettings();
    settings.gravity = Vec3(0.0f);
    World world(settings);
    addGround(world);
    const float gap = 0.5f * settings.contact.speculativeDistance;
    addBox(world, Vec3(0.0f, 0.5f + gap, 0.0f));
    world.step();

    Recorder recorder;
    DebugDrawOptions options;
    options.contacts = true;
    world.draw(recorder, options);
    QCOMPARE(recorder.contacts.size(), std::size_t{4});
    for (const DebugContactPoint& p : recorder.contacts) {
        QVERIFY(p.speculative);
        QVERIFY(std::abs(p.separation - gap) < 1e-4f);
        QCOMPARE(p.normalImpulse, 0.0f);
        QVERIFY(std::abs(p.point.y - 0.5f * gap) < 1e-4f);  // midway between the surfaces
    }
}

void TestDebugDraw::jointFramesFollowTheBodies() {
    WorldSettings settings = awakeSettings();
    settings.gravity = Vec3(0.0f);
    World world(settings);
    const BodyId door = addBox(world, Vec3(1.0f, 1.0f, 0.0f));
    const BodyId weight = addBox(world, Vec3(5.0f, 1.0f, 0.0f), 0.25f);

    JointCreationSettings hinge;
    hinge.type = JointType::Hinge;
    hinge.bodyA = door;
    hinge.anchor = Vec3(0.0f, 1.0f, 0.0f);
    hinge.axis = Vec3(0.0f, 2.0f, 0.0f);  // normalised at creation
    hinge.limits = JointLimits{-1.0f, 1.5f};
    const JointId hingeId = world.createJoint(hinge);

    JointCreationSettings rod;
    rod.type = JointType::Distance;
    rod.bodyA = door;
    rod.bodyB = weight;
    rod.anchor = Vec3(1.5f, 1.0f, 0.0f);
    rod.anchorB = Vec3(4.75f, 1.0f, 0.0f);
    const JointId rodId = world.createJoint(rod);

    // Turn the door about its hinge by 0.4 rad: its centre and the rod's anchor on it turn too.
    const Quat turn = glm::angleAxis(0.4f, Vec3(0.0f, 1.0f, 0.0f));
    world.setTransform(door, hinge.anchor + turn * (world.position(door) - hinge.anchor), turn);

    Recorder recorder;
    DebugDrawOptions options;
    options.bodies = false;
    options.joints = true;
    world.draw(recorder, options);
    QCOMPARE(recorder.joints.size(), std::size_t{2});

    const DebugJoint& h = recorder.joints[0];
    QVERIFY(h.id == hingeId && h.type == JointType::Hinge && h.bodyA == door && !h.bodyB.isValid());
    QVERIFY(!h.centerB);
    QVERIFY(near(h.centerA, world.centerOfMass(door)));
    QVERIFY(near(h.anchorA, hinge.anchor));
    QVERIFY(near(h.anchorB, hinge.anchor));
    QVERIFY(near(h.axis, Vec3(0.0f, 1.0f, 0.0f)));
    QVERIFY(h.limits && *h.limits == *hinge.limits);
    // The door turned by +0.4 about +y relative to the world (B).
    QVERIFY2(std::abs(h.position - 0.4f) < 1e-4f, qPrintable(QString("hinge angle %1").arg(h.position)));

    const DebugJoint& r = recorder.joints[1];
    QVERIFY(r.id == rodId && r.type == JointType::Distance && r.bodyA == door && r.bodyB == weight);
    QVERIFY(r.centerB && near(*r.centerB, world.centerOfMass(weight)));
    QVERIFY(near(r.anchorA, hinge.anchor + turn * (rod.anchor - hinge.anchor)));
    QVERIFY(near(r.anchorB, rod.anchorB));
    const float restLength = glm::length(rod.anchorB - rod.anchor);
    QVERIFY(r.limits && std::abs(r.limits->lower - restLength) < 1e-5f && std::abs(r.limits->upper - restLength) < 1e-5f);
    QVERIFY(std::abs(r.position - glm::length(r.anchorB - r.anchorA)) < 1e-5f);
    QVERIFY(r.position > restLength);  // turning the door pulled the anchors apart
}

QTEST_APPLESS_MAIN(TestDebugDraw)
#include "test_debug_draw.moc"
