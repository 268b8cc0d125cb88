// Compound bodies: mass properties against closed forms, free tumbling, resting contacts made by
// several children, ray casts, continuous collision, and the scene format's compound keys.

#include "simcore/io/scene_io.h"
#include "simcore/shapes/compound_shape.h"
#include "simcore/world/world.h"

#include <QtTest>

#include <cmath>

using namespace simcore;

namespace {

Shape compound(std::vector<CompoundChild> children) {
    return Shape::compoundOf(std::make_shared<const CompoundShape>(std::move(children)));
}

// An L of two 2 x 1 x 1 boxes: one along x centred at the origin, one standing on its +x half,
// made as the same box turned 90 degrees about z (so the child rotation enters the inertia).
Shape lShape() {
    const Quat quarterTurnZ = glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));
    return compound({{Shape::box(Vec3(1.0f, 0.5f, 0.5f)), Transform{}},
                     {Shape::box(Vec3(1.0f, 0.5f, 0.5f)), Transform{Vec3(0.5f, 1.5f, 0.0f), quarterTurnZ}}});
}

// A dumbbell along local y: a capsule bar with a sphere at each end (children 1 and 2).
constexpr float kBarRadius = 0.05f, kBarHalfHeight = 0.5f, kBellRadius = 0.15f, kBellOffset = 0.6f;
Shape dumbbell() {
    return compound({{Shape::capsule(kBarRadius, kBarHalfHeight), Transform{}},
                     {Shape::sphere(kBellRadius), Transform{Vec3(0.0f, -kBellOffset, 0.0f), Quat(1, 0, 0, 0)}},
                     {Shape::sphere(kBellRadius), Transform{Vec3(0.0f, kBellOffset, 0.0f), Quat(1, 0, 0, 0)}}});
}

// A table: a 1.2 x 0.06 x 0.8 top on four 0.05-radius legs 0.7 high; the origin on the floor.
Shape table() {
    std::vector<CompoundChild> parts{{Shape::box(Vec3(0.6f, 0.03f, 0.4f)), Transform{Vec3(0.0f, 0.73f, 0.0f), Quat(1, 0, 0, 0)}}};
    for (const float x : {-0.5f, 0.5f})
        for (const float z : {-0.3f, 0.3f})
            parts.push_back({Shape::box(Vec3(0.05f, 0.35f, 0.05f)), Transform{Vec3(x, 0.35f, z), Quat(1, 0, 0, 0)}});
    return compound(std::move(parts));
}

BodyCreationSettings floorBody() {
    BodyCreationSettings floor;
    floor.motion = MotionType::Static;
    floor.shape = Shape::box(Vec3(10.0f, 0.5f, 10.0f));
    floor.position = Vec3(0.0f, -0.5f, 0.0f);
    return floor;
}

// Lowest point of a body's shape in the world (m).
float lowestPoint(const World& world, BodyId id) {
    return worldBounds(world.shape(id), Transform{world.position(id), world.orientation(id)}).min.y;
}

bool nearlyEqual(double actual, double expected, double relative) {
    return std::abs(actual - expected) <= relative * std::max(1.0, std::abs(expected));
}

}  // namespace

class TestCompound : public QObject {
    Q_OBJECT
private slots:
    void lOfTwoBoxesHasTheParallelAxisInertia();
    void dumbbellMassPropertiesMatchClosedForms();
    void boundsVolumeAndExtentsComeFromTheChildren();
    void bodyOriginStaysWhereTheUserPutIt();
    void tumblingInZeroGravityKeepsMomentumAndEnergy();
    void tableRestsOnItsLegsAndSleeps();
    void legsShareTheWeightLikeOneBox();
    void dumbbellRestsOnTheTableOnBothBells();
    void rayHitsTheNearestChild();
    void fastCompoundDoesNotTunnelThroughAThinWall();
    void contactsFollowTheChildrenThatComeNear();
    void sceneRoundTripsByteStable();
    void loaderNamesTheBadChild_data();
    void loaderNamesTheBadChild();
    void worldRefusesANestedCompound();
};

