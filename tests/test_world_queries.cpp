// World queries: the closest-hit ray cast the editor picks with, the load on a body's contacts, and
// copies of a world (the editor's timeline keeps them) that step on bit for bit.

#include "simcore/world/world.h"

#include "support/state_hash.h"

#include <QtTest>

using namespace simcore;

namespace {

BodyId addBox(World& world, const Vec3& position, MotionType motion = MotionType::Dynamic) {
    BodyCreationSettings b;
    b.shape = Shape::box(Vec3(0.5f));
    b.position = position;
    b.motion = motion;
    return world.createBody(b);
}

WorldSettings floating() {
    WorldSettings s;
    s.gravity = Vec3(0.0f);
    s.sleep.enabled = false;
    return s;
}

}  // namespace

class TestWorldQueries : public QObject {
    Q_OBJECT

private slots:
    void closestBodyAlongTheRay_data();
    void closestBodyAlongTheRay();
    void followsMovingBodies_data();
    void followsMovingBodies();
    void removedBodiesAreNotHit();
    void contactLoadCarriesTheWeight_data();
    void contactLoadCarriesTheWeight();
    void contactLoadOfAFreeBodyIsZero();
    void kineticEnergyOfOneBody();
    void copyStepsOnBitForBit_data();
    void copyStepsOnBitForBit();
};

void TestWorldQueries::closestBodyAlongTheRay_data() {
    QTest::addColumn<QVector<float>>("origin");
    QTest::addColumn<QVector<float>>("direction");
    QTest::addColumn<float>("maxFraction");
    QTest::addColumn<int>("expectedBody");  // index into the row of boxes, -1 for a miss
    QTest::addColumn<float>("expectedFraction");
    // Boxes of side 1 centred at x = 0, 3, 6; a static one at x = 9.
    QTest::newRow("from the left hits the first") << QVector<float>{-5, 0, 0} << QVector<float>{20, 0, 0} << 1.0f << 0 << 4.5f / 20.0f;
    QTest::newRow("from the right hits the static last") << QVector<float>{15, 0, 0} << QVector<float>{-20, 0, 0} << 1.0f << 3 << 5.5f / 20.0f;
    QTest::newRow("from above hits the middle") << QVector<float>{3, 10, 0} << QVector<float>{0, -1, 0} << 100.0f << 1 << 9.5f;
    QTest::newRow("between the boxes") << QVector<float>{1.5f, 10, 0} << QVector<float>{0, -1, 0} << 100.0f << -1 << 0.0f;
    QTest::newRow("too short") << QVector<float>{-5, 0, 0} << QVector<float>{1, 0, 0} << 4.0f << -1 << 0.0f;
    QTest::newRow("pointing away") << QVector<float>{-5, 0, 0} << QVector<float>{-1, 0, 0} << 100.0f << -1 << 0.0f;
}

void TestWorldQueries::closestBodyAlongTheRay() {
    QFETCH(QVector<float>, origin);
    QFETCH(QVector<float>, direction);
    QFETCH(float, maxFraction);
    QFETCH(int, expectedBody);
    QFETCH(float, expectedFraction);

    World world(floating());
    const BodyId ids[] = {addBox(world, {0, 0, 0}), addBox(world, {3, 0, 0}), addBox(world, {6, 0, 0}),
                          addBox(world, {9, 0, 0}, MotionType::Static)};
    const Vec3 o(origin[0], origin[1], origin[2]);
    const Vec3 d(direction[0], direction[1], direction[2]);
    const auto hit = world.castRay(o, d, maxFraction);
    if (expectedBody < 0) {
        QVERIFY(!hit);
        return;
    }
    QVERIFY(hit);
    QVERIFY(hit->body == ids[expectedBody]);
    QVERIFY(std::abs(hit->fraction - expectedFraction) < 1e-5f);
    QVERIFY(glm::length(hit->point - (o + hit->fraction * d)) < 1e-4f);
    QVERIFY(std::abs(glm::length(hit->normal) - 1.0f) < 1e-5f);
    QVERIFY(glm::dot(hit->normal, d) < 0.0f);
}

void TestWorldQueries::followsMovingBodies_data() {
    QTest::addColumn<bool>("contacts");
    QTest::newRow("broad phase running") << true;
    QTest::newRow("contacts off, broad phase idle") << false;
}

