// Over 800 lines because it is the joints' one suite: some thirty closed-form cases, each with the
// reasoning behind its tolerance next to it, which is most of the length.
// Joint physics against closed forms and stability bounds: pendulum periods (ball, hinge and
// distance joints, against the exact large-amplitude period), hinge limits and motors, slider
// limits, a fixed joint's pose, distance limits and spring frequency, a 20-link hinge chain, heavy
// bobs on light chains, islands and sleep through joints, the collision filter, effects, and the
// scene format's joints. Worlds run at the defaults (dt = 1/60 s, 4 substeps of h = 1/240 s, joint
// rows as 60 Hz soft constraints) unless a test says otherwise; every bound below was measured and
// is stated with its margin where it is asserted.

#include "simcore/io/scene_io.h"
#include "simcore/world/world.h"

#include "support/allocation_counter.h"
#include "support/run_program.h"
#include "support/worlds.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace simcore;

namespace {

constexpr float kG = 9.81f;
const Vec3 kAxisZ(0.0f, 0.0f, 1.0f);

WorldSettings awakeSettings() {
    WorldSettings s;
    s.sleep.enabled = false;
    return s;
}

// Stiffer joints: the joint rows' frequency is capped at a quarter of the substep rate, so a
// stiffer joint needs more substeps (4 substeps and 60 Hz are the defaults).
WorldSettings substepSettings(int substeps, float jointHertz) {
    WorldSettings s = awakeSettings();
    s.substeps = substeps;
    s.joint.hertz = jointHertz;
    return s;
}

int stepsFor(const World& world, double seconds) {
    return static_cast<int>(std::lround(seconds / world.settings().timeStep));
}

BodyCreationSettings sphereBody(const Vec3& position, float radius, float mass) {
    BodyCreationSettings b;
    b.name = "sphere";
    b.shape = Shape::sphere(radius);
    b.position = position;
    b.mass = mass;
    return b;
}

BodyCreationSettings boxBody(const Vec3& position, const Vec3& halfExtents, float mass) {
    BodyCreationSettings b;
    b.name = "box";
    b.shape = Shape::box(halfExtents);
    b.position = position;
    b.mass = mass;
    return b;
}

JointCreationSettings jointSettings(JointType type, BodyId a, BodyId b, const Vec3& anchor,
                                    const Vec3& axis = Vec3(0.0f, 0.0f, 1.0f)) {
    JointCreationSettings j;
    j.type = type;
    j.bodyA = a;
    j.bodyB = b;
    j.anchor = anchor;
    j.axis = axis;
    return j;
}

// Mean period of a signal from its upward zero crossings (linear interpolation between steps).
struct PeriodMeter {
    double previousTime = 0.0, previousValue = 0.0;
    std::vector<double> crossings;
    bool started = false;

    void add(double time, double value) {
        if (started && previousValue < 0.0 && value >= 0.0)
            crossings.push_back(previousTime + (time - previousTime) * (-previousValue) / (value - previousValue));
        previousTime = time;
        previousValue = value;
        started = true;
    }
    double period() const {
        return crossings.size() < 2 ? 0.0 : (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    }
};

float worstPositionError(const World& world) { return world.worstJointError().position; }

// Angle of a body about z (rad) from its orientation, for bodies turning about z only.
float angleAboutZ(const Quat& q) { return 2.0f * std::atan2(q.z, q.w); }

}  // namespace

class TestJoints : public QObject {
    Q_OBJECT

private slots:
    void pendulumPeriod_data();
    void pendulumPeriod();
    void hingeLimitHolds();
    void hingeMotorTorqueAndSpeed();
    void hingeMotorHoldsSpeedUnderLoad();
    void sliderLimitsAndLockedRotation();
    void fixedJointKeepsRelativePose_data();
    void fixedJointKeepsRelativePose();
    void distanceJointLimits();
    void distanceSpringFrequency();
    void hingeChain20StaysTogether_data();
    void hingeChain20StaysTogether();
    void heavyBobOnLightChain_data();
    void heavyBobOnLightChain();
    void farAnchorsGainNoEnergy();
    void kinematicSpunHingeDoesNotSpeedUp();
    void embeddedJointedBodiesGainNoEnergy();
    void tornJointsStayFinite_data();
    void tornJointsStayFinite();
    void jointedPairSleepsAndWakesTogether();
    void jointedBodiesDoNotCollide();
    void jointsEffectRunsOnlyWithJoints();
    void createJointRejectsBadSettings();
    void destroyingABodyDestroysItsJoints();
    void noAllocationPerStep();
    void sceneRoundTripWithJoints();
    void malformedJoints_data();
    void malformedJoints();
    void demoScenesInTheRunner_data();
    void demoScenesInTheRunner();
};

// 1. Pendulum period, released from 0.5 rad (29 degrees), where the large-amplitude period is
// 1.6 % longer than the small-angle 2 pi sqrt(L/g): comparing against the exact period
// T0 / agm(1, cos(theta0/2)) checks the joint, not the approximation. A distance joint holds the
// sphere's centre (a point mass, T0 = 2 pi sqrt(L/g)); ball and hinge joints turn the sphere with
// the arm (a physical pendulum, T0 = 2 pi sqrt(I_pivot / (m g L)), I_pivot = m L^2 + 2/5 m r^2).
void TestJoints::pendulumPeriod_data() {
    QTest::addColumn<int>("type");
    QTest::newRow("ball") << int(JointType::Ball);
    QTest::newRow("hinge") << int(JointType::Hinge);
    QTest::newRow("distance") << int(JointType::Distance);
}

void TestJoints::pendulumPeriod() {
    QFETCH(int, type);
    const auto jointType = static_cast<JointType>(type);
    constexpr float kLength = 1.0f, kRadius = 0.05f, kMass = 1.0f;
    constexpr double kTheta0 = 0.5;
    World world(awakeSettings());
    const Vec3 start(kLength * std::sin(float(kTheta0)), -kLength * std::cos(float(kTheta0)), 0.0f);
    const BodyId bob = world.createBody(sphereBody(start, kRadius, kMass));
    JointCreationSettings j = jointSettings(jointType, bob, BodyId{}, Vec3(0.0f));
    if (jointType == JointType::Distance) {
        j.anchor = start;  // the point on the bob
        j.anchorB = Vec3(0.0f);
    }
    world.createJoint(j);

    const double pointT0 = 2.0 * M_PI * std::sqrt(kLength / double(kG));
    const double physicalT0 = pointT0 * std::sqrt(1.0 + 0.4 * double(kRadius * kRadius) / double(kLength * kLength));
    const double expected =
        (jointType == JointType::Distance ? pointT0 : physicalT0) / test_support::agm(1.0, std::cos(kTheta0 / 2.0));

    PeriodMeter meter;
    float maxError = 0.0f;
    for (int i = 0, n = stepsFor(world, 12.0); i < n; ++i) {
        world.step();
        meter.add(world.simulatedTime(), world.centerOfMass(bob).x);
        maxError = std::max(maxError, worstPositionError(world));
    }
    const double period = meter.period();
    const double relativeError = std::abs(period - expected) / expected;
    qInfo("%s: period %.5f s, exact %.5f s, relative error %.2e, worst joint error %.2e m", QTest::currentDataTag(),
          period, expected, relativeError, double(maxError));
    QVERIFY(meter.crossings.size() >= 5);
    // Sources: symplectic Euler's phase error O((omega h)^2) ~ 1e-5, the soft joint's compliance
    // (a 60 Hz spring in series with a 0.5 Hz pendulum) and the crossing interpolation. Measured
    // 3e-5 (ball, hinge) and 6e-5 (distance); asserted at 5e-4, 30x finer than the large-amplitude
    // term.
    QVERIFY2(relativeError < 5e-4, qPrintable(QString("relative period error %1").arg(relativeError)));
    QVERIFY2(maxError < 1e-3f, qPrintable(QString("joint error %1 m").arg(maxError)));
}

// 2. A bar hinged at one end falls from horizontal onto its lower limit (-0.6 rad) and must stay
// within it: the impact at the limit is the hard part, since the bar arrives at 3.5 rad/s.
void TestJoints::hingeLimitHolds() {
    World world(awakeSettings());
    const BodyId bar = world.createBody(boxBody(Vec3(0.5f, 0.0f, 0.0f), Vec3(0.5f, 0.05f, 0.05f), 1.0f));
    JointCreationSettings j = jointSettings(JointType::Hinge, bar, BodyId{}, Vec3(0.0f));
    j.limits = JointLimits{-0.6f, 0.6f};
    const JointId hinge = world.createJoint(j);

    float worstViolation = 0.0f, lowestAngle = 0.0f;
    for (int i = 0, n = stepsFor(world, 4.0); i < n; ++i) {
        world.step();
        worstViolation = std::max(worstViolation, world.jointError(hinge).angle);
        lowestAngle = std::min(lowestAngle, angleAboutZ(world.orientation(bar)));
    }
    const float finalAngle = angleAboutZ(world.orientation(bar));
    qInfo("lowest angle %.4f rad (limit -0.6), worst violation %.2e rad, final angle %.4f rad", double(lowestAngle),
          double(worstViolation), double(finalAngle));
    // The limit is met speculatively (the row closes exactly the remaining gap), so the overshoot
    // is the soft constraint's give under the impact: measured 1.1e-3 rad; asserted at 5e-3 rad.
    QVERIFY2(worstViolation < 5e-3f, qPrintable(QString("violation %1 rad").arg(worstViolation)));
    QVERIFY(lowestAngle > -0.6f - 5e-3f);
    // And the bar does rest on the limit (gravity holds it there).
    QVERIFY2(std::abs(finalAngle + 0.6f) < 5e-3f, qPrintable(QString("final angle %1").arg(finalAngle)));
}

// 3. A motor with a torque limit spins up a free wheel: while it saturates, the angular
// acceleration is maxTorque / I exactly; then it holds the target speed.
void TestJoints::hingeMotorTorqueAndSpeed() {
    WorldSettings settings = awakeSettings();
    settings.gravity = Vec3(0.0f);
    World world(settings);
    BodyCreationSettings wheel;
    wheel.shape = Shape::cylinder(0.5f, 0.1f);
    wheel.mass = 10.0f;  // I about y = m r^2 / 2 = 1.25 kg m^2
    const BodyId body = world.createBody(wheel);
    JointCreationSettings j = jointSettings(JointType::Hinge, body, BodyId{}, Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f));
    j.motor = JointMotor{5.0f, 2.5f};  // 5 rad/s at most 2.5 N m: 2 rad/s^2, reached at 2.5 s
    world.createJoint(j);