// Each box: volume 2, so mass 2 at density 1; inertia about its centre m/12 (b^2 + c^2) with sides
// (2, 1, 1) for the lying box and (1, 2, 1) for the standing one. Centre of mass (0.25, 0.75, 0);
// each centre is d = (-+0.25, -+0.75, 0) from it, adding m (|d|^2 - d_i^2) on the diagonal and
// -m d_x d_y off it.
void TestCompound::lOfTwoBoxesHasTheParallelAxisInertia() {
    const MassProperties props = massProperties(lShape(), 1.0f);
    const double m = 2.0;
    const double lying[3] = {m / 12 * (1 + 1), m / 12 * (4 + 1), m / 12 * (4 + 1)};
    const double standing[3] = {m / 12 * (4 + 1), m / 12 * (1 + 1), m / 12 * (1 + 1 * 4)};
    const glm::dvec3 d(0.25, 0.75, 0.0);
    const double d2 = glm::dot(d, d);
    const double expected[3] = {lying[0] + standing[0] + 2 * m * (d2 - d.x * d.x),
                                lying[1] + standing[1] + 2 * m * (d2 - d.y * d.y),
                                lying[2] + standing[2] + 2 * m * d2};
    const double expectedXY = -2 * m * d.x * d.y;

    QVERIFY(nearlyEqual(props.mass, 2 * m, 1e-6));
    QVERIFY(glm::length(props.centerOfMass - Vec3(0.25f, 0.75f, 0.0f)) < 1e-6f);
    for (int i = 0; i < 3; ++i)
        QVERIFY2(nearlyEqual(props.inertia[i][i], expected[i], 1e-5),
                 qPrintable(QString("I%1%1 = %2, expected %3").arg(i).arg(props.inertia[i][i]).arg(expected[i])));
    QVERIFY2(nearlyEqual(props.inertia[0][1], expectedXY, 1e-5), qPrintable(QString::number(props.inertia[0][1])));
    QVERIFY(nearlyEqual(props.inertia[1][0], expectedXY, 1e-5));
    for (const auto& [r, c] : {std::pair{0, 2}, {2, 0}, {1, 2}, {2, 1}}) QVERIFY(std::abs(props.inertia[r][c]) < 1e-6f);
}

// Two solid spheres (2/5 m r^2 each, carried kBellOffset along y) and the capsule bar about its own
// centre, which is the dumbbell's (symmetric). The bar's ends reach into the bells: overlapping
// volume counts twice, as documented in shape.h.
void TestCompound::dumbbellMassPropertiesMatchClosedForms() {
    const double density = 7800.0;
    const MassProperties props = massProperties(dumbbell(), float(density));
    const double pi = 3.14159265358979323846;
    const double bell = density * 4.0 / 3.0 * pi * std::pow(double(kBellRadius), 3);
    const double r = kBarRadius, h = 2.0 * kBarHalfHeight;
    const double cylinder = density * pi * r * r * h, cap = density * 2.0 / 3.0 * pi * r * r * r;
    const double barAxial = 0.5 * cylinder * r * r + 2 * 0.4 * cap * r * r;
    const double capOffset = kBarHalfHeight + 3.0 / 8.0 * r;
    const double barTransverse =
        cylinder / 12 * (3 * r * r + h * h) + 2 * cap * (83.0 / 320.0 * r * r + capOffset * capOffset);
    const double bellOwn = 0.4 * bell * kBellRadius * kBellRadius;
    const double transverse = barTransverse + 2 * (bellOwn + bell * kBellOffset * kBellOffset);
    const double axial = barAxial + 2 * bellOwn;

    QVERIFY(nearlyEqual(props.mass, 2 * bell + cylinder + 2 * cap, 1e-6));
    QVERIFY(glm::length(props.centerOfMass) < 1e-6f);
    QVERIFY2(nearlyEqual(props.inertia[0][0], transverse, 1e-5), qPrintable(QString::number(props.inertia[0][0])));
    QVERIFY(nearlyEqual(props.inertia[2][2], transverse, 1e-5));
    QVERIFY2(nearlyEqual(props.inertia[1][1], axial, 1e-5), qPrintable(QString::number(props.inertia[1][1])));
    QVERIFY(nearlyEqual(volume(dumbbell()), (2 * bell + cylinder + 2 * cap) / density, 1e-6));
}