void TestWorldQueries::followsMovingBodies() {
    QFETCH(bool, contacts);
    WorldSettings settings = floating();
    settings.effects[Effect::Contacts] = contacts;
    World world(settings);
    const BodyId mover = addBox(world, {0, 0, 0});
    addBox(world, {0, 0, 50});  // a second body, so contacts are needed when enabled
    world.setLinearVelocity(mover, Vec3(10.0f, 0.0f, 0.0f));
    for (int i = 0; i < 60; ++i) world.step();  // 10 m to the right, far beyond any fat margin
    const auto hit = world.castRay(Vec3(world.position(mover).x, 10.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 100.0f);
    QVERIFY(hit);
    QVERIFY(hit->body == mover);
    QVERIFY(std::abs(hit->fraction - 9.5f) < 1e-4f);
    QVERIFY(!world.castRay(Vec3(0.0f, 10.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 100.0f));  // where it was
}

void TestWorldQueries::removedBodiesAreNotHit() {
    World world(floating());
    const BodyId first = addBox(world, {0, 0, 0});
    const BodyId second = addBox(world, {3, 0, 0});
    world.destroyBody(first);
    const auto hit = world.castRay(Vec3(-5, 0, 0), Vec3(1, 0, 0), 100.0f);
    QVERIFY(hit);
    QVERIFY(hit->body == second);
}

void TestWorldQueries::contactLoadCarriesTheWeight_data() {
    QTest::addColumn<float>("mass");
    QTest::addColumn<int>("substeps");
    QTest::newRow("1 kg, 4 substeps") << 1.0f << 4;
    QTest::newRow("50 kg, 4 substeps") << 50.0f << 4;
    QTest::newRow("3 kg, 1 substep") << 3.0f << 1;
}

// A box resting on the ground: its one manifold carries its weight, m g, at any number of substeps
// (the ground's load counts the same manifold from the other side).
void TestWorldQueries::contactLoadCarriesTheWeight() {
    QFETCH(float, mass);
    QFETCH(int, substeps);
    WorldSettings settings;
    settings.sleep.enabled = false;
    settings.substeps = substeps;
    World world(settings);
    const BodyId ground = addBox(world, {0, -0.5f, 0}, MotionType::Static);
    BodyCreationSettings b;
    b.shape = Shape::box(Vec3(0.5f));
    b.position = Vec3(0.0f, 0.5f, 0.0f);
    b.mass = mass;
    const BodyId box = world.createBody(b);
    for (int i = 0; i < 120; ++i) world.step();  // 2 s: settled
    const ContactLoad load = world.contactLoad(box);
    QCOMPARE(load.contacts, 1);
    const float weight = mass * glm::length(settings.gravity);
    const float force = load.normalForce;
    // At rest the contact holds exactly the weight; 0.5 % allows the soft contact's residual bounce.
    QVERIFY2(std::abs(force - weight) < 0.005f * weight, qPrintable(QString("%1 N against %2 N").arg(force).arg(weight)));
    QCOMPARE(world.contactLoad(ground).contacts, 1);
    QCOMPARE(world.contactLoad(ground).normalForce, load.normalForce);
}

void TestWorldQueries::contactLoadOfAFreeBodyIsZero() {
    World world(floating());
    addBox(world, {0, 0, 0});
    const BodyId far = addBox(world, {10, 0, 0});
    world.step();
    QCOMPARE(world.contactLoad(far).contacts, 0);
    QCOMPARE(world.contactLoad(far).normalForce, 0.0f);
    world.destroyBody(far);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, world.contactLoad(far));
}

// A 2 kg cube of side 1 moving at (1, 2, 0) m/s and spinning at 3 rad/s: 1/2 m v^2 + 1/2 I w^2
// with I = m a^2 / 6; the world's total is the sum over its bodies, a static one adding nothing.
void TestWorldQueries::kineticEnergyOfOneBody() {
    World world(floating());
    BodyCreationSettings b;
    b.shape = Shape::box(Vec3(0.5f));
    b.mass = 2.0f;
    b.linearVelocity = Vec3(1.0f, 2.0f, 0.0f);
    b.angularVelocity = Vec3(0.0f, 0.0f, 3.0f);
    b.orientation = glm::angleAxis(0.7f, glm::normalize(Vec3(1, 1, 0)));  // a cube's inertia is the same about any axis
    const BodyId moving = world.createBody(b);
    b.linearVelocity = Vec3(0.0f, 0.0f, -1.0f);
    b.angularVelocity = Vec3(0.0f);
    b.position = Vec3(5.0f, 0.0f, 0.0f);
    const BodyId sliding = world.createBody(b);
    const BodyId fixed = addBox(world, {-5, 0, 0}, MotionType::Static);
    const double expected = 0.5 * 2.0 * 5.0 + 0.5 * (2.0 / 6.0) * 9.0;
    QVERIFY(std::abs(world.kineticEnergy(moving) - expected) < 1e-5 * expected);
    QVERIFY(std::abs(world.kineticEnergy(sliding) - 1.0) < 1e-6);
    QCOMPARE(world.kineticEnergy(fixed), 0.0);
    QCOMPARE(world.kineticEnergy(), world.kineticEnergy(moving) + world.kineticEnergy(sliding));
}

void TestWorldQueries::copyStepsOnBitForBit_data() {
    QTest::addColumn<int>("threads");
    QTest::newRow("1 thread") << 1;
    QTest::newRow("3 threads") << 3;
}

// A pile of tumbling boxes: contacts, warm starts and the broad phase's tree all matter to the
// next steps, so a copy that missed any of them would drift from the original within a few steps.
void TestWorldQueries::copyStepsOnBitForBit() {
    QFETCH(int, threads);
    WorldSettings settings;
    settings.threads = threads;
    World original(settings);
    addBox(original, {0, -0.5f, 0}, MotionType::Static);
    for (int i = 0; i < 27; ++i) {
        BodyCreationSettings b;
        b.shape = Shape::box(Vec3(0.25f));
        b.position = Vec3(float(i % 3) * 0.55f - 0.55f, 1.0f + float(i / 9) * 0.6f, float((i / 3) % 3) * 0.55f - 0.55f);
        b.orientation = glm::angleAxis(0.3f * float(i), glm::normalize(Vec3(1, 2, 3)));
        original.createBody(b);
    }
    for (int i = 0; i < 40; ++i) original.step();
    QVERIFY(original.contactCount() > 0);
    World copy(original);
    QCOMPARE(test_support::stateHash(copy), test_support::stateHash(original));
    QCOMPARE(copy.stepCount(), original.stepCount());
    World assigned;
    assigned = copy;
    for (int i = 0; i < 80; ++i) {
        original.step();
        copy.step();
        assigned.step();
        QCOMPARE(test_support::stateHash(copy), test_support::stateHash(original));
        QCOMPARE(test_support::stateHash(assigned), test_support::stateHash(original));
    }
    QCOMPARE(copy.contactCount(), original.contactCount());
}

QTEST_APPLESS_MAIN(TestWorldQueries)
#include "test_world_queries.moc"
