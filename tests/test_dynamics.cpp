// Free-body dynamics against closed forms. Under constant acceleration each integrator with step h
// has a known, exact discrete solution, x_n = x0 + v0 t + 1/2 g t^2 + c g h t with c = 1/2 for
// semi-implicit Euler, -1/2 for explicit Euler and 0 for velocity Verlet, so the tests assert both
// that discrete answer (to float rounding) and the bound |error| <= 1/2 |g| h t against the
// continuous one.

#include "simcore/io/scene_io.h"
#include "simcore/world/world.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace simcore;

Q_DECLARE_METATYPE(simcore::Integrator)

namespace {

WorldSettings zeroGravity() {
    WorldSettings s;
    s.gravity = Vec3(0.0f);
    s.sleep.enabled = false;
    return s;
}

BodyCreationSettings dynamicBox(const Vec3& halfExtents, const Vec3& position = Vec3(0.0f)) {
    BodyCreationSettings b;
    b.name = "box";
    b.shape = Shape::box(halfExtents);
    b.position = position;
    b.mass = 2.0f;
    return b;
}

// Relative float rounding accumulated over n additions of comparable terms.
float roundingBound(float magnitude, int steps) { return 4.0f * magnitude * 1.2e-7f * static_cast<float>(steps); }

}  // namespace

class TestDynamics : public QObject {
    Q_OBJECT

private slots:
    void projectileMatchesDiscreteAndContinuousSolutions_data();
    void projectileMatchesDiscreteAndContinuousSolutions();
    void torqueFreeSpinAboutPrincipalAxis_data();
    void torqueFreeSpinAboutPrincipalAxis();
    void appliedForceActsOverTheWholeStep_data();
    void appliedForceActsOverTheWholeStep();
    void quaternionStaysUnitOverMillionSteps();
    void dampingDecaysExponentially();
    void staticAndKinematicBodiesIgnoreGravity();
    void impulseChangesMomentumAndAngularMomentum();
    void staleHandlesAreDetected();
    void restingBodyFallsAsleepAndWakesOnImpulse();
    void mixedPileSleepsWithinTenSeconds();
    void disabledOrUnneededEffectsDoNotRun();
    void invalidCreationSettingsAreRejectedByName_data();
    void invalidCreationSettingsAreRejectedByName();
};

void TestDynamics::projectileMatchesDiscreteAndContinuousSolutions_data() {
    QTest::addColumn<float>("dt");
    QTest::addColumn<int>("substeps");
    QTest::addColumn<QVector<float>>("velocity");
    QTest::addColumn<Integrator>("integrator");
    QTest::addColumn<float>("offsetPerGht");  // c in the discrete solution's c g h t
    const struct {
        Integrator method;
        float offset;
    } integrators[] = {{Integrator::SymplecticEuler, 0.5f}, {Integrator::ExplicitEuler, -0.5f},
                       {Integrator::VelocityVerlet, 0.0f}};
    for (const auto& [method, offset] : integrators) {
        const std::string name(integratorName(method));
        auto row = [&](const char* label) -> QTestData& { return QTest::newRow((name + ", " + label).c_str()); };
        row("free fall 60 Hz") << 1.0f / 60.0f << 1 << QVector<float>{0, 0, 0} << method << offset;
        row("projectile 60 Hz") << 1.0f / 60.0f << 1 << QVector<float>{3, 5, -2} << method << offset;
        row("projectile 60 Hz, 4 substeps") << 1.0f / 60.0f << 4 << QVector<float>{3, 5, -2} << method << offset;
        row("projectile 240 Hz") << 1.0f / 240.0f << 1 << QVector<float>{-1, 12, 0.5f} << method << offset;
    }
}