void TestCompound::boundsVolumeAndExtentsComeFromTheChildren() {
    const Shape l = lShape();
    const Aabb local = localBounds(l);
    QVERIFY(glm::length(local.min - Vec3(-1.0f, -0.5f, -0.5f)) < 1e-6f);
    QVERIFY(glm::length(local.max - Vec3(1.0f, 2.5f, 0.5f)) < 1e-6f);
    // Turned a quarter about x, the L's standing box points along z.
    const Transform turned{Vec3(3.0f, 0.0f, 0.0f), glm::angleAxis(0.5f * kPi, Vec3(1.0f, 0.0f, 0.0f))};
    const Aabb world = worldBounds(l, turned);
    QVERIFY2(glm::length(world.min - Vec3(2.0f, -0.5f, -0.5f)) < 1e-5f, qPrintable(QString::number(world.min.z)));
    QVERIFY(glm::length(world.max - Vec3(4.0f, 0.5f, 2.5f)) < 1e-5f);
    QCOMPARE(volume(l), 4.0f);
    QCOMPARE(minimumExtent(l), 1.0f);
    QCOMPARE(minimumExtent(dumbbell()), 2.0f * kBarRadius);
    QCOMPARE(rollingRadius(dumbbell()), 0.0f);
    // Support: the farthest point of any child.
    QVERIFY(glm::length(support(l, Vec3(0.1f, 1.0f, 0.2f)) - Vec3(1.0f, 2.5f, 0.5f)) < 1e-6f);
    QVERIFY(glm::length(support(dumbbell(), Vec3(0.0f, -1.0f, 0.0f)) -
                        Vec3(0.0f, -kBellOffset - kBellRadius, 0.0f)) < 1e-6f);
    QCOMPARE(subShapeCount(l), std::size_t(2));
    QCOMPARE(subShapeCount(Shape::sphere(1.0f)), std::size_t(1));
}

void TestCompound::bodyOriginStaysWhereTheUserPutIt() {
    World world;
    BodyCreationSettings b;
    b.shape = lShape();
    b.position = Vec3(1.0f, 5.0f, -2.0f);
    b.density = 1.0f;
    const BodyId id = world.createBody(b);
    QCOMPARE(world.position(id), b.position);
    QVERIFY(glm::length(world.centerOfMass(id) - (b.position + Vec3(0.25f, 0.75f, 0.0f))) < 1e-5f);
    QVERIFY(nearlyEqual(world.mass(id), 4.0, 1e-6));
}

// The same bounds as the box tumbler in test_hard_cases (free tumble): |L| and the kinetic
// energy within 0.1 % over the run. The L's principal axes are not its body axes, so the spin
// is far from any principal axis and the inertia's off-diagonal terms are exercised.
void TestCompound::tumblingInZeroGravityKeepsMomentumAndEnergy() {
    WorldSettings settings;
    settings.gravity = Vec3(0.0f);
    World world(settings);
    BodyCreationSettings b;
    b.shape = lShape();
    b.mass = 3.0f;
    b.angularVelocity = Vec3(1.0f, 4.0f, -2.0f);
    world.createBody(b);
    const float l0 = glm::length(world.angularMomentum());
    const double e0 = world.kineticEnergy();
    float worstL = 0.0f;
    double worstE = 0.0;
    for (int i = 0; i < 1200; ++i) {
        world.step();
        worstL = std::max(worstL, std::abs(glm::length(world.angularMomentum()) - l0) / l0);
        worstE = std::max(worstE, std::abs(world.kineticEnergy() - e0) / e0);
    }
    qInfo("compound tumbler over %.0f s: |L| off by %.4f %%, energy by %.4f %%", world.simulatedTime(), 100.0 * worstL,
          100.0 * worstE);
    QVERIFY2(worstL < 1e-3f, qPrintable(QString("|L| off by %1").arg(worstL)));
    QVERIFY2(worstE < 1e-3, qPrintable(QString("energy off by %1").arg(worstE)));
}

