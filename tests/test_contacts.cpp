// Over 800 lines because it is the contact solver's one suite: some thirty closed-form cases, each
// with the reasoning behind its tolerance next to it, which is most of the length.
// Contact physics against closed forms and stability bounds: sliding and sticking on an incline,
// rolling, elastic and inelastic impacts, stacks that must stand, sleeping and waking, effect
// switches, no allocation in steady state, and long mixed runs that stay finite and never gain
// energy. Every world is built in code except the benchmark stacks, whose scene files are the
// subject. Tolerances are justified where they are asserted: the main error sources are the step
// (dt = 1/60 s, 4 substeps of h = 1/240 s), the soft contact (a stiff, overdamped spring, so
// resting contacts sit a little inside each other) and float rounding.

#include "simcore/io/scene_io.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/world/world.h"

#include "support/allocation_counter.h"
#include "support/worlds.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

using namespace simcore;
using namespace test_support;

namespace {

constexpr float kG = 9.81f;
constexpr float kTheta = Incline::kTheta;

// Acceleration along the slope from the velocity at t = 0.5 s and t = 1.5 s (past the first
// contact transient; the velocity difference over 1 s is the mean acceleration).
float measureSlopeAcceleration(World& world, const Incline& incline) {
    run(world, 0.5f);
    const float v0 = incline.slopeSpeed(world);
    run(world, 1.0f);
    return incline.slopeSpeed(world) - v0;
}

QString vecString(const Vec3& v) { return QString("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z); }

}  // namespace

class TestContacts : public QObject {
    Q_OBJECT

private slots:
    void boxOnInclineSticksOrSlides_data();
    void boxOnInclineSticksOrSlides();
    void sphereRollsWithoutSlipping();
    void spinningBoxSlowsAtTheCornerFrictionRate_data();
    void spinningBoxSlowsAtTheCornerFrictionRate();
    void rollingResistanceDeceleratesABall_data();
    void rollingResistanceDeceleratesABall();
    void rollingResistanceOnAnIncline_data();
    void rollingResistanceOnAnIncline();
    void rollingResistanceLeavesFlatPairsAlone();
    void elasticSpheresHeadOn_data();
    void elasticSpheresHeadOn();
    void boxWithoutRestitutionDoesNotBounce();
    void fastImpactIsMetAtTheSurface_data();
    void fastImpactIsMetAtTheSurface();
    void spinningCapsuleLandsWithoutDipping();
    void ballReboundsToQuarterHeight();
    void elasticBallReturnsToItsHeight_data();
    void elasticBallReturnsToItsHeight();
    void boxLandingFlatBouncesAsAWhole();
    void symmetricImpactStaysInItsPlane();
    void elasticTumblingBoxGainsNoEnergy_data();
    void elasticTumblingBoxGainsNoEnergy();
    void benchStacksStand_data();
    void benchStacksStand();
    void heavyOnLightHolds();
    void pileSleepsAndWakesWhenHit();
    void effectSwitches();
    void restitutionRunsOnlyWhenSomePairBounces();
    void steadyStateStepDoesNotAllocate();
    void contactCapLimitsPairsBetweenDynamicBodiesOnly();
    void longMixedRunStaysFiniteAndDoesNotGainEnergy();
};

// -------------------------------------------------------------------------------------------------
// 1. Coulomb friction on a 30 degree incline.

void TestContacts::boxOnInclineSticksOrSlides_data() {
    QTest::addColumn<float>("mu");
    QTest::addColumn<bool>("sticks");
    QTest::addColumn<float>("relativeTolerance");
    // tan 30 = 0.577 < 0.8: static friction holds the box.
    QTest::newRow("mu 0.8 sticks") << 0.8f << true << 0.0f;
    // a = g (sin - mu cos) = 3.206 m/s^2. 1 %: with the first friction axis along the slip, the
    // clamped friction opposes the slip exactly (measured +0.2 %); friction axes at an angle to the
    // slip came out 3.6 % weak in mu (+2 % in a here, +23 % at mu 0.5), a wrong combining rule 20 %.
    QTest::newRow("mu 0.2 slides") << 0.2f << false << 0.01f;
    QTest::newRow("mu 0.5 slides") << 0.5f << false << 0.02f;  // a = 0.657 m/s^2: small, so 2 %
    // a = g sin = 4.905 m/s^2; nothing but the normal force acts along the slope, so only the
    // contact's tangential leakage (normal solved at anchors that move within the step) remains: 3 %.
    QTest::newRow("mu 0 slides freely") << 0.0f << false << 0.03f;
}

void TestContacts::boxOnInclineSticksOrSlides() {
    QFETCH(float, mu);
    QFETCH(bool, sticks);
    QFETCH(float, relativeTolerance);

    World world(awakeSettings());
    const Incline incline(world, Shape::box(Vec3(0.25f)), 0.25f, mu);
    const Vec3 start = world.position(incline.body);

    if (sticks) {
        run(world, 5.0f);
        const float displacement = glm::length(world.position(incline.body) - start);
        qInfo("mu %.1f: moved %.5f m in 5 s", mu, displacement);
        // 1 cm over 5 s: a sticking box only settles into the soft contact (sub-millimetre);
        // a slowly creeping one would cover centimetres.
        QVERIFY2(displacement < 0.01f, qPrintable(QString("box moved %1 m").arg(displacement)));
        QVERIFY(world.effectUsage().ran(Effect::Friction));
        return;
    }
    const float expected = kG * (std::sin(kTheta) - mu * std::cos(kTheta));
    const float a = measureSlopeAcceleration(world, incline);
    qInfo("mu %.1f: a = %.4f m/s^2, expected %.4f (%+.2f %%)", mu, a, expected, 100.0f * (a - expected) / expected);
    QVERIFY2(std::abs(a - expected) < relativeTolerance * expected,
             qPrintable(QString("a = %1 m/s^2, expected %2").arg(a).arg(expected)));
    // It slides along the slope, not off it: the velocity stays parallel to the face.
    QVERIFY(std::abs(glm::dot(world.linearVelocity(incline.body), incline.normal)) < 0.05f);
    QCOMPARE(world.effectUsage().ran(Effect::Friction), mu > 0.0f);
}

// -------------------------------------------------------------------------------------------------
// 2. Rolling: a solid sphere (I = 2/5 m r^2) rolls without slipping when mu >= 2/7 tan(theta) = 0.165.

void TestContacts::sphereRollsWithoutSlipping() {
    World world(awakeSettings());
    const float r = 0.25f;
    const Incline incline(world, Shape::sphere(r), r, 1.0f);
    const float expected = 5.0f / 7.0f * kG * std::sin(kTheta);  // 3.504 m/s^2
    const float a = measureSlopeAcceleration(world, incline);
    qInfo("rolling: a = %.4f m/s^2, expected %.4f (%+.2f %%)", a, expected, 100.0f * (a - expected) / expected);
    // 5 %: a one-point contact, friction solved once per substep (the sliding box above has the
    // same budget). Sliding instead of rolling would give 4.9 m/s^2 (+40 %).
    QVERIFY2(std::abs(a - expected) < 0.05f * expected,
             qPrintable(QString("a = %1 m/s^2, expected %2").arg(a).arg(expected)));

    // Rolling: contact point at rest, so |w| = v / r (w along normal x downSlope).
    const float v = incline.slopeSpeed(world);
    const float w = glm::dot(world.angularVelocity(incline.body), glm::cross(incline.normal, incline.downSlope));
    qInfo("rolling: w = %.4f rad/s, v / r = %.4f", w, v / r);
    QVERIFY2(std::abs(w - v / r) < 0.05f * v / r, qPrintable(QString("w = %1 rad/s, v / r = %2").arg(w).arg(v / r)));
}

// -------------------------------------------------------------------------------------------------
// A unit cube resting on its four corner contacts and spinning about the vertical slows at
// alpha = mu m g r / I (each corner carries m g / 4 at r = sqrt(1/2) m from the axis; I = m / 6):
// the manifold's twist row bounds its torque by mu times each point's impulse times its lever arm,
// which is that torque exactly while the corners slip. 0.5 %: the bound; measured to the
// fourth digit (per-point friction rows came out 1.4 % weak).
void TestContacts::spinningBoxSlowsAtTheCornerFrictionRate_data() {
    QTest::addColumn<float>("mu");
    for (float mu : {0.2f, 0.5f, 1.0f}) QTest::addRow("mu %.1f", mu) << mu;
}

void TestContacts::spinningBoxSlowsAtTheCornerFrictionRate() {
    QFETCH(float, mu);
    World world(awakeSettings());
    addGround(world, mu);
    const BodyId id = world.createBody(cube(Vec3(0.0f, 0.5f, 0.0f), 1.0f, 0.5f, mu));
    run(world, 1.0f);  // settled on its corners
    constexpr float kSpin = 10.0f;
    world.setAngularVelocity(id, Vec3(0.0f, kSpin, 0.0f));
    const float alpha = mu * kG * std::sqrt(0.5f) * 6.0f;
    const float seconds = 0.8f * kSpin / alpha;  // still spinning: the slip has not stopped
    run(world, seconds);
    const float slowed = kSpin - world.angularVelocity(id).y;
    const float measured = slowed / (float(stepsFor(world, seconds)) * world.settings().timeStep);
    qInfo("slows at %.4f rad/s^2, closed form %.4f (%.3f %%)", measured, alpha, 100.0f * (measured / alpha - 1.0f));
    QVERIFY2(std::abs(measured / alpha - 1.0f) < 0.005f, qPrintable(QString("%1 rad/s^2").arg(measured)));
}

// 2b. Rolling resistance: a torque of up to C r N against the rolling (r the ball's radius, N the
// normal force). A solid sphere rolling without slipping on a flat floor at v, about the contact
// point (gravity, normal force and friction all pass through it): (I + m r^2) dw/dt = -C r m g,
// and with v = w r, a = -C r^2 m g / (I + m r^2) = -C g / (1 + I / (m r^2)) = -(5/7) C g.

namespace {

constexpr float kRollRadius = 0.25f;

// A 1 kg solid sphere of radius kRollRadius on the ground, rolling along +x at v0 without slipping.
BodyId addRollingBall(World& world, float v0, float rollingResistance) {
    BodyCreationSettings ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(kRollRadius);
    ball.mass = 1.0f;
    ball.position = Vec3(-20.0f, kRollRadius, 0.0f);
    ball.linearVelocity = Vec3(v0, 0.0f, 0.0f);
    ball.angularVelocity = Vec3(0.0f, 0.0f, -v0 / kRollRadius);  // contact point at rest: v + w x (-r y) = 0
    ball.rollingResistance = rollingResistance;
    return world.createBody(ball);
}

}  // namespace

void TestContacts::rollingResistanceDeceleratesABall_data() {
    QTest::addColumn<float>("coefficient");
    QTest::newRow("C 0 keeps rolling") << 0.0f;
    QTest::newRow("C 0.02") << 0.02f;
    QTest::newRow("C 0.05") << 0.05f;
    QTest::newRow("C 0.1") << 0.1f;
    QTest::newRow("C 0.2") << 0.2f;
}

void TestContacts::rollingResistanceDeceleratesABall() {
    QFETCH(float, coefficient);
    World world(awakeSettings());
    addGround(world);
    const float v0 = 3.0f;
    const BodyId ball = addRollingBall(world, v0, coefficient);
    const float expected = 5.0f / 7.0f * coefficient * kG;
    if (coefficient == 0.0f) {
        run(world, 2.0f);
        const float dv = world.linearVelocity(ball).x - v0;
        qInfo("C 0: dv = %.3g m/s over 2 s", dv);
        // A pure rolling contact needs no friction and keeps its speed but for the soft contact's
        // settling in the first steps (measured 1.2e-4 m/s): 1e-3 m/s is 1/14 of what even C = 0.001
        // would take away in 2 s ((5/7) C g t = 0.014 m/s).
        QVERIFY2(std::abs(dv) < 1e-3f, qPrintable(QString("dv = %1 m/s").arg(dv)));
        return;
    }
    // The mean deceleration between 0.5 s and 1.5 s (C = 0.2 stops at v0 / a = 2.1 s).
    run(world, 0.5f);
    const float v1 = world.linearVelocity(ball).x;
    run(world, 1.0f);
    const float v2 = world.linearVelocity(ball).x;
    const float a = v1 - v2;
    qInfo("C %.2f: a = %.5f m/s^2, expected (5/7) C g = %.5f (%+.3f %%)", coefficient, a, expected,
          100.0f * (a - expected) / expected);
    // 2 %: the bound C r sum(lambda_n) uses the normal impulse of the same relax pass, which holds
    // the ball's weight to the soft contact's settling (well under 1 %), and the rolling and
    // friction blocks are solved one after the other once per substep. Sliding friction would
    // decelerate at mu g = 5.4 m/s^2; a rule that left out the 2/7 share the floor's friction takes
    // (C g) would be 40 % off.
    QVERIFY2(std::abs(a - expected) < 0.02f * expected,
             qPrintable(QString("a = %1 m/s^2, expected %2").arg(a).arg(expected)));
    // Still rolling without slipping: w = v / r.
    const float w = -world.angularVelocity(ball).z;
    QVERIFY2(std::abs(w * kRollRadius - v2) < 1e-3f * v0, qPrintable(QString("w r = %1, v = %2").arg(w * kRollRadius).arg(v2)));
    QVERIFY(world.effectUsage().ran(Effect::Friction));
}

// On an incline of angle theta a ball held by rolling resistance needs, about its centre, the
// friction torque r F = r m g sin(theta) (F holds it along the slope) within C r m g cos(theta):
// it stays for C >= tan(theta) = 0.577 at 30 degrees. Below it, about the contact point,
// (I + m r^2) dw/dt = r m g sin(theta) - C r m g cos(theta): a = (5/7) g (sin(theta) - C cos(theta)).
// Friction 1 on both sides covers the F both need (at most m g sin(theta) = 0.58 mu m g cos(theta)).
void TestContacts::rollingResistanceOnAnIncline_data() {
    QTest::addColumn<float>("coefficient");
    QTest::newRow("C 0.2 rolls") << 0.2f;
    QTest::newRow("C 0.4 rolls") << 0.4f;
    QTest::newRow("C 0.5 rolls") << 0.5f;
    QTest::newRow("C 0.56 rolls") << 0.56f;  // 3 % below the threshold: a = 0.105 m/s^2
    QTest::newRow("C 0.59 stays") << 0.59f;  // 2 % above it
    QTest::newRow("C 1 stays") << 1.0f;
}

void TestContacts::rollingResistanceOnAnIncline() {
    QFETCH(float, coefficient);
    const float threshold = std::tan(kTheta);
    World world(awakeSettings());
    const float r = 0.25f;
    const Incline incline(world, Shape::sphere(r), r, 1.0f, coefficient);
    if (coefficient > threshold) {
        run(world, 0.5f);
        const Vec3 start = world.position(incline.body);
        run(world, 5.0f);
        const float displacement = glm::length(world.position(incline.body) - start);
        qInfo("C %.2f > tan(theta) = %.3f: moved %.5f m in 5 s", coefficient, threshold, displacement);
        // 1 cm in 5 s, as for the sticking box: a ball that rolled away at even a tenth of the
        // C = 0.56 rate would cover 0.26 m.
        QVERIFY2(displacement < 0.01f, qPrintable(QString("ball moved %1 m").arg(displacement)));
        return;
    }
    const float expected = 5.0f / 7.0f * kG * (std::sin(kTheta) - coefficient * std::cos(kTheta));
    const float a = measureSlopeAcceleration(world, incline);
    qInfo("C %.2f < tan(theta) = %.3f: a = %.4f m/s^2, expected %.4f (%+.2f %%)", coefficient, threshold, a, expected,
          100.0f * (a - expected) / expected);
    // 1 % of the rolling acceleration without resistance (0.035 m/s^2; measured within 4e-4 m/s^2):
    // the error of the rolling contact does not shrink with the difference sin - C cos, and a third
    // of the C = 0.56 acceleration, so a ball that stayed there would fail.
    const float budget = 0.01f * 5.0f / 7.0f * kG * std::sin(kTheta);
    QVERIFY2(std::abs(a - expected) < budget, qPrintable(QString("a = %1 m/s^2, expected %2").arg(a).arg(expected)));
}

// Two flat bodies have no rolling radius, so their lever is 0: a box with rolling resistance
// slides down the incline bit for bit as one without.
void TestContacts::rollingResistanceLeavesFlatPairsAlone() {
    std::vector<Vec3> paths[2];
    for (int i = 0; i < 2; ++i) {
        World world(awakeSettings());
        const Incline incline(world, Shape::box(Vec3(0.25f)), 0.25f, 0.2f, i == 0 ? 0.0f : 5.0f);
        for (int step = 0; step < 120; ++step) {
            world.step();
            paths[i].push_back(world.position(incline.body));
            paths[i].push_back(world.angularVelocity(incline.body));
        }
    }
    QVERIFY(paths[0] == paths[1]);

    // The combining rule: the larger coefficient times the larger radius.
    QCOMPARE(combineRollingResistance(0.1f, 0.25f, 0.0f, 0.0f), 0.1f * 0.25f);   // a ball on a plain floor
    QCOMPARE(combineRollingResistance(0.0f, 0.25f, 0.2f, 0.0f), 0.2f * 0.25f);   // a plain ball on a carpet
    QCOMPARE(combineRollingResistance(0.3f, 0.0f, 0.3f, 0.0f), 0.0f);            // two flat bodies
    QCOMPARE(rollingRadius(Shape::cylinder(0.3f, 1.0f)), 0.3f);
    QCOMPARE(rollingRadius(Shape::capsule(0.2f, 1.0f)), 0.2f);
    QCOMPARE(rollingRadius(Shape::box(Vec3(1.0f))), 0.0f);
}

// -------------------------------------------------------------------------------------------------
// 3. Elastic head-on impacts (restitution 1, no gravity, no friction).

void TestContacts::elasticSpheresHeadOn_data() {
    QTest::addColumn<float>("m1");
    QTest::addColumn<float>("m2");
    QTest::addColumn<float>("u1");
    QTest::addColumn<float>("u2");
    QTest::addColumn<float>("tolerance");  // relative to the approach speed
    // Equal masses swap velocities. 2 %: the restitution pass restores e * (approach velocity
    // measured when the step began); both spheres fly freely, so that is the impact velocity up to
    // the soft contact's push, which the relax passes remove.
    QTest::newRow("equal masses swap") << 1.0f << 1.0f << 3.0f << 0.0f << 0.02f;
    QTest::newRow("equal masses, both moving") << 2.0f << 2.0f << 2.0f << -1.5f << 0.02f;
    // 1 and 3 kg: v1' = ((m1 - m2) u1 + 2 m2 u2) / (m1 + m2) = -3, v2' = ((m2 - m1) u2 + 2 m1 u1) / (m1 + m2) = 1.
    QTest::newRow("1 kg and 3 kg") << 1.0f << 3.0f << 3.0f << -1.0f << 0.03f;
}

void TestContacts::elasticSpheresHeadOn() {
    QFETCH(float, m1);
    QFETCH(float, m2);
    QFETCH(float, u1);
    QFETCH(float, u2);
    QFETCH(float, tolerance);

    WorldSettings settings = awakeSettings();
    settings.gravity = Vec3(0.0f);
    World world(settings);
    auto sphere = [&](float x, float mass, float u) {
        BodyCreationSettings b;
        b.name = "sphere";
        b.shape = Shape::sphere(0.5f);
        b.position = Vec3(x, 0.0f, 0.0f);
        b.mass = mass;
        b.linearVelocity = Vec3(u, 0.0f, 0.0f);
        b.friction = 0.0f;
        b.restitution = 1.0f;
        return world.createBody(b);
    };
    const BodyId a = sphere(-2.0f, m1, u1);
    const BodyId b = sphere(2.0f, m2, u2);
    const Vec3 p0 = world.linearMomentum();
    const double e0 = world.kineticEnergy();

    run(world, 3.0f);  // they meet within 1 s and are apart for good after

    const float approach = u1 - u2;
    const float v1 = ((m1 - m2) * u1 + 2.0f * m2 * u2) / (m1 + m2);
    const float v2 = ((m2 - m1) * u2 + 2.0f * m1 * u1) / (m1 + m2);
    const Vec3 w1 = world.linearVelocity(a), w2 = world.linearVelocity(b);
    qInfo("v1 = %.4f (expected %.4f), v2 = %.4f (expected %.4f), kinetic energy %.4f -> %.4f J", w1.x, v1, w2.x, v2,
          e0, world.kineticEnergy());
    QVERIFY2(std::abs(w1.x - v1) < tolerance * approach && std::abs(w2.x - v2) < tolerance * approach,
             qPrintable(QString("v1 = %1 (expected %2), v2 = %3 (expected %4)").arg(w1.x).arg(v1).arg(w2.x).arg(v2)));
    // Head-on through the centres: nothing off the line of impact, no spin.
    QVERIFY(glm::length(Vec3(0.0f, w1.y, w1.z)) < 1e-4f && glm::length(Vec3(0.0f, w2.y, w2.z)) < 1e-4f);
    // Momentum: impulses are equal and opposite by construction; only float rounding remains.
    const Vec3 p = world.linearMomentum();
    QVERIFY2(glm::length(p - p0) < 1e-4f * std::max(glm::length(p0), m1 * std::abs(u1)),
             qPrintable(QString("momentum %1 -> %2").arg(vecString(p0), vecString(p))));
    // Energy: 2 % (from the same sources as the velocity bound; a 1 % velocity error is 2 % energy).
    const double e = world.kineticEnergy();
    QVERIFY2(std::abs(e - e0) < 0.02 * e0, qPrintable(QString("kinetic energy %1 -> %2 J").arg(e0).arg(e)));
    QVERIFY(world.effectUsage().ran(Effect::Restitution));
}

// -------------------------------------------------------------------------------------------------
// 4. Inelastic impacts.

void TestContacts::boxWithoutRestitutionDoesNotBounce() {
    World world(awakeSettings());
    addGround(world);
    const BodyId box = world.createBody(cube(Vec3(0.0f, 1.5f, 0.0f)));  // bottom 1 m up: hits at 4.4 m/s

    float highestAfterImpact = -1.0f;
    bool hit = false;
    for (int i = 0, n = stepsFor(world, 3.0f); i < n; ++i) {
        world.step();
        const float y = world.position(box).y;
        if (!hit && y < 0.5f + 0.02f) hit = true;  // within the speculative margin of the ground
        if (hit) highestAfterImpact = std::max(highestAfterImpact, y);
    }
    QVERIFY(hit);
    qInfo("box rose to %.4f m after impact, rests at %.4f m", highestAfterImpact, world.position(box).y);
    // Restitution 0: the centre never rises more than 1 cm above its resting height (0.5 m).
    QVERIFY2(highestAfterImpact < 0.5f + 0.01f, qPrintable(QString("rose to %1 m").arg(highestAfterImpact)));
    // At rest on its face: speed below the sleep threshold, height 0.5 m to within the soft
    // contact's resting overlap (a few millimetres at most).
    QVERIFY2(glm::length(world.linearVelocity(box)) < 0.01f, qPrintable(vecString(world.linearVelocity(box))));
    QVERIFY2(std::abs(world.position(box).y - 0.5f) < 0.005f, qPrintable(QString("y = %1").arg(world.position(box).y)));
    QVERIFY(!world.effectUsage().ran(Effect::Restitution));
}

void TestContacts::fastImpactIsMetAtTheSurface_data() {
    QTest::addColumn<float>("speed");
    QTest::newRow("10 m/s") << 10.0f;
    QTest::newRow("30 m/s") << 30.0f;  // 0.5 m a step: half the cube's size
}

// A cube thrown at the ground covers speed / 60 metres a step. The speculative margin grows with
// the approach speed, so the contact is solved the step before it touches: the cube stops at the
// surface instead of being found deep inside it a step later and pushed out (which adds energy).
void TestContacts::fastImpactIsMetAtTheSurface() {
    QFETCH(float, speed);
    World world(awakeSettings());
    addGround(world);
    BodyCreationSettings thrown = cube(Vec3(0.0f, 3.0f, 0.0f));
    thrown.linearVelocity = Vec3(0.0f, -speed, 0.0f);
    const BodyId box = world.createBody(thrown);

    float deepest = 0.0f, lowest = 10.0f;
    for (int i = 0, n = stepsFor(world, 2.0f); i < n; ++i) {
        world.step();
        deepest = std::max(deepest, world.lastStepProfile().maxPenetration);
        lowest = std::min(lowest, world.position(box).y);
    }
    qInfo("%.0f m/s: deepest contact %.4f m, lowest centre %.4f m", speed, deepest, lowest);
    // 1 cm: the soft contact's give under the stopping impulse, against up to speed / 60 (17-50 cm)
    // with a fixed 2 cm margin.
    QVERIFY2(deepest < 0.01f, qPrintable(QString("penetrated %1 m").arg(deepest)));
    QVERIFY2(lowest > 0.5f - 0.01f, qPrintable(QString("centre reached %1 m").arg(lowest)));
    QVERIFY2(std::abs(world.position(box).y - 0.5f) < 0.005f, qPrintable(QString("rests at %1 m").arg(world.position(box).y)));
}

// A capsule (a ragdoll's shin: radius 6 cm, segment 30 cm) dropped tilted at 6 m/s and turning at
// up to 25 rad/s: its high end swings down by up to 9 cm a step. Forty drops, each at its own tilt
// and spin; the deepest overlap any reaches stays under 5 mm (the narrow phase's slop). With the
// low end's point alone, the high end was found 7.9 cm deep (1.3 cm on average over the drops).
void TestContacts::spinningCapsuleLandsWithoutDipping() {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    float deepest = 0.0f;
    for (int drop = 0; drop < 40; ++drop) {
        World world{WorldSettings{}};
        addGround(world);
        BodyCreationSettings shin;
        shin.shape = Shape::capsule(0.06f, 0.15f);
        shin.position = Vec3(0.0f, 0.5f + 0.3f * unit(random), 0.0f);
        shin.orientation = glm::normalize(Quat(1.0f, 0.5f * unit(random), 0.5f * unit(random), 0.5f * unit(random)));
        shin.linearVelocity = Vec3(0.0f, -6.0f, 0.0f);
        shin.angularVelocity = Vec3(25.0f * unit(random), 5.0f * unit(random), 25.0f * unit(random));
        shin.mass = 1.0f;
        world.createBody(shin);
        for (int i = 0; i < 120; ++i) {
            world.step();
            deepest = std::max(deepest, world.lastStepProfile().maxPenetration);
        }
    }
    qInfo("40 spinning capsules: deepest overlap %.4f m", deepest);
    QVERIFY2(deepest < 0.005f, qPrintable(QString("a capsule went %1 m into the ground").arg(deepest)));
}

void TestContacts::ballReboundsToQuarterHeight() {
    World world(awakeSettings());
    addGround(world, 0.6f, 0.0f);  // restitution combines by max: the ball's 0.5 counts
    BodyCreationSettings ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(0.5f);
    ball.position = Vec3(0.0f, 1.5f, 0.0f);  // lowest point 1 m above the ground
    ball.mass = 1.0f;
    ball.restitution = 0.5f;
    const BodyId id = world.createBody(ball);

    // Impact at sqrt(2 g h) = 4.43 m/s, rebound at 2.21 m/s, apex e^2 h = 0.25 m above contact.
    bool bounced = false;
    float apex = 0.0f;
    for (int i = 0, n = stepsFor(world, 1.2f); i < n; ++i) {
        world.step();
        const float vy = world.linearVelocity(id).y;
        if (vy > 0.0f) bounced = true;
        if (bounced) apex = std::max(apex, world.position(id).y - 0.5f);
    }
    QVERIFY(bounced);
    qInfo("ball apex %.4f m above rest (expected 0.25 m)", apex);
    // The impact reverses the ball up to one substep of travel before the surfaces meet (v h =
    // 1.8 cm at 4.43 m/s); what e < 1 takes out is then taken that high, so the apex is high by up
    // to (1 - e^2) v h = 1.4 cm, and the step samples it within 1/2 g dt^2 = 1.4 mm. A missing
    // threshold or a bounce of e = 1 would give 1 m, e^2 vs e confusion 0.5 m.
    const float bound = (1.0f - 0.25f) * std::sqrt(2.0f * kG * 1.0f) / 240.0f + 0.5f * kG / (60.0f * 60.0f);
    QVERIFY2(std::abs(apex - 0.25f) < bound, qPrintable(QString("apex %1 m, expected 0.25 m within %2").arg(apex).arg(bound)));
    QVERIFY(world.effectUsage().ran(Effect::Restitution));
}

// The symplectic-Euler invariant of a body in uniform gravity: with the velocity taken half a substep
// h before the position, 1/2 m v^2 + 1/2 w.I w - m g.x + 1/2 h m g.v is exactly constant in free
// flight (plain kinetic plus potential energy swings by 1/2 h m g v, 0.4 % of a 5 m drop), so it
// shows what an impact adds or takes.
double flightInvariant(const World& world, BodyId id) {
    const Vec3 g = world.settings().gravity;
    const float h = world.settings().timeStep / static_cast<float>(world.settings().substeps);
    const double m = world.mass(id);
    return totalEnergy(world) + 0.5 * h * m * glm::dot(g, world.linearVelocity(id));
}

// A ball with restitution 1 dropped 5 m onto a plane comes back to 5 m, bounce after bounce. The
// impact reverses the velocity the ball has at the instant of the positions, which symplectic
// Euler holds half a substep of gravity away from the stored one; reversing the stored one took
// g h |v| out of each bounce (v h = 4.1 cm a bounce at 4 substeps, 8 % over ten). 0.5 %: the
// apex is sampled once a step (1/2 g dt^2 = 1.4 mm, 0.03 %) and the reversal comes up to a
// substep early, which restitution 1 forgives.
void TestContacts::elasticBallReturnsToItsHeight_data() {
    QTest::addColumn<int>("substeps");
    for (int substeps : {1, 2, 4, 8}) QTest::addRow("%d substeps", substeps) << substeps;
}

void TestContacts::elasticBallReturnsToItsHeight() {
    QFETCH(int, substeps);
    WorldSettings settings = awakeSettings();
    settings.substeps = substeps;
    World world(settings);
    addGround(world, 0.6f, 1.0f);
    constexpr float kDrop = 5.0f;
    BodyCreationSettings ball;
    ball.shape = Shape::sphere(0.5f);
    ball.position = Vec3(0.0f, kDrop + 0.5f, 0.0f);
    ball.mass = 1.0f;
    ball.restitution = 1.0f;
    const BodyId id = world.createBody(ball);
    int bounces = 0;
    float worst = 0.0f, previousVy = 0.0f;
    for (int i = 0, n = stepsFor(world, 30.0f); i < n && bounces < 10; ++i) {
        world.step();
        const float vy = world.linearVelocity(id).y;
        if (previousVy > 0.0f && vy <= 0.0f) {
            ++bounces;
            worst = std::max(worst, std::abs(world.position(id).y - 0.5f - kDrop) / kDrop);
        }
        previousVy = vy;
    }
    qInfo("%d bounces, apex at worst %.4f %% from %.0f m", bounces, 100.0 * worst, double(kDrop));
    QCOMPARE(bounces, 10);
    QVERIFY2(worst < 0.005f, qPrintable(QString("apex %1 % off").arg(100.0f * worst)));
}

// A cube dropped flat from 40 m with restitution 1 bounces as a whole: its four corners meet the
// floor together, and their impacts are one impact at their centre. Solved corner by corner, they
// set it spinning and it came back to 6 m. 95 %: the bound; measured 99.99 %.
void TestContacts::boxLandingFlatBouncesAsAWhole() {
    World world(awakeSettings());
    addGround(world, 0.6f, 1.0f);
    constexpr float kDrop = 40.0f;
    BodyCreationSettings box = cube(Vec3(0.0f, kDrop + 0.5f, 0.0f));
    box.restitution = 1.0f;
    const BodyId id = world.createBody(box);
    bool bounced = false;
    float apex = 0.0f, fastestSpin = 0.0f;
    for (int i = 0, n = stepsFor(world, 7.0f); i < n; ++i) {
        world.step();
        fastestSpin = std::max(fastestSpin, glm::length(world.angularVelocity(id)));
        if (world.linearVelocity(id).y > 0.0f) bounced = true;
        if (bounced) apex = std::max(apex, world.position(id).y - 0.5f);
    }
    qInfo("apex %.3f m of %.0f m, fastest spin %.4f rad/s", apex, double(kDrop), fastestSpin);
    QVERIFY(bounced);
    QVERIFY2(apex >= 0.95f * kDrop, qPrintable(QString("came back to %1 m").arg(apex)));
    QVERIFY2(fastestSpin < 0.1f, qPrintable(QString("spun at %1 rad/s").arg(fastestSpin)));
}

// A bar 2 m long and 10 cm thick, tilted 45 degrees in the xy plane, falls edge first at 5 m/s
// onto a frictionless floor. Shape and motion are mirror-symmetric about z = 0, so the motion stays
// in that plane: no turn about x or y, ever. The two points of the edge's manifold, at z = +-5 cm,
// must share the impact equally; solved once each, one after the other, the first took nearly all
// of it and, through the bar's small inertia about its long axis, rolled the bar (27 rad/s, a
// quarter turn, then a spin about y that never ended), which the solver's repeated sweeps of a
// manifold's normal rows prevent. Bound 0.05 rad/s, float rounding's scale.
void TestContacts::symmetricImpactStaysInItsPlane() {
    World world(awakeSettings());
    addGround(world, 0.0f);
    BodyCreationSettings bar;
    bar.shape = Shape::box(Vec3(1.0f, 0.05f, 0.05f));
    bar.position = Vec3(0.0f, 3.0f, 0.0f);
    bar.orientation = glm::angleAxis(0.25f * 3.14159265f, Vec3(0.0f, 0.0f, 1.0f));
    bar.linearVelocity = Vec3(0.0f, -5.0f, 0.0f);
    bar.mass = 1.0f;
    bar.friction = 0.0f;
    const BodyId id = world.createBody(bar);
    float offPlane = 0.0f;  // rad/s: the largest turn rate about x or y
    for (int i = 0, n = stepsFor(world, 2.0f); i < n; ++i) {
        world.step();
        const Vec3 w = world.angularVelocity(id);
        offPlane = std::max({offPlane, std::abs(w.x), std::abs(w.y)});
    }
    qInfo("fastest turn out of the plane %.4f rad/s", offPlane);
    QVERIFY2(offPlane < 0.05f, qPrintable(QString("turned out of its plane at %1 rad/s").arg(offPlane)));
}

// A box dropped tilted with restitution 1 tumbles from bounce to bounce; an impact may pass energy
// between spin and flight, never add it. Impacts take the body's inertia and arms as they are at
// the impact: with those of the step's start, a box spinning at 30 rad/s (half a radian a step)
// gained up to 30 % in 10 s. Bound 0.1 % of the flight invariant; measured at most 0.005 %.
void TestContacts::elasticTumblingBoxGainsNoEnergy_data() {
    QTest::addColumn<float>("angle");
    QTest::addColumn<float>("friction");
    for (float angle : {0.05f, 0.3f, 0.7f, 1.2f, 2.0f})
        for (float friction : {0.0f, 0.5f}) QTest::addRow("%.2f rad, friction %.1f", angle, friction) << angle << friction;
}

void TestContacts::elasticTumblingBoxGainsNoEnergy() {
    QFETCH(float, angle);
    QFETCH(float, friction);
    World world(awakeSettings());
    addGround(world, friction, 1.0f);
    BodyCreationSettings box;
    box.shape = Shape::box(Vec3(0.5f, 0.25f, 0.4f));
    box.position = Vec3(0.0f, 5.0f, 0.0f);
    box.orientation = glm::angleAxis(angle, glm::normalize(Vec3(1.0f, 0.3f, 0.5f)));
    box.mass = 1.0f;
    box.friction = friction;
    box.restitution = 1.0f;
    const BodyId id = world.createBody(box);
    const double start = flightInvariant(world, id);
    double highest = start;
    for (int i = 0, n = stepsFor(world, 10.0f); i < n; ++i) {
        world.step();
        highest = std::max(highest, flightInvariant(world, id));
    }
    QVERIFY(!world.findNonFiniteBody());
    qInfo("energy at most %+.4f %% of the start", 100.0 * (highest - start) / start);
    QVERIFY2(highest <= start * 1.001, qPrintable(QString("gained %1 %").arg(100.0 * (highest - start) / start)));
}

// -------------------------------------------------------------------------------------------------
// 5. The benchmark stacks stand.

void TestContacts::benchStacksStand_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<float>("seconds");
    QTest::addColumn<float>("maxPenetrationBound");
    // Resting overlap of the soft contact under the load of the whole stack: the spring (60 Hz,
    // capped at a quarter of 240 Hz, damping ratio 10) with the tower's 20 kg on the lowest face
    // settles a few millimetres deep. 1 cm is twice the speculative margin and a fifth of the
    // 5 cm drift allowed: a cube sinking that far is a failing contact, not a soft one.
    QTest::newRow("tower20") << "scenes/bench/tower20.json" << 10.0f << 0.01f;
    QTest::newRow("pyramid10") << "scenes/bench/pyramid10.json" << 10.0f << 0.01f;
    // 40 cubes buckle with 60 Hz contacts (a chain of load-independent springs: critical height
    // about 25); the scene asks for 12 substeps and 180 Hz, which holds them for 30 s.
    QTest::newRow("tower40, stiff contacts") << "scenes/tower40.json" << 30.0f << 0.01f;
}

void TestContacts::benchStacksStand() {
    QFETCH(QString, file);
    QFETCH(float, seconds);
    QFETCH(float, maxPenetrationBound);

    const SceneLoadResult loaded = loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/" + file.toStdString());
    QVERIFY(loaded.ok());
    BuiltWorld built = buildWorld(*loaded.scene);
    World& world = built.world;
    std::vector<Vec3> start;
    for (const BodyId id : built.bodyIds) start.push_back(world.position(id));

    // Standing means at every instant, not just at the end: the worst drift over the whole run.
    float worstPenetration = 0.0f;
    float worstDrift = 0.0f;
    float worstDriftTime = 0.0f;
    QString worstBody;
    for (int i = 0, n = stepsFor(world, seconds); i < n; ++i) {
        world.step();
        worstPenetration = std::max(worstPenetration, world.lastStepProfile().maxPenetration);
        for (std::size_t k = 0; k < built.bodyIds.size(); ++k) {
            const float drift = glm::length(world.position(built.bodyIds[k]) - start[k]);
            if (drift > worstDrift) {
                worstDrift = drift;
                worstDriftTime = static_cast<float>(world.simulatedTime());
                worstBody = QString::fromStdString(world.name(built.bodyIds[k]));
            }
        }
    }
    qInfo("%s: worst drift %.4f m (%s at t = %.2f s), max penetration %.4f m", qPrintable(file), worstDrift,
          qPrintable(worstBody), worstDriftTime, worstPenetration);
    QVERIFY(!world.findNonFiniteBody());
    QVERIFY2(worstPenetration < maxPenetrationBound,
             qPrintable(QString("max penetration %1 m").arg(worstPenetration)));
    QVERIFY2(worstDrift < 0.05f, qPrintable(QString("%1 moved %2 m").arg(worstBody).arg(worstDrift)));
}

// -------------------------------------------------------------------------------------------------
// 6. A 100 kg cube on a 1 kg cube.

void TestContacts::heavyOnLightHolds() {
    World world(awakeSettings());
    addGround(world);
    const BodyId light = world.createBody(cube(Vec3(0.0f, 0.5f, 0.0f), 1.0f));
    const BodyId heavy = world.createBody(cube(Vec3(0.0f, 1.5f, 0.0f), 100.0f));
    const Vec3 heavyStart = world.position(heavy);

    float lowestLight = 1.0f;
    float drift = 0.0f;  // worst over the run: holding means at every instant
    float deepest = 0.0f;
    for (int i = 0, n = stepsFor(world, 5.0f); i < n; ++i) {
        world.step();
        lowestLight = std::min(lowestLight, world.position(light).y);
        drift = std::max(drift, glm::length(world.position(heavy) - heavyStart));
        deepest = std::max(deepest, world.lastStepProfile().maxPenetration);
    }
    qInfo("heavy on light: heavy drift %.4f m, light centre down to %.4f m, max penetration %.4f m", drift,
          lowestLight, deepest);
    // 2 cm: both soft contacts carry 100 kg; at 100:1 the sequential solver converges slowly and
    // the light cube is squeezed a few millimetres, never centimetres, unless the stack fails.
    QVERIFY2(drift < 0.02f, qPrintable(QString("heavy cube moved %1 m").arg(drift)));
    // No tunnelling: the light cube's centre (0.5 m at rest) stays above 0.4 m.
    QVERIFY2(lowestLight > 0.4f, qPrintable(QString("light cube's centre went down to %1 m").arg(lowestLight)));
    QVERIFY(world.position(heavy).y > world.position(light).y + 0.9f);
}

// -------------------------------------------------------------------------------------------------
// 7. Sleeping and waking.

void TestContacts::pileSleepsAndWakesWhenHit() {
    World world;  // sleep enabled by default
    QVERIFY(world.settings().sleep.enabled);
    addGround(world);
    // 30 cubes in a loose grid: 3 layers of 5 x 2, 0.2 m gaps, each layer dropped from 0.1 m above
    // where it comes to rest.
    std::vector<BodyId> pile;
    for (int layer = 0; layer < 3; ++layer)
        for (int i = 0; i < 5; ++i)
            for (int k = 0; k < 2; ++k)
                pile.push_back(world.createBody(
                    cube(Vec3(-2.4f + 1.2f * i, 0.6f + 1.1f * layer, -0.6f + 1.2f * k))));
    // A lone cube resting far away: its own island.
    const BodyId far = world.createBody(cube(Vec3(30.0f, 0.5f, 0.0f)));

    int stepsToSleep = -1;
    for (int i = 0, n = stepsFor(world, 5.0f); i < n; ++i) {
        world.step();
        if (world.lastStepProfile().counters.awakeBodies == 0) {
            stepsToSleep = i + 1;
            break;
        }
    }
    QVERIFY2(stepsToSleep > 0, qPrintable(QString("%1 bodies still awake after 5 s")
                                              .arg(world.lastStepProfile().counters.awakeBodies)));
    qInfo("pile of 30 asleep after %.2f s", stepsToSleep * world.settings().timeStep);

    // Throw a ball into the first column of the pile.
    BodyCreationSettings ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(0.3f);
    ball.position = Vec3(-5.0f, 0.5f, -0.6f);
    ball.linearVelocity = Vec3(8.0f, 0.0f, 0.0f);
    ball.mass = 2.0f;
    const BodyId thrown = world.createBody(ball);

    int awakePileBodies = 0;
    for (int i = 0; i < 60 && awakePileBodies == 0; ++i) {
        world.step();
        awakePileBodies = static_cast<int>(
            std::count_if(pile.begin(), pile.end(), [&](BodyId id) { return world.isAwake(id); }));
        QVERIFY2(!world.isAwake(far), "the far cube woke up");
    }
    QVERIFY2(awakePileBodies > 0, "the ball hit the pile without waking it");
    QVERIFY(world.position(thrown).x < -2.4f);  // it hit and did not pass through
    for (int i = 0; i < 60; ++i) {
        world.step();
        QVERIFY2(!world.isAwake(far), "the far cube woke up");
    }
}

// -------------------------------------------------------------------------------------------------
// 8. Effect switches.

void TestContacts::effectSwitches() {
    const float freeSlide = kG * std::sin(kTheta);
    {
        // Friction off: the mu 0.8 box that would stick slides as if frictionless (3 %, as above).
        WorldSettings settings = awakeSettings();
        settings.effects[Effect::Friction] = false;
        World world(settings);
        const Incline incline(world, Shape::box(Vec3(0.25f)), 0.25f, 0.8f);
        const float a = measureSlopeAcceleration(world, incline);
        QVERIFY2(std::abs(a - freeSlide) < 0.03f * freeSlide, qPrintable(QString("a = %1").arg(a)));
        QVERIFY(!world.effectUsage().ran(Effect::Friction));
        QVERIFY(world.effectUsage().ran(Effect::Contacts));
    }
    {
        // Friction on but one side frictionless: sqrt(0.8 * 0) = 0, no friction rows at all.
        WorldSettings settings = awakeSettings();
        World world(settings);
        Incline incline(world, Shape::box(Vec3(0.25f)), 0.25f, 0.0f);
        const float a = measureSlopeAcceleration(world, incline);
        QVERIFY2(std::abs(a - freeSlide) < 0.03f * freeSlide, qPrintable(QString("a = %1").arg(a)));
        QVERIFY(!world.effectUsage().ran(Effect::Friction));
    }
    {
        // The combining rule itself: any frictionless side makes the pair frictionless.
        QCOMPARE(combineFriction(0.8f, 0.0f), 0.0f);
        QVERIFY(std::abs(combineFriction(0.8f, 0.2f) - 0.4f) < 1e-6f);
        QCOMPARE(combineRestitution(0.0f, 0.5f), 0.5f);
    }
    {
        // Contacts off: a box resting on the ground falls through it freely (1/2 g t^2 = 4.9 m in 1 s).
        WorldSettings settings = awakeSettings();
        settings.effects[Effect::Contacts] = false;
        World world(settings);
        addGround(world);
        const BodyId box = world.createBody(cube(Vec3(0.0f, 0.5f, 0.0f)));
        run(world, 1.0f);
        QVERIFY2(world.position(box).y < 0.5f - 4.5f, qPrintable(QString("y = %1").arg(world.position(box).y)));
        QVERIFY(!world.effectUsage().ran(Effect::Contacts));
        QVERIFY(!world.effectUsage().ran(Effect::Friction));
        QVERIFY(world.effectUsage().ran(Effect::Gravity));
    }
}

void TestContacts::restitutionRunsOnlyWhenSomePairBounces() {
    struct Case {
        const char* name;
        float restitution;
        bool effectEnabled;
        bool expectRan;
    };
    const Case cases[] = {
        {"restitution 0", 0.0f, true, false},
        {"restitution 0.5", 0.5f, true, true},
        {"restitution 0.5, effect off", 0.5f, false, false},
    };
    for (const Case& c : cases) {
        WorldSettings settings = awakeSettings();
        settings.effects[Effect::Restitution] = c.effectEnabled;
        World world(settings);
        addGround(world);
        BodyCreationSettings ball;
        ball.shape = Shape::sphere(0.5f);
        ball.position = Vec3(0.0f, 1.5f, 0.0f);
        ball.mass = 1.0f;
        ball.restitution = c.restitution;
        const BodyId id = world.createBody(ball);
        float maxUpward = 0.0f;
        for (int i = 0, n = stepsFor(world, 1.0f); i < n; ++i) {
            world.step();
            maxUpward = std::max(maxUpward, world.linearVelocity(id).y);
        }
        QVERIFY2(world.effectUsage().ran(Effect::Restitution) == c.expectRan, c.name);
        // Without restitution the ball does not leave the ground (upward speed from the soft
        // push-out only, centimetres per second); with it, it rebounds at about 2.2 m/s.
        QVERIFY2((maxUpward > 1.5f) == c.expectRan, qPrintable(QString("%1: upward %2 m/s").arg(c.name).arg(maxUpward)));
    }
}

// -------------------------------------------------------------------------------------------------
// 9. No heap allocation per step once the contact set is steady.

void TestContacts::steadyStateStepDoesNotAllocate() {
    World world(awakeSettings());  // sleep off: every body keeps being stepped
    addGround(world);
    for (int layer = 0; layer < 4; ++layer)
        for (int i = 0; i < 5; ++i)
            for (int k = 0; k < 5; ++k)
                world.createBody(cube(Vec3(-2.4f + 1.2f * i, 0.6f + 1.2f * layer, -2.4f + 1.2f * k)));
    QCOMPARE(world.bodyCount(), std::size_t(101));
    for (int i = 0; i < 120; ++i) world.step();

    test_support::startCountingAllocations();
    for (int i = 0; i < 60; ++i) world.step();
    const std::size_t allocations = test_support::stopCountingAllocations();
    QCOMPARE(world.lastStepProfile().counters.awakeBodies, 100u);
    QVERIFY(world.lastStepProfile().counters.contactPoints > 0);
    QCOMPARE(allocations, std::size_t{0});
}

// -------------------------------------------------------------------------------------------------
// 10. The contact cap: twelve coincident cubes resting on the ground with a cap of 3 contacts
// with other dynamic bodies. Every cube keeps its ground contact; no cube has more than 3 contacts
// with other cubes; the pairs refused are counted in the step that refused them.

void TestContacts::contactCapLimitsPairsBetweenDynamicBodiesOnly() {
    WorldSettings settings = awakeSettings();
    settings.contact.maxContactsPerBody = 3;
    World world(settings);
    const BodyId ground = addGround(world);
    constexpr int kCubes = 12;
    for (int i = 0; i < kCubes; ++i) world.createBody(cube(Vec3(0.0f, 0.5f, 0.0f)));
    world.step();
    QCOMPARE(world.lastStepProfile().counters.droppedPairs, std::uint32_t(kCubes * (kCubes - 1) / 2 - kCubes * 3 / 2));

    std::map<std::uint32_t, int> withCubes;
    int withGround = 0;
    for (std::size_t c = 0; c < world.contactCount(); ++c) {
        const ContactInfo contact = world.contact(c);
        if (contact.bodyA == ground || contact.bodyB == ground) {
            ++withGround;
            continue;
        }
        ++withCubes[contact.bodyA.index];
        ++withCubes[contact.bodyB.index];
    }
    QCOMPARE(withGround, kCubes);
    for (const auto& [slot, count] : withCubes) QVERIFY2(count <= 3, qPrintable(QString("cube %1 has %2").arg(slot).arg(count)));
}

// -------------------------------------------------------------------------------------------------
// 11. A long mixed run.

void TestContacts::longMixedRunStaysFiniteAndDoesNotGainEnergy() {
    World world(awakeSettings());
    addArena(world, 30.0f);

    std::mt19937 rng(20240611u);
    auto uniform = [&rng](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    // 200 bodies on a 6 x 6 grid of 2 m cells, 6 layers from 1 m up: every shape fits in a 1 m
    // cube (half sizes 0.05-0.5 m, a 0.87 m circumradius at most), so nothing starts overlapping.
    int created = 0;
    for (int layer = 0; layer < 6 && created < 200; ++layer) {
        for (int i = 0; i < 6 && created < 200; ++i) {
            for (int k = 0; k < 6 && created < 200; ++k, ++created) {
                BodyCreationSettings b;
                b.name = "body " + std::to_string(created);
                switch (created % 5) {
                    case 0: b.shape = Shape::box(Vec3(uniform(0.05f, 0.5f), uniform(0.05f, 0.5f), uniform(0.05f, 0.5f))); break;
                    case 1: b.shape = Shape::sphere(uniform(0.05f, 0.5f)); break;
                    case 2: {
                        const float radius = uniform(0.05f, 0.25f);
                        b.shape = Shape::capsule(radius, uniform(0.05f, 0.5f - radius));
                        break;
                    }
                    case 3: b.shape = Shape::cylinder(uniform(0.05f, 0.35f), uniform(0.05f, 0.35f)); break;
                    case 4: {
                        const Vec3 size(uniform(0.05f, 0.5f), uniform(0.05f, 0.5f), uniform(0.05f, 0.5f));
                        std::vector<Vec3> points;
                        for (int p = 0; p < 12; ++p)
                            points.push_back(size * Vec3(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f)));
                        ConvexHull::BuildResult hull = ConvexHull::build(points);
                        QVERIFY2(hull.hull, hull.error.c_str());
                        b.shape = Shape::convexHull(hull.hull);
                        break;
                    }
                }
                b.position = Vec3(-5.0f + 2.0f * i, 1.0f + 2.0f * layer, -5.0f + 2.0f * k);
                b.orientation = glm::normalize(Quat(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
                b.linearVelocity = Vec3(uniform(-4, 4), uniform(-4, 4), uniform(-4, 4));
                b.angularVelocity = Vec3(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5));
                b.density = uniform(200.0f, 2000.0f);
                b.friction = uniform(0.0f, 1.0f);
                b.restitution = uniform(0.0f, 0.5f);
                // Every third body resists rolling (C up to 0.12), without drawing from the
                // generator, so the rest of the mix is the one it always was.
                b.rollingResistance = created % 3 == 0 ? 0.02f * static_cast<float>(created % 7) : 0.0f;
                world.createBody(b);
            }
        }
    }

    const double e0 = totalEnergy(world);
    QVERIFY(e0 > 0.0);
    double worstEnergy = e0;
    int worstEnergyStep = 0;
    float lowest = 0.0f;
    std::string lowestName;
    for (int step = 1; step <= 2000; ++step) {
        world.step();
        if (const auto bad = world.findNonFiniteBody())
            QFAIL(qPrintable(QString("step %1: %2 has a non-finite %3")
                                 .arg(step).arg(bad->name.c_str(), bad->quantity.c_str())));
        const double e = totalEnergy(world);
        if (e > worstEnergy) {
            worstEnergy = e;
            worstEnergyStep = step;
        }
        for (const BodyId id : world.bodyIds()) {
            if (world.motionType(id) == MotionType::Dynamic && world.centerOfMass(id).y < lowest) {
                lowest = world.centerOfMass(id).y;
                lowestName = world.name(id);
            }
        }
    }
    qInfo("mixed run: energy %.1f J -> %.1f J, peak %.1f J at step %d, lowest centre %.3f m (%s)", e0,
          totalEnergy(world), worstEnergy, worstEnergyStep, lowest, lowestName.c_str());
    // Nothing tunnels through the 1 m thick ground at these speeds (at most ~15 m/s, 25 cm a step).
    QVERIFY2(lowest > -0.5f, qPrintable(QString("a centre of mass reached y = %1 m").arg(lowest)));
    // Contacts, friction, rolling resistance and restitution <= 1 only take energy out, semi-implicit Euler loses
    // 1/2 m g^2 h t in free flight; 1 % covers the soft contact's push-out of transient overlap.
    QVERIFY2(worstEnergy <= 1.01 * e0,
             qPrintable(QString("energy rose from %1 J to %2 J at step %3").arg(e0).arg(worstEnergy).arg(worstEnergyStep)));
}

QTEST_APPLESS_MAIN(TestContacts)
#include "test_contacts.moc"
