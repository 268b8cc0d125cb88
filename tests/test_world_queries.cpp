// World queries: the closest-hit ray cast the editor picks with.

#include "simcore/world/world.h"

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

QTEST_APPLESS_MAIN(TestWorldQueries)
#include "test_world_queries.moc"