    for (int i = 0, n = stepsFor(world, 1.0); i < n; ++i) world.step();
    const float speedAt1s = world.angularVelocity(body).y;
    for (int i = 0, n = stepsFor(world, 3.0); i < n; ++i) world.step();
    const float speedAt4s = world.angularVelocity(body).y;
    qInfo("speed at 1 s %.5f rad/s (expected 2), at 4 s %.5f rad/s (target 5)", double(speedAt1s), double(speedAt4s));
    // The clamp is exact per substep: the only error is float rounding.
    QVERIFY(std::abs(speedAt1s - 2.0f) < 2e-3f);
    QVERIFY(std::abs(speedAt4s - 5.0f) < 1e-3f);
}

// 4. Under a load that varies around the turn (a 2 kg lever 0.5 m out: up to 9.8 N m of gravity
// torque), a motor of 50 N m keeps 1 rad/s.
void TestJoints::hingeMotorHoldsSpeedUnderLoad() {
    World world(awakeSettings());
    const BodyId lever = world.createBody(boxBody(Vec3(0.5f, 0.0f, 0.0f), Vec3(0.5f, 0.05f, 0.05f), 2.0f));
    JointCreationSettings j = jointSettings(JointType::Hinge, lever, BodyId{}, Vec3(0.0f));
    j.motor = JointMotor{1.0f, 50.0f};
    world.createJoint(j);

    for (int i = 0, n = stepsFor(world, 0.5); i < n; ++i) world.step();
    float worstDeviation = 0.0f;
    for (int i = 0, n = stepsFor(world, 8.0); i < n; ++i) {  // more than a full turn
        world.step();
        worstDeviation = std::max(worstDeviation, std::abs(world.angularVelocity(lever).z - 1.0f));
    }
    qInfo("worst speed deviation under load %.2e rad/s (target 1)", double(worstDeviation));
    // The motor row is solved before the point rows, which then pull the lever's velocity a little
    // off; measured below 1e-3; asserted at 1 % of the target.
    QVERIFY2(worstDeviation < 1e-2f, qPrintable(QString("deviation %1").arg(worstDeviation)));
}

// 5. A box on a vertical slider falls onto its lower limit; a sideways push and a spin must not
// move it off the axis or turn it.
void TestJoints::sliderLimitsAndLockedRotation() {
    World world(awakeSettings());
    BodyCreationSettings b = boxBody(Vec3(0.0f), Vec3(0.2f), 1.0f);
    b.linearVelocity = Vec3(2.0f, 0.0f, 1.0f);
    b.angularVelocity = Vec3(3.0f, 5.0f, -2.0f);
    const BodyId box = world.createBody(b);
    JointCreationSettings j = jointSettings(JointType::Slider, box, BodyId{}, Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f));
    j.limits = JointLimits{-1.0f, 0.5f};
    const JointId slider = world.createJoint(j);

    JointError worst;
    for (int i = 0, n = stepsFor(world, 3.0); i < n; ++i) {
        world.step();
        const JointError e = world.jointError(slider);
        worst.position = std::max(worst.position, e.position);
        worst.angle = std::max(worst.angle, e.angle);
    }
    const Vec3 p = world.position(box);
    qInfo("final position (%.5f, %.5f, %.5f), worst error %.2e m / %.2e rad", double(p.x), double(p.y), double(p.z),
          double(worst.position), double(worst.angle));
    QVERIFY2(std::abs(p.y + 1.0f) < 2e-3f, qPrintable(QString("rest height %1 (limit -1)").arg(p.y)));
    // The kick and the landing on the limit: measured 0.35 mm and 1 mrad; asserted at 2 mm, 5 mrad.
    QVERIFY2(worst.position < 2e-3f, qPrintable(QString("position error %1 m").arg(worst.position)));
    QVERIFY2(worst.angle < 5e-3f, qPrintable(QString("angle error %1 rad").arg(worst.angle)));
    QVERIFY(std::abs(p.x) < 1e-3f && std::abs(p.z) < 1e-3f);
    QVERIFY(glm::length(world.angularVelocity(box)) < 1e-3f);
}