// Dropped 5 cm, the table lands on its four legs: four contacts, one per leg (the top never
// touches), no leg deeper than the slop, and it falls asleep.
void TestCompound::tableRestsOnItsLegsAndSleeps() {
    World world;
    const BodyId floor = world.createBody(floorBody());
    BodyCreationSettings t;
    t.shape = table();
    t.position = Vec3(0.0f, 0.05f, 0.0f);
    t.density = 700.0f;
    const BodyId id = world.createBody(t);
    float deepest = 0.0f;
    for (int i = 0; i < 300 && world.isAwake(id); ++i) {
        world.step();
        deepest = std::min(deepest, lowestPoint(world, id));
    }
    const float slop = world.settings().contact.linearSlop;
    qInfo("table: deepest %.2e m, settled at %.2e m after %.2f s", -deepest, lowestPoint(world, id), world.simulatedTime());
    QVERIFY2(!world.isAwake(id), "the table is still awake after 5 s");
    QVERIFY2(deepest > -slop, qPrintable(QString("a leg sank %1 m").arg(-deepest)));
    QVERIFY(std::abs(world.position(id).y) < slop);
    QVERIFY(glm::length(world.linearVelocity(id)) < 1e-3f);
    int touchingLegs = 0;
    for (std::size_t c = 0; c < world.contactCount(); ++c) {
        const ContactInfo contact = world.contact(c);
        if (contact.pointCount == 0) continue;
        QVERIFY(contact.bodyA == floor || contact.bodyB == floor);
        const std::uint32_t child = contact.bodyA == id ? contact.subShapeA : contact.subShapeB;
        QVERIFY2(child >= 1, "the table top touches the floor");
        ++touchingLegs;
    }
    QCOMPARE(touchingLegs, 4);
}

// Warm-started through its child contacts, the table at rest carries its weight through its four
// legs: their impulses sum to a single box's of the same mass on the same floor (1 %), and by
// symmetry each leg takes a quarter (5 %: the four contacts are solved one after another).
void TestCompound::legsShareTheWeightLikeOneBox() {
    WorldSettings settings;
    settings.sleep.enabled = false;
    const auto floorImpulses = [&settings](const Shape& shape, float mass, float height, std::vector<float>* perContact) {
        World world(settings);
        world.createBody(floorBody());
        BodyCreationSettings b;
        b.shape = shape;
        b.mass = mass;
        b.position = Vec3(0.0f, height, 0.0f);
        const BodyId id = world.createBody(b);
        for (int i = 0; i < 120; ++i) world.step();
        float sum = 0.0f;
        for (std::size_t c = 0; c < world.contactCount(); ++c) {
            const ContactInfo contact = world.contact(c);
            if (contact.bodyA != id && contact.bodyB != id) continue;
            float impulse = 0.0f;
            for (int k = 0; k < contact.pointCount; ++k) impulse += contact.normalImpulses[k];
            if (perContact && contact.pointCount > 0) perContact->push_back(impulse);
            sum += impulse;
        }
        return sum;
    };
    std::vector<float> legs;
    const float table = floorImpulses(::table(), 20.0f, 0.0f, &legs);  // its origin is on the floor
    const float box = floorImpulses(Shape::box(Vec3(0.5f, 0.35f, 0.3f)), 20.0f, 0.35f, nullptr);
    qInfo("floor impulse: table %.6f N s on %zu legs, box %.6f N s", table, legs.size(), box);
    QVERIFY2(std::abs(table / box - 1.0f) < 0.01f, qPrintable(QString("table / box = %1").arg(table / box)));
    QCOMPARE(legs.size(), std::size_t(4));
    for (const float leg : legs)
        QVERIFY2(std::abs(leg / (0.25f * table) - 1.0f) < 0.05f, qPrintable(QString("a leg carries %1").arg(leg / table)));
}