void TestDynamics::projectileMatchesDiscreteAndContinuousSolutions() {
    QFETCH(float, dt);
    QFETCH(int, substeps);
    QFETCH(QVector<float>, velocity);
    QFETCH(Integrator, integrator);
    QFETCH(float, offsetPerGht);

    WorldSettings settings;
    settings.timeStep = dt;
    settings.substeps = substeps;
    settings.integrator = integrator;
    settings.sleep.enabled = false;
    World world(settings);
    const Vec3 x0(1.0f, 10.0f, -3.0f);
    const Vec3 v0(velocity[0], velocity[1], velocity[2]);
    BodyCreationSettings body = dynamicBox(Vec3(0.5f), x0);
    body.linearVelocity = v0;
    const BodyId id = world.createBody(body);

    const int steps = static_cast<int>(std::lround(2.0f / dt));
    for (int i = 0; i < steps; ++i) world.step();

    const float h = dt / static_cast<float>(substeps);
    const float t = static_cast<float>(steps) * dt;
    const Vec3 g = settings.gravity;
    const Vec3 continuous = x0 + v0 * t + 0.5f * g * t * t;
    const Vec3 discrete = continuous + offsetPerGht * g * h * t;
    const Vec3 x = world.position(id);
    const float tolerance = roundingBound(glm::length(continuous) + 20.0f, steps * substeps);

    QVERIFY2(glm::length(x - discrete) < tolerance,
             qPrintable(QString("off the discrete solution by %1 m").arg(glm::length(x - discrete))));
    QVERIFY(glm::length(x - continuous) <= 0.5f * glm::length(g) * h * t + tolerance);
    QVERIFY(glm::length(world.linearVelocity(id) - (v0 + g * t)) < tolerance);
    QCOMPARE(world.orientation(id), Quat(1.0f, 0.0f, 0.0f, 0.0f));
}

void TestDynamics::torqueFreeSpinAboutPrincipalAxis_data() {
    QTest::addColumn<int>("axis");
    QTest::addColumn<float>("rate");
    // Box with distinct principal moments: I_x < I_y < I_z for half extents (0.5, 0.3, 0.1)... the
    // largest half extents give the largest moments about the other axes.
    QTest::newRow("min axis x") << 0 << 3.0f;
    QTest::newRow("intermediate axis y") << 1 << 3.0f;
    QTest::newRow("max axis z") << 2 << -5.0f;
}

void TestDynamics::torqueFreeSpinAboutPrincipalAxis() {
    QFETCH(int, axis);
    QFETCH(float, rate);

    WorldSettings settings = zeroGravity();
    World world(settings);
    Vec3 omega(0.0f);
    omega[axis] = rate;
    BodyCreationSettings body = dynamicBox(Vec3(0.5f, 0.3f, 0.1f));
    body.angularVelocity = omega;
    const BodyId id = world.createBody(body);
    const Vec3 angularMomentum0 = world.angularMomentum();
    const double energy0 = world.kineticEnergy();

    const int steps = 600;
    for (int i = 0; i < steps; ++i) world.step();

    // About a principal axis w x (I w) = 0: the rate is constant and the body turns uniformly.
    QVERIFY(glm::length(world.angularVelocity(id) - omega) < 1e-5f * std::abs(rate));
    QVERIFY(glm::length(world.angularMomentum() - angularMomentum0) < 1e-5f * glm::length(angularMomentum0));
    QVERIFY(std::abs(world.kineticEnergy() - energy0) < 1e-5 * energy0);

    // The first-order quaternion update turns by 2 atan(h w / 2) per substep instead of h w: the
    // discrete angle is known exactly, and differs from the continuous one by (h w)^3 / 12 a substep.
    const int substeps = steps * settings.substeps;
    const float h = settings.timeStep / static_cast<float>(settings.substeps);
    const float w = std::abs(rate);
    const double discreteAngle = substeps * 2.0 * std::atan(0.5 * h * w);
    const double continuousAngle = substeps * static_cast<double>(h) * w;
    const Quat q = world.orientation(id);
    Vec3 expectedAxis(0.0f);
    expectedAxis[axis] = rate > 0.0f ? 1.0f : -1.0f;
    const Quat expected = glm::angleAxis(static_cast<float>(discreteAngle), expectedAxis);
    const float angleError = 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(q, expected))));
    QVERIFY2(angleError < 2e-3f, qPrintable(QString("orientation off by %1 rad").arg(angleError)));
    QVERIFY(std::abs(discreteAngle - continuousAngle) <= substeps * std::pow(h * w, 3.0) / 12.0 * 1.01);
}

void TestDynamics::appliedForceActsOverTheWholeStep_data() {
    QTest::addColumn<int>("substeps");
    for (int substeps : {1, 2, 4, 8}) QTest::newRow(qPrintable(QString("%1 substeps").arg(substeps))) << substeps;
}