// 6. Two boxes welded by a fixed joint swing as one pendulum from a ball joint: the weld keeps
// its pose within 1 mm and 1 mrad with 120 Hz joints (8 substeps); at the defaults the swing's
// load (up to about 3 g on the 3 kg box) stretches the 60 Hz weld a little more.
void TestJoints::fixedJointKeepsRelativePose_data() {
    QTest::addColumn<int>("substeps");
    QTest::addColumn<float>("jointHertz");
    QTest::addColumn<float>("bound");
    QTest::newRow("defaults") << 4 << 60.0f << 2e-3f;      // measured 1.1 mm, 2.0 mrad
    QTest::newRow("8 substeps, 120 Hz") << 8 << 120.0f << 1e-3f;  // measured 0.3 mm, 0.5 mrad
}

void TestJoints::fixedJointKeepsRelativePose() {
    QFETCH(int, substeps);
    QFETCH(float, jointHertz);
    QFETCH(float, bound);
    World world(substepSettings(substeps, jointHertz));
    const BodyId upper = world.createBody(boxBody(Vec3(0.5f, 0.0f, 0.0f), Vec3(0.5f, 0.1f, 0.1f), 2.0f));
    BodyCreationSettings lowerSettings = boxBody(Vec3(1.2f, 0.0f, 0.3f), Vec3(0.2f, 0.2f, 0.3f), 3.0f);
    lowerSettings.orientation = glm::angleAxis(0.4f, glm::normalize(Vec3(1.0f, 1.0f, 0.0f)));
    const BodyId lower = world.createBody(lowerSettings);
    world.createJoint(jointSettings(JointType::Ball, upper, BodyId{}, Vec3(0.0f)));
    const JointId weld = world.createJoint(jointSettings(JointType::Fixed, upper, lower, Vec3(1.0f, 0.0f, 0.0f)));

    JointError worst;
    for (int i = 0, n = stepsFor(world, 6.0); i < n; ++i) {
        world.step();
        const JointError e = world.jointError(weld);
        worst.position = std::max(worst.position, e.position);
        worst.angle = std::max(worst.angle, e.angle);
    }
    qInfo("fixed joint worst error %.2e m, %.2e rad (bounds %.0e m, %.0e rad)", double(worst.position),
          double(worst.angle), double(bound), double(1.5f * bound));
    QVERIFY2(worst.position < bound, qPrintable(QString("position error %1 m").arg(worst.position)));
    QVERIFY2(worst.angle < 1.5f * bound, qPrintable(QString("angle error %1 rad").arg(worst.angle)));
}

// 7. A rope: a distance joint with minLength 0.5 and maxLength 1 is slack in between. The bob,
// released 0.7 m from the pivot, falls freely until the rope is taut, then swings on it.
void TestJoints::distanceJointLimits() {
    World world(awakeSettings());
    const BodyId bob = world.createBody(sphereBody(Vec3(0.7f, 0.0f, 0.0f), 0.05f, 1.0f));
    JointCreationSettings j = jointSettings(JointType::Distance, bob, BodyId{}, Vec3(0.7f, 0.0f, 0.0f));
    j.anchorB = Vec3(0.0f);
    j.minLength = 0.5f;
    j.maxLength = 1.0f;
    world.createJoint(j);

    // Free fall until the rope tightens at y = -sqrt(1 - 0.49) = -0.714 m (t = 0.38 s).
    for (int i = 0, n = stepsFor(world, 0.3); i < n; ++i) world.step();
    const float freeFallY = world.centerOfMass(bob).y;
    const double t = world.simulatedTime();
    QVERIFY2(std::abs(freeFallY + 0.5f * kG * float(t * t)) < 0.01f, qPrintable(QString("y %1").arg(freeFallY)));

    float longest = 0.0f, shortest = 10.0f;
    for (int i = 0, n = stepsFor(world, 5.0); i < n; ++i) {
        world.step();
        const float length = glm::length(world.centerOfMass(bob));
        longest = std::max(longest, length);
        shortest = std::min(shortest, length);
    }
    qInfo("rope length in [%.5f, %.5f] m (limits [0.5, 1])", double(shortest), double(longest));
    // The jerk when the rope tightens is the worst moment: measured 0.4 mm past the limit.
    QVERIFY2(longest < 1.002f, qPrintable(QString("longest %1").arg(longest)));
    QVERIFY(shortest > 0.5f - 0.005f);
}

// 8. A 2 kg mass hanging on an undamped 1.5 Hz spring from its rest length oscillates about the
// static stretch g / omega^2 with period 1 / f: the soft row is the implicit spring k = m omega^2.
void TestJoints::distanceSpringFrequency() {
    World world(awakeSettings());
    constexpr float kHertz = 1.5f;
    const BodyId mass = world.createBody(sphereBody(Vec3(0.0f, -1.0f, 0.0f), 0.1f, 2.0f));
    JointCreationSettings j = jointSettings(JointType::Distance, mass, BodyId{}, Vec3(0.0f, -1.0f, 0.0f));
    j.anchorB = Vec3(0.0f);
    j.spring = JointSpring{kHertz, 0.0f};
    world.createJoint(j);

    const double omega = 2.0 * M_PI * kHertz;
    const double equilibrium = -1.0 - double(kG) / (omega * omega);
    PeriodMeter meter;
    double lowest = 0.0;
    for (int i = 0, n = stepsFor(world, 6.0); i < n; ++i) {
        world.step();
        const double y = world.centerOfMass(mass).y;
        meter.add(world.simulatedTime(), y - equilibrium);
        lowest = std::min(lowest, y);
    }
    const double period = meter.period();
    const double relativeError = std::abs(period * kHertz - 1.0);
    qInfo("spring period %.5f s (expected %.5f), relative error %.2e; lowest %.4f m (undamped: %.4f)", period,
          1.0 / kHertz, relativeError, lowest, -1.0 - 2.0 * double(kG) / (omega * omega));
    // Implicit Euler lengthens the period by O((omega h)^2) ~ 1e-3 relative at h = 1/240 s;
    // measured below that, asserted at 3e-3. Its numerical damping shrinks the amplitude.
    QVERIFY2(relativeError < 3e-3, qPrintable(QString("relative error %1").arg(relativeError)));
    QVERIFY(meter.crossings.size() >= 7);
}