// A dumbbell lying across the table top touches it with both bells: contacts between a child of
// one compound and a child of the other. It stays on the top (no sinking past the slop) and both
// fall asleep.
void TestCompound::dumbbellRestsOnTheTableOnBothBells() {
    World world;
    world.createBody(floorBody());
    BodyCreationSettings t;
    t.shape = table();
    t.density = 700.0f;
    const BodyId tableId = world.createBody(t);
    BodyCreationSettings d;
    d.shape = dumbbell();
    d.density = 7800.0f;
    d.orientation = glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));  // lying along x
    d.position = Vec3(0.0f, 0.76f + kBellRadius + 0.02f, 0.0f);
    const BodyId bellId = world.createBody(d);
    float deepest = 1.0f;
    for (int i = 0; i < 600 && (world.isAwake(bellId) || world.isAwake(tableId)); ++i) {
        world.step();
        deepest = std::min(deepest, lowestPoint(world, bellId) - 0.76f);
    }
    const float slop = world.settings().contact.linearSlop;
    qInfo("dumbbell on table: deepest %.2e m below the top after %.2f s", -deepest, world.simulatedTime());
    QVERIFY(!world.isAwake(bellId) && !world.isAwake(tableId));
    QVERIFY2(deepest > -slop, qPrintable(QString("the dumbbell sank %1 m into the top").arg(-deepest)));
    std::vector<std::uint32_t> bells;
    for (std::size_t c = 0; c < world.contactCount(); ++c) {
        const ContactInfo contact = world.contact(c);
        if (contact.pointCount == 0 || (contact.bodyA != bellId && contact.bodyB != bellId)) continue;
        QCOMPARE(contact.bodyA == tableId ? contact.subShapeA : contact.subShapeB, 0u);  // the top
        bells.push_back(contact.bodyA == bellId ? contact.subShapeA : contact.subShapeB);
    }
    std::sort(bells.begin(), bells.end());
    QCOMPARE(bells, (std::vector<std::uint32_t>{1, 2}));
}

void TestCompound::rayHitsTheNearestChild() {
    World world;
    BodyCreationSettings d;
    d.motion = MotionType::Static;
    d.shape = dumbbell();
    d.orientation = glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));  // local +y -> world -x
    const BodyId id = world.createBody(d);
    // Straight down onto the bell at world x = +0.6 (local y = -0.6: child 1).
    const auto bell = world.castRay(Vec3(kBellOffset, 2.0f, 0.0f), Vec3(0.0f, -4.0f, 0.0f));
    QVERIFY(bell);
    QCOMPARE(bell->body, id);
    QCOMPARE(bell->subShape, 1u);
    QVERIFY(std::abs(bell->point.y - kBellRadius) < 1e-5f);
    // Down onto the bar's middle: the capsule, child 0, at its radius.
    const auto bar = world.castRay(Vec3(0.0f, 2.0f, 0.0f), Vec3(0.0f, -4.0f, 0.0f));
    QVERIFY(bar);
    QCOMPARE(bar->subShape, 0u);
    QVERIFY(std::abs(bar->point.y - kBarRadius) < 1e-5f);
    // Along the bar from +x: the first bell met is child 1, not the far one.
    const auto along = world.castRay(Vec3(3.0f, 0.0f, 0.0f), Vec3(-6.0f, 0.0f, 0.0f));
    QVERIFY(along);
    QCOMPARE(along->subShape, 1u);
    QVERIFY(std::abs(along->point.x - (kBellOffset + kBellRadius)) < 1e-5f);
    // Between the bar and a bell's edge: nothing.
    QVERIFY(!world.castRay(Vec3(0.3f, 2.0f, 0.1f), Vec3(0.0f, -4.0f, 0.0f)));
}