// A force and a torque added before every step act over the whole step, in every substep: on a
// 1 kg ball in zero gravity, F newtons for 1 s make F m/s whatever the substep count (they used to
// act in the first substep only, F / substeps). The ball's inertia is isotropic, so there is no
// gyroscopic term and w = tau t / I exactly. The position follows semi-implicit Euler's discrete
// solution x = a t^2 / 2 + a h t / 2 (h the substep). Each of the 60 k substeps adds a h to v,
// rounding by at most half an ulp of |v| <= |F|: the bound below is that sum, N 2^-24 |F|
// (2.9e-5 relative at 8 substeps); the measured error is far below it.
void TestDynamics::appliedForceActsOverTheWholeStep() {
    QFETCH(int, substeps);
    WorldSettings settings = zeroGravity();
    settings.timeStep = 1.0f / 60.0f;
    settings.substeps = substeps;
    World world(settings);
    BodyCreationSettings body;
    body.shape = Shape::sphere(0.5f);
    body.mass = 1.0f;
    const BodyId id = world.createBody(body);
    const float inertia = world.localInertia(id)[0][0];
    const Vec3 force(3.0f, -1.5f, 0.5f);  // N
    const Vec3 torque(0.0f, 0.02f, 0.0f);  // N m

    const int steps = 60;
    for (int i = 0; i < steps; ++i) {
        world.addForce(id, force);
        world.addTorque(id, torque);
        world.step();
    }
    // Spent at the end of the step: one more without adding it leaves the velocities as they are.
    const Vec3 v = world.linearVelocity(id), w = world.angularVelocity(id);
    const Vec3 x = world.centerOfMass(id);

    const double t = steps * static_cast<double>(settings.timeStep);
    const double h = settings.timeStep / static_cast<float>(substeps);
    const int n = steps * substeps;
    const auto bound = [n](double magnitude) { return n * std::ldexp(1.0, -24) * magnitude; };
    const glm::dvec3 a(force);  // m = 1 kg
    const double velocityError = glm::length(glm::dvec3(v) - a * t);
    const double spinError = glm::length(glm::dvec3(w) - glm::dvec3(torque) / double(inertia) * t);
    const double positionError = glm::length(glm::dvec3(x) - (0.5 * a * t * t + 0.5 * a * h * t));
    qInfo("%d substeps: |v| = %.7f m/s (expected %.7f, off by %.2e), |w| off by %.2e, x off by %.2e m", substeps,
          glm::length(v), glm::length(a * t), velocityError, spinError, positionError);
    QVERIFY2(velocityError <= bound(glm::length(a * t)), qPrintable(QString("v off by %1 m/s").arg(velocityError)));
    QVERIFY2(spinError <= bound(glm::length(glm::dvec3(torque) / double(inertia) * t)),
             qPrintable(QString("w off by %1 rad/s").arg(spinError)));
    // x adds h v n times: the velocities' error (at most the bound, over t) and its own rounding.
    QVERIFY2(positionError <= t * bound(glm::length(a * t)) + bound(glm::length(glm::dvec3(x))),
             qPrintable(QString("x off by %1 m").arg(positionError)));

    world.step();
    QCOMPARE(world.linearVelocity(id), v);
    QCOMPARE(world.angularVelocity(id), w);
}

void TestDynamics::quaternionStaysUnitOverMillionSteps() {
    World world(zeroGravity());
    BodyCreationSettings body = dynamicBox(Vec3(0.5f, 0.3f, 0.1f));
    body.angularVelocity = Vec3(0.3f, 7.0f, -2.0f);  // tumbling, not about a principal axis
    const BodyId id = world.createBody(body);
    float worstNormError = 0.0f;
    for (int i = 0; i < 1'000'000; ++i) {
        world.step();
        worstNormError = std::max(worstNormError, std::abs(glm::length(world.orientation(id)) - 1.0f));
    }
    QVERIFY(!world.findNonFiniteBody());
    QVERIFY2(worstNormError < 1e-6f, qPrintable(QString("|q| - 1 reached %1").arg(worstNormError)));
}

void TestDynamics::dampingDecaysExponentially() {
    WorldSettings settings = zeroGravity();
    settings.damping.linear = 0.5f;
    settings.damping.angular = 2.0f;
    World world(settings);
    BodyCreationSettings body = dynamicBox(Vec3(0.5f));  // cube: isotropic inertia, no gyroscopic torque
    body.linearVelocity = Vec3(4.0f, 0.0f, 0.0f);
    body.angularVelocity = Vec3(0.0f, 3.0f, 0.0f);
    const BodyId id = world.createBody(body);
    for (int i = 0; i < 120; ++i) world.step();
    const float t = 120 * settings.timeStep;
    QVERIFY(std::abs(world.linearVelocity(id).x - 4.0f * std::exp(-0.5f * t)) < 1e-5f);
    QVERIFY(std::abs(world.angularVelocity(id).y - 3.0f * std::exp(-2.0f * t)) < 1e-5f);
    QVERIFY(world.effectUsage().ran(Effect::Damping));
}