// 9. The issue's hard case: a chain of 20 hinged links (5 m, 0.5 kg each) released horizontally
// swings for 10 s; its end whips through at over 10 m/s. With 120 Hz joints (8 substeps, twice
// the default cost) no joint ever opens by 1 cm; at the defaults the stretch is 1.6 cm.
void TestJoints::hingeChain20StaysTogether_data() {
    QTest::addColumn<int>("substeps");
    QTest::addColumn<float>("jointHertz");
    QTest::addColumn<float>("bound");
    QTest::newRow("defaults") << 4 << 60.0f << 0.025f;          // measured 1.6 cm
    QTest::newRow("8 substeps, 120 Hz") << 8 << 120.0f << 0.01f;  // measured 0.64 cm
}

void TestJoints::hingeChain20StaysTogether() {
    QFETCH(int, substeps);
    QFETCH(float, jointHertz);
    QFETCH(float, bound);
    World world(substepSettings(substeps, jointHertz));
    constexpr int kLinks = 20;
    constexpr float kHalfLength = 0.125f;  // 0.25 m links: a 5 m chain
    BodyId previous;
    for (int i = 0; i < kLinks; ++i) {
        const float x0 = 2.0f * kHalfLength * float(i);
        const BodyId link =
            world.createBody(boxBody(Vec3(x0 + kHalfLength, 0.0f, 0.0f), Vec3(kHalfLength, 0.03f, 0.03f), 0.5f));
        world.createJoint(jointSettings(JointType::Hinge, link, previous, Vec3(x0, 0.0f, 0.0f)));
        previous = link;
    }
    float worst = 0.0f;
    for (int i = 0, n = stepsFor(world, 10.0); i < n; ++i) {
        world.step();
        worst = std::max(worst, worstPositionError(world));
    }
    QVERIFY(!world.findNonFiniteBody());
    qInfo("20-link hinge chain: worst joint separation over 10 s %.2e m (bound %.2e)", double(worst), double(bound));
    QVERIFY2(worst < bound, qPrintable(QString("worst separation %1 m").arg(worst)));
}

// 10. A heavy bob on a chain of ten light links (ball joints), released at 45 degrees. A soft
// joint is a spring for the mass its row moves, here the light link's (about 0.025 kg with its
// rotation), so the bob's weight stretches it by (M / m) g / omega^2: the stretch grows with the
// mass ratio and falls with the square of the joint frequency, which more substeps allow (more
// iterations do not help: measured). At the defaults 1000:1 tears the chain (the links are
// thrown about by metres); it needs 16 substeps and 240 Hz joints (4x the default cost).
void TestJoints::heavyBobOnLightChain_data() {
    QTest::addColumn<float>("ratio");
    QTest::addColumn<int>("substeps");
    QTest::addColumn<float>("jointHertz");
    QTest::addColumn<float>("bound");
    QTest::newRow("100:1 defaults") << 100.0f << 4 << 60.0f << 0.04f;               // measured 2.7 cm
    QTest::newRow("100:1, 8 substeps, 120 Hz") << 100.0f << 8 << 120.0f << 0.01f;   // measured 0.7 cm
    QTest::newRow("1000:1, 16 substeps, 240 Hz") << 1000.0f << 16 << 240.0f << 0.03f;  // measured 1.9 cm
    QTest::newRow("1000:1, 32 substeps, 480 Hz") << 1000.0f << 32 << 480.0f << 0.01f;  // measured 0.5 cm
}

void TestJoints::heavyBobOnLightChain() {
    QFETCH(float, ratio);
    QFETCH(int, substeps);
    QFETCH(float, jointHertz);
    QFETCH(float, bound);
    World world(substepSettings(substeps, jointHertz));
    constexpr int kLinks = 10;
    constexpr float kLinkLength = 0.2f, kLinkMass = 0.1f;
    // The chain starts straight at 45 degrees from the vertical.
    const Vec3 direction = glm::normalize(Vec3(1.0f, -1.0f, 0.0f));
    const Quat linkRotation = glm::angleAxis(-0.25f * kPi, kAxisZ);  // the box's x along the chain
    BodyId previous;
    for (int i = 0; i <= kLinks; ++i) {
        const Vec3 start = (kLinkLength * float(i)) * direction;
        const bool isBob = i == kLinks;
        BodyCreationSettings b = isBob ? sphereBody(start + 0.2f * direction, 0.2f, kLinkMass * ratio)
                                       : boxBody(start + 0.5f * kLinkLength * direction,
                                                 Vec3(0.5f * kLinkLength, 0.02f, 0.02f), kLinkMass);
        b.orientation = linkRotation;
        const BodyId body = world.createBody(b);
        world.createJoint(jointSettings(JointType::Ball, body, previous, start));
        previous = body;
    }
    float worst = 0.0f;
    for (int i = 0, n = stepsFor(world, 5.0); i < n; ++i) {
        world.step();
        worst = std::max(worst, worstPositionError(world));
    }
    QVERIFY(!world.findNonFiniteBody());
    qInfo("mass ratio %.0f:1, %d substeps: worst joint separation %.2e m (bound %.2e)", double(ratio), substeps,
          double(worst), double(bound));
    QVERIFY2(worst < bound, qPrintable(QString("worst separation %1 m").arg(worst)));
}

// 10b. Anchors metres from the bodies' centres, where the lever arms, not the masses, set what a
// joint moves. An isolated assembly with no gravity and no contact: a heavy flywheel (1e6 kg, as
// good as kinematic) spinning at 1 rad/s, a 16 kg capsule hinged to it 5.7 m from the capsule's
// centre, and a 340 kg capsule fixed to that one by another anchor 5.7 m away, the scene
// tests/data/nonfinite/kinematic_spun_hinge.json with the flywheel made dynamic. Its energy can
// only fall (the soft joints are damped). When the joint's rotation and anchor rows were soft
// springs each scaled to its own rows' mass, the joints stretched by metres and pumped energy in
// until the bodies flew apart, 900 steps in (speeds of 1e5 m/s). Measured now: +0.4 % over 5000
// steps (from the warm-started, unconverged Gauss-Seidel between the two joints that share the
// light capsule: 8 velocity iterations or 16 substeps remove it), joints within 1 cm.
void TestJoints::farAnchorsGainNoEnergy() {
    WorldSettings settings = awakeSettings();
    settings.gravity = Vec3(0.0f);
    settings.effects[Effect::Contacts] = false;
    World world(settings);
    BodyCreationSettings flywheel = boxBody(Vec3(0.0f), Vec3(0.3f), 1e6f);
    flywheel.angularVelocity = Vec3(0.0f, 1.0f, 0.0f);
    BodyCreationSettings light;
    light.shape = Shape::capsule(0.25f, 0.6f);
    light.mass = 16.0f;
    BodyCreationSettings heavy;
    heavy.shape = Shape::capsule(0.25f, 0.7f);  // 340 kg at the default density
    const BodyId a = world.createBody(light);
    const BodyId k = world.createBody(flywheel);
    const BodyId b = world.createBody(heavy);
    world.createJoint(jointSettings(JointType::Hinge, a, k, Vec3(0.0f, 4.0f, -4.0f), Vec3(0.0f, 1.0f, 0.0f)));
    world.createJoint(jointSettings(JointType::Fixed, a, b, Vec3(1.0f, 4.0f, -4.0f)));

    const double initialEnergy = world.kineticEnergy();
    double highestEnergy = initialEnergy;
    float worstStretch = 0.0f;
    for (int i = 0; i < 5000; ++i) {
        world.step();
        highestEnergy = std::max(highestEnergy, world.kineticEnergy());
        worstStretch = std::max(worstStretch, worstPositionError(world));
    }
    QVERIFY(!world.findNonFiniteBody());
    const double gain = highestEnergy / initialEnergy - 1.0;
    qInfo("far anchors, isolated: energy gain %.2e (bound 1e-2), worst stretch %.2e m (bound 0.05)", gain,
          double(worstStretch));
    QVERIFY2(gain < 1e-2, qPrintable(QString("energy gained %1").arg(gain)));
    QVERIFY2(worstStretch < 0.05f, qPrintable(QString("joint stretched %1 m").arg(worstStretch)));
}