// A dumbbell thrown end-on at 300 m/s (5 m per step at 60 Hz) at a 2 cm static wall: without a
// sweep its 10 cm bar would pass it between two steps. With ccd it stops on the near side.
void TestCompound::fastCompoundDoesNotTunnelThroughAThinWall() {
    WorldSettings settings;
    settings.gravity = Vec3(0.0f);
    World world(settings);
    BodyCreationSettings wall;
    wall.motion = MotionType::Static;
    wall.shape = Shape::box(Vec3(0.01f, 2.0f, 2.0f));
    wall.position = Vec3(10.0f, 0.0f, 0.0f);
    world.createBody(wall);
    BodyCreationSettings d;
    d.shape = dumbbell();
    d.orientation = glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));
    d.linearVelocity = Vec3(300.0f, 0.0f, 0.0f);
    d.ccd = true;
    d.position = Vec3(0.3f, 0.0f, 0.0f);  // 4 cm apart between steps is no coincidence: start off the step grid
    const BodyId id = world.createBody(d);
    for (int i = 0; i < 30; ++i) world.step();
    const Aabb bounds = worldBounds(world.shape(id), Transform{world.position(id), world.orientation(id)});
    qInfo("after the wall: dumbbell spans x %.3f .. %.3f m", bounds.min.x, bounds.max.x);
    QVERIFY2(bounds.max.x < 10.0f - 0.01f + world.settings().contact.linearSlop,
             qPrintable(QString("the dumbbell reached x = %1 m, past the wall's face").arg(bounds.max.x)));
    QVERIFY(!world.findNonFiniteBody());
}

// The mid-phase makes a contact per child pair only while their grown bounds overlap: a sphere
// rolling under one end of a raised dumbbell meets that bell's child alone.
void TestCompound::contactsFollowTheChildrenThatComeNear() {
    WorldSettings settings;
    settings.gravity = Vec3(0.0f);
    World world(settings);
    BodyCreationSettings d;
    d.motion = MotionType::Static;
    d.shape = dumbbell();
    d.orientation = glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));
    const BodyId bellId = world.createBody(d);
    BodyCreationSettings ball;
    ball.shape = Shape::sphere(0.1f);
    ball.position = Vec3(kBellOffset, kBellRadius + 0.1f + 0.001f, 0.0f);  // just above bell 1
    const BodyId ballId = world.createBody(ball);
    world.step();
    std::vector<std::uint32_t> children;
    for (std::size_t c = 0; c < world.contactCount(); ++c) {
        const ContactInfo contact = world.contact(c);
        QVERIFY(contact.bodyA == bellId || contact.bodyB == bellId);
        QVERIFY(contact.bodyA == ballId || contact.bodyB == ballId);
        children.push_back(contact.bodyA == bellId ? contact.subShapeA : contact.subShapeB);
    }
    std::sort(children.begin(), children.end());
    QVERIFY2(!children.empty() && std::find(children.begin(), children.end(), 2u) == children.end(),
             qPrintable(QString("%1 contacts").arg(children.size())));
    QVERIFY(std::find(children.begin(), children.end(), 1u) != children.end());
}