void TestDynamics::staticAndKinematicBodiesIgnoreGravity() {
    World world;
    BodyCreationSettings ground;
    ground.motion = MotionType::Static;
    ground.shape = Shape::box(Vec3(10.0f, 0.5f, 10.0f));
    ground.position = Vec3(0.0f, -0.5f, 0.0f);
    ground.linearVelocity = Vec3(1.0f, 0.0f, 0.0f);  // ignored: static bodies never move
    const BodyId groundId = world.createBody(ground);

    BodyCreationSettings platform;
    platform.motion = MotionType::Kinematic;
    platform.shape = Shape::box(Vec3(1.0f, 0.1f, 1.0f));
    platform.position = Vec3(0.0f, 2.0f, 0.0f);
    platform.linearVelocity = Vec3(0.5f, 0.0f, 0.0f);
    const BodyId platformId = world.createBody(platform);

    for (int i = 0; i < 60; ++i) world.step();
    QCOMPARE(world.position(groundId), Vec3(0.0f, -0.5f, 0.0f));
    QVERIFY(glm::length(world.position(platformId) - Vec3(0.5f, 2.0f, 0.0f)) < 1e-5f);
    QCOMPARE(world.mass(platformId), 0.0f);
    // Nothing dynamic: gravity has nothing to act on and is skipped.
    QVERIFY(!world.effectUsage().ran(Effect::Gravity));
}

void TestDynamics::impulseChangesMomentumAndAngularMomentum() {
    World world(zeroGravity());
    const BodyId id = world.createBody(dynamicBox(Vec3(0.5f), Vec3(0.0f, 1.0f, 0.0f)));
    const Vec3 impulse(0.0f, 0.0f, 3.0f);
    const Vec3 point(0.5f, 1.0f, 0.0f);  // on the +x face, off the centre of mass
    world.addImpulse(id, impulse, point);
    QVERIFY(glm::length(world.linearMomentum() - impulse) < 1e-6f);
    // Angular momentum about the origin gains r x J for the point of application.
    QVERIFY(glm::length(world.angularMomentum() - glm::cross(point, impulse)) < 1e-5f);
}

void TestDynamics::staleHandlesAreDetected() {
    World world(zeroGravity());
    const BodyId a = world.createBody(dynamicBox(Vec3(0.5f), Vec3(1.0f, 0.0f, 0.0f)));
    const BodyId b = world.createBody(dynamicBox(Vec3(0.5f), Vec3(2.0f, 0.0f, 0.0f)));
    const BodyId c = world.createBody(dynamicBox(Vec3(0.5f), Vec3(3.0f, 0.0f, 0.0f)));
    world.destroyBody(a);
    QVERIFY(!world.contains(a));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, world.position(a));
    // The last body was moved into the freed slot; its handle still resolves to it.
    QCOMPARE(world.position(c), Vec3(3.0f, 0.0f, 0.0f));
    QCOMPARE(world.position(b), Vec3(2.0f, 0.0f, 0.0f));
    const BodyId d = world.createBody(dynamicBox(Vec3(0.5f), Vec3(4.0f, 0.0f, 0.0f)));
    QCOMPARE(d.index, a.index);  // slot reused...
    QVERIFY(!world.contains(a));  // ...but the old handle stays stale
    QCOMPARE(world.bodyCount(), std::size_t(3));
}

void TestDynamics::restingBodyFallsAsleepAndWakesOnImpulse() {
    WorldSettings settings = zeroGravity();
    settings.sleep.enabled = true;
    World world(settings);
    const BodyId id = world.createBody(dynamicBox(Vec3(0.5f)));
    const int stepsToSleep = static_cast<int>(std::ceil(settings.sleep.timeToSleep / settings.timeStep));
    for (int i = 0; i < stepsToSleep - 1; ++i) world.step();
    QVERIFY(world.isAwake(id));
    world.step();
    QVERIFY(!world.isAwake(id));
    world.addImpulse(id, Vec3(1.0f, 0.0f, 0.0f), world.centerOfMass(id));
    QVERIFY(world.isAwake(id));
    world.step();
    QVERIFY(world.position(id).x > 0.0f);
}