// 10c. The two scenes of tests/data/nonfinite/ that once overflowed through joints with far
// anchors gain no energy. kinematic_spun_hinge, 20000 steps (5.6 min): the hinge's anchor circles
// at 4 m/s on the kinematic box, and the capsules' centre lies 4 m across from it; in the box's
// turning frame the pair swings about the anchor with no more energy than it started with, at most
// about 2 rad/s relative to the box, so no point of it passes 4 + 3 x 4 = 16 m/s: bound 20 m/s
// (measured 16.7 m/s). The kinematic box drives it, so its energy is not conserved; speed is the
// measure. Before, it flew apart at the speed bound (1e5 m/s) by step 300.
void TestJoints::kinematicSpunHingeDoesNotSpeedUp() {
    const auto loaded = loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/tests/data/nonfinite/kinematic_spun_hinge.json");
    QVERIFY(loaded.ok());
    BuiltWorld built = buildWorld(*loaded.scene);
    World& world = built.world;
    float fastest = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        world.step();
        for (const BodyId id : world.bodyIds()) fastest = std::max(fastest, glm::length(world.linearVelocity(id)));
    }
    QVERIFY(!world.findNonFiniteBody());
    qInfo("kinematic_spun_hinge: fastest %.1f m/s (bound 20)", double(fastest));
    QVERIFY2(fastest < 20.0f, qPrintable(QString("%1 m/s").arg(fastest)));
}

// joint_far_anchors, 1500 steps: a capsule that starts inside the ground is pushed out through its
// underside, and the free slider lets it fall for ever; a heavy box fixed to a light hull 7 m away
// lands on one corner, which flings the hull at 31 m/s by the lever (the impact takes 7 kJ out).
// Closed but for the push out of the ground, which is over within the first 10 steps, so the
// mechanical energy (kinetic plus m g y) never rises above its highest in those steps. Before the
// velocity bound and the dropped overflowing passes, it flew apart at 1e5 m/s by step 100; later
// its slide reaches kilometres, a lever arm float cannot hold (see tests/data/nonfinite/README.md).
void TestJoints::embeddedJointedBodiesGainNoEnergy() {
    const auto loaded = loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/tests/data/nonfinite/joint_far_anchors.json");
    QVERIFY(loaded.ok());
    BuiltWorld built = buildWorld(*loaded.scene);
    World& world = built.world;
    const Vec3 gravity = world.settings().gravity;
    auto mechanicalEnergy = [&] {
        double energy = world.kineticEnergy();
        for (const BodyId id : world.bodyIds()) energy -= world.mass(id) * glm::dot(gravity, world.centerOfMass(id));
        return energy;
    };
    constexpr int kPushSteps = 10;
    double afterPush = -1e300, highest = -1e300;
    for (int i = 0; i < 1500; ++i) {
        world.step();
        QVERIFY(!world.findNonFiniteBody());
        double& slot = i < kPushSteps ? afterPush : highest;
        slot = std::max(slot, mechanicalEnergy());
    }
    qInfo("joint_far_anchors: energy at most %.1f J after the push, %.1f J during it", highest, afterPush);
    QVERIFY2(highest <= afterPush, qPrintable(QString("gained %1 J").arg(highest - afterPush)));
}

// 10d. Joints torn kilometres apart stay finite. The editor soak's case: an 18 kg box on a slider
// to the ground holds a 1400 kg ball by a ball joint whose anchor is 8 m from the box's centre, so
// the joint moves the light box's small inertia through a long lever; dragged by the ball it tore,
// and with lever arms of 600 m and more its 3x3 mass matrix lost its small eigenvalue to float
// (condition beyond 1e7): the inverse was garbage, impulses of 1e16 and then NaN. Here the ball is
// put a distance away from its joint and the assembly falls for 2000 steps. Whatever the joints do
// with such a pose (they fling the bodies at the bound: a torn joint is not a state a sequential
// solver recovers from), every body must stay finite and within the velocity bound (1e5 m/s, a
// quarter turn per substep) after every step, and the step must count the velocities it cut. Before
// the bound was also applied before velocity updates and after steps with joints, and an
// overflowing joint pass dropped, 7 of the 12 rows ended steps beyond it (the way the soak's world
// reached NaN).
void TestJoints::tornJointsStayFinite_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<float>("tear");
    for (const JointType type : {JointType::Ball, JointType::Hinge, JointType::Fixed, JointType::Slider})
        for (const float tear : {1e3f, 1e4f, 1e5f})
            QTest::addRow("%s, %.0e m", std::string(jointTypeName(type)).c_str(), double(tear)) << int(type) << tear;
}

void TestJoints::tornJointsStayFinite() {
    QFETCH(int, type);
    QFETCH(float, tear);
    World world(awakeSettings());
    BodyCreationSettings ground = boxBody(Vec3(0.0f, -0.5f, 0.0f), Vec3(30.0f, 0.5f, 30.0f), 1.0f);
    ground.motion = MotionType::Static;
    const BodyId groundId = world.createBody(ground);
    const BodyId box = world.createBody(boxBody(Vec3(-1.9f, 4.0f, -2.5f), Vec3(0.36f, 0.25f, 0.063f), 18.0f));
    const BodyId ball = world.createBody(sphereBody(Vec3(2.3f, 3.0f, -6.1f), 0.61f, 1400.0f));
    world.createJoint(jointSettings(JointType::Slider, groundId, box, Vec3(-0.2f, 6.0f, -0.6f), glm::normalize(Vec3(-0.8f, -0.5f, 0.34f))));
    world.createJoint(jointSettings(static_cast<JointType>(type), ball, box, Vec3(2.2f, 12.0f, 4.6f)));
    world.setTransform(ball, world.position(ball) + tear * glm::normalize(Vec3(0.1f, -1.0f, 0.3f)), world.orientation(ball));

    float fastest = 0.0f, fastestTurn = 0.0f;
    std::uint64_t bounded = 0;
    for (int i = 0; i < 2000; ++i) {
        world.step();
        bounded += world.lastStepProfile().counters.boundedVelocities;
        for (const BodyId id : {box, ball}) fastestTurn = std::max(fastestTurn, glm::length(world.angularVelocity(id)));
        const auto bad = world.findNonFiniteBody();
        QVERIFY2(!bad, qPrintable(QString("non-finite %1 of %2 at step %3").arg(QString::fromStdString(bad ? bad->quantity : ""),
                                                                               QString::fromStdString(bad ? bad->name : "")).arg(i)));
        for (const BodyId id : {box, ball}) fastest = std::max(fastest, glm::length(world.linearVelocity(id)));
    }
    qInfo("fastest %.3g m/s (bound 1e5), %llu velocities cut to the bound", double(fastest), static_cast<unsigned long long>(bounded));
    const float substep = world.settings().timeStep / static_cast<float>(world.settings().substeps);
    const float turnBound = 0.25f * kPi / substep;
    QVERIFY(fastest <= 1e5f * (1.0f + 1e-6f));
    QVERIFY2(fastestTurn <= turnBound * (1.0f + 1e-6f), qPrintable(QString("%1 rad/s").arg(fastestTurn)));
    if (fastest > 0.99e5f || fastestTurn > 0.99f * turnBound) QVERIFY2(bounded > 0, "a body at the bound was not counted");
}