void TestCompound::sceneRoundTripsByteStable() {
    const std::string text = R"({"format": "interplay.scene", "version": 1, "bodies": [
        {"name": "l", "shape": {"type": "compound", "children": [
            {"shape": {"type": "box", "halfExtents": [1, 0.5, 0.5]}},
            {"shape": {"type": "capsule", "radius": 0.1, "halfHeight": 0.3}, "position": [0.5, 1.5, 0],
             "orientation": [0.7071068, 0, 0, 0.7071068]},
            {"shape": {"type": "convexHull", "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}, "position": [-1, 0, 0]}]}}]})";
    const SceneLoadResult loaded = parseScene(text, "compound.json");
    QVERIFY2(loaded.ok(), loaded.diagnostics.empty() ? "" : loaded.diagnostics.front().message.c_str());
    const Shape& shape = loaded.scene->bodies.front().body.shape;
    QCOMPARE(shape.type, ShapeType::Compound);
    QCOMPARE(subShapeCount(shape), std::size_t(3));
    QCOMPARE(subShape(shape, 1).type, ShapeType::Capsule);
    QCOMPARE(shape.compound->children()[1].pose.position, Vec3(0.5f, 1.5f, 0.0f));
    const std::string saved = serializeScene(*loaded.scene);
    const SceneLoadResult again = parseScene(saved, "saved.json");
    QVERIFY(again.ok() && again.diagnostics.empty());
    QCOMPARE(serializeScene(*again.scene), saved);
    QVERIFY(saved.find("\"children\"") != std::string::npos);
}

void TestCompound::loaderNamesTheBadChild_data() {
    QTest::addColumn<QString>("shape");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("words");
    QTest::newRow("bad child radius")
        << R"({"type": "compound", "children": [{"shape": {"type": "box", "halfExtents": [1, 1, 1]}},
              {"shape": {"type": "sphere", "radius": -1}}]})"
        << "/bodies/0/shape/children/1/shape/radius" << "radius";
    QTest::newRow("nested compound")
        << R"({"type": "compound", "children": [{"shape": {"type": "compound", "children": []}}]})"
        << "/bodies/0/shape/children/0/shape/type" << "do not nest";
    QTest::newRow("no children") << R"({"type": "compound", "children": []})" << "/bodies/0/shape/children"
                                 << "1 to 64";
    QTest::newRow("children missing") << R"({"type": "compound"})" << "/bodies/0/shape/children" << "missing";
    QTest::newRow("child without shape") << R"({"type": "compound", "children": [{"position": [0, 0, 0]}]})"
                                         << "/bodies/0/shape/children/0/shape" << "missing";
    QTest::newRow("zero orientation")
        << R"({"type": "compound", "children": [{"shape": {"type": "sphere", "radius": 1}, "orientation": [0, 0, 0, 0]}]})"
        << "/bodies/0/shape/children/0/orientation" << "";
    QString many = R"({"type": "compound", "children": [)";
    for (int i = 0; i < 65; ++i) many += QString(i ? "," : "") + R"({"shape": {"type": "sphere", "radius": 1}})";
    QTest::newRow("too many children") << many + "]}" << "/bodies/0/shape/children" << "got 65";
}

void TestCompound::loaderNamesTheBadChild() {
    QFETCH(QString, shape);
    QFETCH(QString, path);
    QFETCH(QString, words);
    const std::string text =
        R"({"format": "interplay.scene", "version": 1, "bodies": [{"shape": )" + shape.toStdString() + "}]}";
    const SceneLoadResult loaded = parseScene(text, "bad.json");
    QVERIFY(!loaded.ok());
    bool found = false;
    for (const Diagnostic& d : loaded.diagnostics)
        if (d.severity == Diagnostic::Severity::Error && QString::fromStdString(d.path) == path &&
            QString::fromStdString(d.message).contains(words))
            found = true;
    QString all;
    for (const Diagnostic& d : loaded.diagnostics) all += QString::fromStdString(d.path + ": " + d.message + "\n");
    QVERIFY2(found, qPrintable(all));
}

void TestCompound::worldRefusesANestedCompound() {
    World world;
    BodyCreationSettings b;
    b.shape = compound({{lShape(), Transform{}}});
    try {
        world.createBody(b);
        QFAIL("a compound inside a compound was accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(QString(e.what()).contains("shape.children[0].shape must be convex"), e.what());
    }
    b.shape = compound({{Shape::sphere(-1.0f), Transform{}}});
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, world.createBody(b));
}

QTEST_MAIN(TestCompound)
#include "test_compound.moc"