// scenes/bench/mixed1k.json (1000 spheres, capsules, cylinders and boxes dropped in a grid, no
// rolling resistance) at the defaults: every body asleep within 10 s, as in Box3D (issue 12).
void TestDynamics::mixedPileSleepsWithinTenSeconds() {
    const SceneLoadResult loaded = loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/scenes/bench/mixed1k.json");
    QVERIFY(loaded.ok());
    WorldSettings defaults;
    defaults.gravity = loaded.scene->settings.gravity;
    defaults.timeStep = loaded.scene->settings.timeStep;
    QVERIFY(loaded.scene->settings == defaults);
    World world(loaded.scene->settings);
    std::vector<BodyId> dynamic;
    for (const SceneBody& b : loaded.scene->bodies) {
        const BodyId id = world.createBody(b.body);
        if (b.body.motion == MotionType::Dynamic) dynamic.push_back(id);
    }
    QCOMPARE(dynamic.size(), std::size_t{1000});
    auto awake = [&] { return std::count_if(dynamic.begin(), dynamic.end(), [&](BodyId id) { return world.isAwake(id); }); };
    const int limit = static_cast<int>(std::lround(10.0f / world.settings().timeStep));
    int step = 0;
    while (step < limit && awake() > 0) {
        world.step();
        ++step;
    }
    qInfo("mixed1k: %d of 1000 awake after %.2f s", static_cast<int>(awake()), step * world.settings().timeStep);
    QCOMPARE(awake(), 0);
}

void TestDynamics::disabledOrUnneededEffectsDoNotRun() {
    WorldSettings settings;
    settings.effects[Effect::Gravity] = false;
    settings.sleep.enabled = false;
    World world(settings);
    const BodyId id = world.createBody(dynamicBox(Vec3(0.5f), Vec3(0.0f, 5.0f, 0.0f)));
    for (int i = 0; i < 30; ++i) world.step();
    QCOMPARE(world.position(id), Vec3(0.0f, 5.0f, 0.0f));
    for (int e = 0; e < kEffectCount; ++e)
        QVERIFY2(!world.effectUsage().ran(static_cast<Effect>(e)),
                 qPrintable(QString("%1 ran").arg(effectName(static_cast<Effect>(e)).data())));
}

void TestDynamics::invalidCreationSettingsAreRejectedByName_data() {
    QTest::addColumn<int>("defect");
    QTest::addColumn<QString>("field");
    QTest::newRow("negative radius") << 0 << "radius";
    QTest::newRow("zero half extent") << 1 << "halfExtents";
    QTest::newRow("NaN position") << 2 << "position";
    QTest::newRow("zero quaternion") << 3 << "orientation";
    QTest::newRow("zero mass") << 4 << "mass";
    QTest::newRow("negative friction") << 5 << "friction";
    QTest::newRow("restitution above one") << 6 << "restitution";
    QTest::newRow("infinite velocity") << 7 << "linearVelocity";
    QTest::newRow("negative rolling resistance") << 8 << "rollingResistance";
    QTest::newRow("NaN rolling resistance") << 9 << "rollingResistance";
}

void TestDynamics::invalidCreationSettingsAreRejectedByName() {
    QFETCH(int, defect);
    QFETCH(QString, field);
    BodyCreationSettings b = dynamicBox(Vec3(0.5f));
    switch (defect) {
        case 0: b.shape = Shape::sphere(-1.0f); break;
        case 1: b.shape = Shape::box(Vec3(1.0f, 0.0f, 1.0f)); break;
        case 2: b.position.y = std::nanf(""); break;
        case 3: b.orientation = Quat(0.0f, 0.0f, 0.0f, 0.0f); break;
        case 4: b.mass = 0.0f; break;
        case 5: b.friction = -0.1f; break;
        case 6: b.restitution = 1.5f; break;
        case 7: b.linearVelocity.x = INFINITY; break;
        case 8: b.rollingResistance = -0.01f; break;
        case 9: b.rollingResistance = std::nanf(""); break;
    }
    World world;
    try {
        world.createBody(b);
        QFAIL("accepted invalid settings");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(QString(e.what()).contains(field), e.what());
    }
    QCOMPARE(world.bodyCount(), std::size_t(0));
}

QTEST_APPLESS_MAIN(TestDynamics)
#include "test_dynamics.moc"