// 11. Two boxes resting apart on the ground, joined by a distance joint, are one island: they fall
// asleep in the same step, and waking one wakes the other.
void TestJoints::jointedPairSleepsAndWakesTogether() {
    World world;
    BodyCreationSettings ground = boxBody(Vec3(0.0f, -0.5f, 0.0f), Vec3(20.0f, 0.5f, 20.0f), 1.0f);
    ground.motion = MotionType::Static;
    world.createBody(ground);
    const BodyId a = world.createBody(boxBody(Vec3(-1.0f, 0.5f, 0.0f), Vec3(0.5f), 1.0f));
    BodyCreationSettings later = boxBody(Vec3(1.0f, 0.5f, 0.0f), Vec3(0.5f), 1.0f);
    later.linearVelocity = Vec3(0.0f, 0.0f, 0.5f);  // slides a little: it stays awake longer than a
    const BodyId b = world.createBody(later);
    JointCreationSettings j = jointSettings(JointType::Distance, a, b, Vec3(-1.0f, 0.5f, 0.0f));
    j.anchorB = Vec3(1.0f, 0.5f, 0.0f);
    j.minLength = 0.0f;
    j.maxLength = 5.0f;  // slack: the joint does not pull, it only connects
    world.createJoint(j);

    int stepAsleepA = -1, stepAsleepB = -1;
    for (int i = 0; i < stepsFor(world, 5.0) && (stepAsleepA < 0 || stepAsleepB < 0); ++i) {
        world.step();
        if (stepAsleepA < 0 && !world.isAwake(a)) stepAsleepA = i;
        if (stepAsleepB < 0 && !world.isAwake(b)) stepAsleepB = i;
    }
    QVERIFY(stepAsleepA >= 0);
    QCOMPARE(stepAsleepA, stepAsleepB);
    world.step();
    QCOMPARE(world.lastStepProfile().counters.islands, 0u);

    world.setLinearVelocity(b, Vec3(0.0f, 0.0f, 0.3f));
    QVERIFY(!world.isAwake(a));
    world.step();
    QVERIFY(world.isAwake(a));
    QVERIFY(world.isAwake(b));
    QCOMPARE(world.lastStepProfile().counters.islands, 1u);
}

// 12. Jointed bodies pass through each other unless collideConnected is set.
void TestJoints::jointedBodiesDoNotCollide() {
    for (const bool collide : {false, true}) {
        WorldSettings settings = awakeSettings();
        settings.gravity = Vec3(0.0f);
        World world(settings);
        const BodyId a = world.createBody(boxBody(Vec3(0.0f), Vec3(0.5f), 1.0f));
        const BodyId b = world.createBody(boxBody(Vec3(0.6f, 0.0f, 0.0f), Vec3(0.5f), 1.0f));  // overlapping
        world.step();  // the pair's contact exists before the joint
        QCOMPARE(world.contactCount(), std::size_t(1));
        JointCreationSettings j = jointSettings(JointType::Ball, a, b, Vec3(0.3f, 0.0f, 0.0f));
        j.collideConnected = collide;
        const JointId joint = world.createJoint(j);
        for (int i = 0; i < 10; ++i) world.step();
        QCOMPARE(world.contactCount(), std::size_t(collide ? 1 : 0));
        world.destroyJoint(joint);
        world.step();
        QCOMPARE(world.contactCount(), std::size_t(1));  // colliding again
    }
}

// 13. The joint stage runs only when there is a joint to solve, and switching it off frees the
// bodies.
void TestJoints::jointsEffectRunsOnlyWithJoints() {
    {
        World world(awakeSettings());
        world.createBody(sphereBody(Vec3(0.0f), 0.1f, 1.0f));
        for (int i = 0; i < 10; ++i) world.step();
        QVERIFY(!world.effectUsage().ran(Effect::Joints));
    }
    for (const bool enabled : {true, false}) {
        WorldSettings settings = awakeSettings();
        settings.effects[Effect::Joints] = enabled;
        World world(settings);
        const BodyId bob = world.createBody(sphereBody(Vec3(0.0f, -1.0f, 0.0f), 0.1f, 1.0f));
        world.createJoint(jointSettings(JointType::Ball, bob, BodyId{}, Vec3(0.0f)));
        for (int i = 0, n = stepsFor(world, 1.0); i < n; ++i) world.step();
        QCOMPARE(world.effectUsage().ran(Effect::Joints), enabled);
        const float y = world.centerOfMass(bob).y;
        if (enabled) QVERIFY(std::abs(y + 1.0f) < 1e-3f);
        else QVERIFY(y < -5.0f);  // fell freely, about 4.9 m in 1 s
    }
}

// 14. Bad settings throw, naming the field.
void TestJoints::createJointRejectsBadSettings() {
    World world;
    const BodyId a = world.createBody(sphereBody(Vec3(0.0f), 0.1f, 1.0f));
    const BodyId b = world.createBody(sphereBody(Vec3(1.0f, 0.0f, 0.0f), 0.1f, 1.0f));
    const BodyId gone = world.createBody(sphereBody(Vec3(2.0f, 0.0f, 0.0f), 0.1f, 1.0f));
    world.destroyBody(gone);

    auto expectError = [&](JointCreationSettings j, const char* field) {
        try {
            world.createJoint(j);
            QFAIL(qPrintable(QString("accepted; expected an error naming %1").arg(field)));
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find(field) != std::string::npos, e.what());
        }
    };
    const JointCreationSettings hinge = jointSettings(JointType::Hinge, a, b, Vec3(0.5f, 0.0f, 0.0f));
    JointCreationSettings j = hinge;
    j.bodyA = gone;
    expectError(j, "bodyA");
    j = hinge;
    j.bodyB = gone;
    expectError(j, "bodyB");
    j = hinge;
    j.bodyB = a;
    expectError(j, "bodyB");
    j = hinge;
    j.anchor.x = NAN;
    expectError(j, "anchor");
    j = hinge;
    j.axis = Vec3(0.0f);
    expectError(j, "axis");
    j = hinge;
    j.limits = JointLimits{0.5f, -0.5f};
    expectError(j, "limits.lower");
    j = hinge;
    j.limits = JointLimits{-4.0f, 0.0f};
    expectError(j, "limits");
    j = hinge;
    j.motor = JointMotor{1.0f, -1.0f};
    expectError(j, "motor.maxForce");
    j = hinge;
    j.spring = JointSpring{};
    expectError(j, "spring");
    j = jointSettings(JointType::Distance, a, b, Vec3(0.0f));
    j.anchorB = Vec3(0.0f);
    expectError(j, "anchorB");
    j.anchorB = Vec3(1.0f, 0.0f, 0.0f);
    j.maxLength = 0.5f;  // below the rest length, which minLength defaults to
    expectError(j, "minLength");
    j.spring = JointSpring{0.0f, 1.0f};
    expectError(j, "spring.hertz");
    QCOMPARE(world.jointCount(), std::size_t(0));
}

// 15. Destroying a body destroys its joints and leaves other joints' handles valid.
void TestJoints::destroyingABodyDestroysItsJoints() {
    World world;
    const BodyId a = world.createBody(sphereBody(Vec3(0.0f), 0.1f, 1.0f));
    const BodyId b = world.createBody(sphereBody(Vec3(1.0f, 0.0f, 0.0f), 0.1f, 1.0f));
    const BodyId c = world.createBody(sphereBody(Vec3(2.0f, 0.0f, 0.0f), 0.1f, 1.0f));
    const JointId ab = world.createJoint(jointSettings(JointType::Ball, a, b, Vec3(0.5f, 0.0f, 0.0f)));
    const JointId bWorld = world.createJoint(jointSettings(JointType::Ball, b, BodyId{}, Vec3(1.0f, 1.0f, 0.0f)));
    const JointId ac = world.createJoint(jointSettings(JointType::Ball, a, c, Vec3(1.0f, 0.0f, 0.0f)));
    world.destroyBody(b);
    QCOMPARE(world.jointCount(), std::size_t(1));
    QVERIFY(!world.contains(ab) && !world.contains(bWorld) && world.contains(ac));
    QVERIFY(world.jointBodyA(ac) == a && world.jointBodyB(ac) == c);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, world.jointError(ab));
    world.step();
}

// 16. Joints add no heap allocation per step once the world is running.
void TestJoints::noAllocationPerStep() {
    // A chain hanging straight down: it moves (gravity against the joints' softness) but its
    // contact pairs do not change, so nothing is created.
    World world(awakeSettings());
    BodyId previous;
    for (int i = 0; i < 8; ++i) {
        const BodyId link =
            world.createBody(boxBody(Vec3(0.0f, -0.25f - 0.5f * float(i), 0.0f), Vec3(0.05f, 0.25f, 0.05f), 1.0f));
        world.createJoint(jointSettings(i % 2 ? JointType::Hinge : JointType::Ball, link, previous,
                                        Vec3(0.0f, -0.5f * float(i), 0.0f)));
        previous = link;
    }
    for (int i = 0; i < 20; ++i) world.step();
    test_support::startCountingAllocations();
    for (int i = 0; i < 100; ++i) world.step();
    QCOMPARE(test_support::stopCountingAllocations(), std::size_t{0});
}

// 17. Every joint type and option survives save -> load bit for bit.
void TestJoints::sceneRoundTripWithJoints() {
    Scene scene;
    scene.settings.joint.hertz = 45.5f;
    scene.settings.joint.dampingRatio = 3.25f;
    for (int i = 0; i < 3; ++i) {
        SceneBody b;
        b.body = boxBody(Vec3(0.1f * float(i), 1.0f / 3.0f, 0.0f), Vec3(0.25f), 1.0f);
        b.body.name = "link " + std::to_string(i);
        scene.bodies.push_back(b);
    }
    auto add = [&](JointType type, std::size_t a, std::optional<std::size_t> b) -> JointCreationSettings& {
        SceneJoint j;
        j.joint.name = std::string(jointTypeName(type));
        j.joint.type = type;
        j.joint.anchor = Vec3(0.1f, 0.7f, -1.0f / 7.0f);
        j.bodyA = a;
        j.bodyB = b;
        scene.joints.push_back(j);
        return scene.joints.back().joint;
    };
    add(JointType::Ball, 0, std::nullopt).collideConnected = true;
    JointCreationSettings& hinge = add(JointType::Hinge, 0, 1);
    hinge.axis = Vec3(0.3f, 0.1f, 1.0f / 3.0f);
    hinge.limits = JointLimits{-1.0f / 3.0f, 2.0f};
    hinge.motor = JointMotor{0.1f, 7.5f};
    JointCreationSettings& slider = add(JointType::Slider, 1, 2);
    slider.axis = Vec3(1.0f, 0.0f, 0.0f);
    slider.limits = JointLimits{-0.25f, 0.75f};
    slider.motor = JointMotor{-0.2f, 100.0f};
    add(JointType::Fixed, 2, 0);
    JointCreationSettings& distance = add(JointType::Distance, 2, std::nullopt);
    distance.anchorB = Vec3(0.0f, 3.0f, 0.0f);
    distance.spring = JointSpring{2.5f, 0.1f};
    distance.minLength = 0.5f;
    distance.maxLength = 4.0f / 3.0f;

    const std::string text = serializeScene(scene);
    const SceneLoadResult loaded = parseScene(text, "joints.json");
    for (const Diagnostic& d : loaded.diagnostics) qWarning("%s", d.toString().c_str());
    QVERIFY(loaded.ok());
    QVERIFY(loaded.diagnostics.empty());
    QCOMPARE(serializeScene(*loaded.scene), text);
    QVERIFY(loaded.scene->settings == scene.settings);
    QCOMPARE(loaded.scene->joints.size(), scene.joints.size());
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const SceneJoint& expected = scene.joints[i];
        const SceneJoint& got = loaded.scene->joints[i];
        QCOMPARE(got.bodyA, expected.bodyA);
        QVERIFY(got.bodyB == expected.bodyB);
        QCOMPARE(got.joint.name, expected.joint.name);
        QVERIFY(got.joint.type == expected.joint.type);
        QVERIFY(got.joint.anchor == expected.joint.anchor);
        QVERIFY(got.joint.limits == expected.joint.limits);
        QVERIFY(got.joint.motor == expected.joint.motor);
        QVERIFY(got.joint.spring == expected.joint.spring);
        QVERIFY(got.joint.minLength == expected.joint.minLength);
        QVERIFY(got.joint.maxLength == expected.joint.maxLength);
        QCOMPARE(got.joint.collideConnected, expected.joint.collideConnected);
        if (got.joint.type == JointType::Hinge || got.joint.type == JointType::Slider)
            QVERIFY(got.joint.axis == expected.joint.axis);
        if (got.joint.type == JointType::Distance) QVERIFY(got.joint.anchorB == expected.joint.anchorB);
    }
    // And the loaded scene builds.
    const BuiltWorld built = buildWorld(*loaded.scene);
    QCOMPARE(built.world.jointCount(), scene.joints.size());
    QVERIFY(built.world.jointBodyB(built.jointIds[0]) == BodyId{});
}

// 18. Malformed joints: each error names the JSON path and the reason.
void TestJoints::malformedJoints_data() {
    QTest::addColumn<QString>("joints");
    QTest::addColumn<QString>("expected");
    auto row = [](const char* name, const char* joints, const char* expected) {
        QTest::newRow(name) << QString(joints) << QString(expected);
    };
    row("unknown body", R"([{"type": "ball", "bodyA": "Crate", "anchor": [0, 0, 0]}])",
        "error at /joints/0/bodyA: no body named \"Crate\"");
    row("ambiguous body", R"([{"type": "ball", "bodyA": "twin", "anchor": [0, 0, 0]}])",
        "error at /joints/0/bodyA: 2 bodies are named \"twin\"");
    row("same body twice", R"([{"type": "ball", "bodyA": "a", "bodyB": "a", "anchor": [0, 0, 0]}])",
        "error at /joints/0/bodyB: bodyB names the same body as bodyA");
    row("missing bodyA", R"([{"type": "ball", "anchor": [0, 0, 0]}])",
        "error at /joints/0/bodyA: required key 'bodyA' is missing");
    row("unknown type", R"([{"type": "rope", "bodyA": "a", "anchor": [0, 0, 0]}])",
        "error at /joints/0/type: unknown joint type 'rope'");
    row("non-finite anchor", R"([{"type": "ball", "bodyA": "a", "anchor": [0, 1e300, 0]}])",
        "error at /joints/0/anchor/1: ");
    row("missing axis", R"([{"type": "hinge", "bodyA": "a", "anchor": [0, 0, 0]}])",
        "error at /joints/0/axis: required key 'axis' is missing");
    row("zero axis", R"([{"type": "slider", "bodyA": "a", "anchor": [0, 0, 0], "axis": [0, 0, 0]}])",
        "error at /joints/0/axis: axis must not be zero");
    row("limits reversed",
        R"([{"type": "hinge", "bodyA": "a", "anchor": [0, 0, 0], "axis": [0, 0, 1], "limits": {"lower": 1, "upper": -1}}])",
        "error at /joints/0/limits: lower (1) exceeds upper (-1)");
    row("hinge limit beyond pi",
        R"([{"type": "hinge", "bodyA": "a", "anchor": [0, 0, 0], "axis": [0, 0, 1], "limits": {"lower": -4, "upper": 1}}])",
        "error at /joints/0/limits/lower: ");
    row("negative motor torque",
        R"([{"type": "hinge", "bodyA": "a", "anchor": [0, 0, 0], "axis": [0, 0, 1], "motor": {"speed": 1, "maxTorque": -1}}])",
        "error at /joints/0/motor/maxTorque: ");
    row("slider motor names force",
        R"([{"type": "slider", "bodyA": "a", "anchor": [0, 0, 0], "axis": [0, 0, 1], "motor": {"speed": 1, "maxTorque": 1}}])",
        "error at /joints/0/motor/maxForce: required key 'maxForce' is missing");
    row("distance without anchorB", R"([{"type": "distance", "bodyA": "a", "anchor": [0, 0, 0]}])",
        "error at /joints/0/anchorB: required key 'anchorB' is missing");
    row("distance min above max",
        R"([{"type": "distance", "bodyA": "a", "anchor": [0, 0, 0], "anchorB": [0, 2, 0], "minLength": 3, "maxLength": 1}])",
        "error at /joints/0/minLength: minLength (3) exceeds maxLength (1)");
    row("zero spring frequency",
        R"([{"type": "distance", "bodyA": "a", "anchor": [0, 0, 0], "anchorB": [0, 2, 0], "spring": {"hertz": 0}}])",
        "error at /joints/0/spring/hertz: ");
    row("joint not an object", R"([3])", "error at /joints/0: expected an object, got a number");
    row("bad joint settings", R"([])", "");  // settings rows below replace this one's scene
}

void TestJoints::malformedJoints() {
    QFETCH(QString, joints);
    QFETCH(QString, expected);
    const QString bodies = R"([{"name": "a", "shape": {"type": "sphere", "radius": 1}},
                               {"name": "twin", "shape": {"type": "sphere", "radius": 1}},
                               {"name": "twin", "shape": {"type": "sphere", "radius": 1}}])";
    QString text = R"({"format": "interplay.scene", "version": 1, "bodies": )" + bodies + R"(, "joints": )" + joints + "}";
    if (expected.isEmpty()) {
        // Settings: joint stiffness must be positive.
        text = R"({"format": "interplay.scene", "version": 1, "settings": {"joint": {"hertz": 0}}, "bodies": []})";
        expected = "error at /settings/joint/hertz: ";
    }
    const SceneLoadResult r = parseScene(text.toStdString(), "scene.json");
    QVERIFY(!r.ok());
    QString all;
    for (const Diagnostic& d : r.diagnostics) all += QString::fromStdString(d.toString()) + "\n";
    QVERIFY2(all.contains(expected), qPrintable(expected + " not in:\n" + all));
}

// 19. The joint demos run in interplay-run, which reports their joint count and errors. Bounds
// are about twice the measured worst over 10 s (what each scene's docstring in generate.py says
// it shows): the chain asks for 8 substeps and 120 Hz joints; the ragdoll's worst is its landing.
void TestJoints::demoScenesInTheRunner_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("joints");
    QTest::addColumn<double>("bound");
    QTest::newRow("chain20") << "chain20" << 20 << 0.01;         // measured 5.7 mm
    QTest::newRow("hinge_door") << "hinge_door" << 1 << 0.002;  // measured 0.7 mm
    QTest::newRow("ragdoll") << "ragdoll" << 9 << 0.03;         // measured 1.1 cm, at the landing
    QTest::newRow("pendulums") << "pendulums" << 5 << 0.002;    // measured 0.6 mm, the rope's jerk
}

void TestJoints::demoScenesInTheRunner() {
    QFETCH(QString, scene);
    QFETCH(int, joints);
    QFETCH(double, bound);
    const test_support::ProgramRun run = test_support::runProgram(
        INTERPLAY_RUN_PATH, {QString(INTERPLAY_SOURCE_DIR) + "/scenes/" + scene + ".json", "--steps", "600"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    const QJsonObject metrics = report["metrics"].toObject();
    QCOMPARE(metrics["jointCount"].toInt(), joints);
    QVERIFY(report["effects"].toObject()["joints"].toBool());
    const double worst = metrics["maxJointError"].toObject()["position"].toDouble();
    const double final = metrics["worstJointError"].toObject()["position"].toDouble();
    qInfo("%s: worst joint error over the run %.2e m, at the end %.2e m", qPrintable(scene), worst, final);
    QVERIFY2(worst < bound, qPrintable(QString("worst joint error %1 m").arg(worst)));
    QVERIFY(final <= worst);
}

QTEST_GUILESS_MAIN(TestJoints)
#include "test_joints.moc"
