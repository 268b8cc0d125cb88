#include "reference_scenes.h"

#include "support/scene_builders.h"
#include "support/worlds.h"  // agm

#include "simcore/world/debug_draw.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

namespace accuracy {

using simcore::BodyCreationSettings;
using simcore::BodyId;
using simcore::Effect;
using simcore::JointCreationSettings;
using simcore::JointType;
using simcore::MotionType;
using simcore::Quat;
using simcore::Shape;
using simcore::Vec3;
using simcore::World;
using simcore::WorldSettings;

void SteppingTimer::step(World& world) {
    if (beforeFirstStep_) std::exchange(beforeFirstStep_, {})(world);
    const auto start = std::chrono::steady_clock::now();
    world.step();
    milliseconds_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

namespace {

constexpr double kG = 9.81;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Steps `world` through `seconds` of simulated time; `afterStep` (the scene's own measuring, not
// timed) sees the world after each step.
template <typename AfterStep>
void stepFor(World& world, double seconds, SteppingTimer& timer, AfterStep afterStep) {
    const int steps = static_cast<int>(std::lround(seconds / static_cast<double>(world.settings().timeStep)));
    for (int i = 0; i < steps; ++i) {
        timer.step(world);
        afterStep();
    }
}
void stepFor(World& world, double seconds, SteppingTimer& timer) {
    stepFor(world, seconds, timer, [] {});
}

Observation observation(const World& world, std::vector<double> values) {
    return {std::move(values), !world.findNonFiniteBody()};
}

// The setups' material: friction 0.5 for the ground and every cube, as the tables state.
constexpr float kFriction = 0.5f;

void addGround(World& world, float halfSize) { scene_builders::addGround(world, kFriction, 0.0f, halfSize); }

BodyCreationSettings unitCube(const Vec3& position, float mass) { return scene_builders::cube(position, mass, 0.5f, kFriction); }

WorldSettings zeroGravity() {
    WorldSettings s;
    s.gravity = Vec3(0.0f);
    return s;
}

// Centres of mass of the given bodies, x y z each, as an observation to compare with a converged run.
Observation centres(const World& world, const std::vector<BodyId>& bodies) {
    std::vector<double> values;
    for (BodyId id : bodies) {
        const Vec3 c = world.centerOfMass(id);
        values.insert(values.end(), {c.x, c.y, c.z});
    }
    return observation(world, std::move(values));
}

// Largest distance (m) of any body's centre from where the converged run has it.
double largestCentreDistance(const Observation& observed, const Observation* converged) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 2 < observed.values.size(); i += 3) {
        const double dx = observed.values[i] - converged->values[i];
        const double dy = observed.values[i + 1] - converged->values[i + 1];
        const double dz = observed.values[i + 2] - converged->values[i + 2];
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return worst;
}

// ---- incline: a static 30° ramp (rising towards +x) with a body touching its top face 8 m up-slope
// (the tests' own incline, tests/support/scene_builders.h)

constexpr float kInclineTheta = scene_builders::Incline::kTheta;
constexpr double kSlideFriction = 0.3;  // below tan 30° = 0.577: slides
constexpr double kRollFriction = 0.5;   // above 2/7 tan 30° = 0.165: rolls without slipping

// Distance (m) the body's centre of mass moved down the slope in `seconds`.
Observation runIncline(const WorldSettings& settings, double seconds, SteppingTimer& timer, const Shape& shape,
                       float offsetAlongNormal, float friction) {
    World world(settings);
    const scene_builders::Incline incline(world, shape, offsetAlongNormal, friction);
    const Vec3 start = world.centerOfMass(incline.body);
    stepFor(world, seconds, timer);
    return observation(world, {glm::dot(world.centerOfMass(incline.body) - start, incline.downSlope), world.simulatedTime()});
}

double relativeDistanceError(const Observation& o, double acceleration) {
    const double t = o.values[1];
    const double exact = 0.5 * acceleration * t * t;
    return std::abs(o.values[0] - exact) / exact;
}

ReferenceScene inclineSlide() {
    ReferenceScene s;
    s.name = "incline-slide";
    s.title = "Box sliding down a 30° incline";
    s.setup = "A 1 m, 1 kg cube released from rest on a static 30° ramp, both at friction 0.3 (below tan 30°, so "
              "it slides).";
    s.metric = "relative error of the distance slid in 2 s, |d − d*| / d*";
    s.errorAxis = "relative error of the distance slid in 2 s";
    s.answer = "d* = ½ g (sin θ − μ cos θ) t² = 4.713 m at t = 2 s";
    s.seconds = 2.0;
    s.quickSeconds = 2.0;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        return runIncline(settings, seconds, timer, Shape::box(Vec3(0.5f)), 0.5f, static_cast<float>(kSlideFriction));
    };
    s.error = [](const Observation& o, const Observation*) {
        const double theta = static_cast<double>(kInclineTheta);
        return relativeDistanceError(o, kG * (std::sin(theta) - kSlideFriction * std::cos(theta)));
    };
    return s;
}

ReferenceScene inclineRoll() {
    ReferenceScene s;
    s.name = "rolling-sphere";
    s.title = "Sphere rolling down a 30° incline";
    s.setup = "A solid sphere (r = 0.5 m, 1 kg) released from rest on a static 30° ramp, both at friction 0.5 "
              "(above 2/7 tan 30°, so it rolls without slipping).";
    s.metric = "relative error of the distance rolled in 2 s, |d − d*| / d*";
    s.errorAxis = "relative error of the distance rolled in 2 s";
    s.answer = "d* = ½ (5/7 g sin θ) t² = 7.007 m at t = 2 s";
    s.seconds = 2.0;
    s.quickSeconds = 2.0;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        return runIncline(settings, seconds, timer, Shape::sphere(0.5f), 0.5f, static_cast<float>(kRollFriction));
    };
    s.error = [](const Observation& o, const Observation*) {
        return relativeDistanceError(o, 5.0 / 7.0 * kG * std::sin(static_cast<double>(kInclineTheta)));
    };
    return s;
}

// ---- pendulum on a hinge

constexpr double kPendulumLength = 1.0, kBobRadius = 0.05, kTheta0 = 0.5;

double exactPendulumPeriod() {
    const double pointT0 = 2.0 * 3.14159265358979323846 * std::sqrt(kPendulumLength / kG);
    const double physicalT0 = pointT0 * std::sqrt(1.0 + 0.4 * kBobRadius * kBobRadius / (kPendulumLength * kPendulumLength));
    return physicalT0 / test_support::agm(1.0, std::cos(kTheta0 / 2.0));
}

ReferenceScene pendulum() {
    ReferenceScene s;
    s.name = "pendulum";
    s.title = "Pendulum on a hinge";
    s.setup = "A solid sphere (r = 5 cm, 1 kg) whose centre is 1 m from a hinge to the world (axis z), released "
              "from 0.5 rad (29°); its period is measured from the upward zero crossings of x over the run.";
    s.metric = "relative error of the period, |T − T*| / T* (a run with fewer than two crossings counts as failed)";
    s.errorAxis = "relative error of the period";
    char answer[200];
    std::snprintf(answer, sizeof answer,
                  "T* = T0 / agm(1, cos(θ0/2)) = %.5f s, T0 = 2π sqrt(I / (m g L)) of the physical pendulum "
                  "(I = m L² + 2/5 m r²)",
                  exactPendulumPeriod());
    s.answer = answer;
    s.seconds = 8.0;
    s.quickSeconds = 5.0;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        const Vec3 start(static_cast<float>(kPendulumLength * std::sin(kTheta0)),
                         static_cast<float>(-kPendulumLength * std::cos(kTheta0)), 0.0f);
        BodyCreationSettings b;
        b.name = "bob";
        b.shape = Shape::sphere(static_cast<float>(kBobRadius));
        b.position = start;
        b.mass = 1.0f;
        const BodyId bob = world.createBody(b);
        JointCreationSettings j;
        j.type = JointType::Hinge;
        j.bodyA = bob;
        j.anchor = Vec3(0.0f);
        j.axis = Vec3(0.0f, 0.0f, 1.0f);
        world.createJoint(j);
        std::vector<double> crossings;
        double previousTime = 0.0, previousX = static_cast<double>(start.x);
        stepFor(world, seconds, timer, [&] {
            const double t = world.simulatedTime(), x = world.centerOfMass(bob).x;
            if (previousX < 0.0 && x >= 0.0) crossings.push_back(previousTime + (t - previousTime) * -previousX / (x - previousX));
            previousTime = t;
            previousX = x;
        });
        const double period = crossings.size() < 2 ? kInfinity
                                                   : (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
        return observation(world, {period});
    };
    s.error = [](const Observation& o, const Observation*) {
        const double exact = exactPendulumPeriod();
        return std::abs(o.values[0] - exact) / exact;
    };
    return s;
}

// ---- elastic collision

constexpr double kMassA = 1.0, kMassB = 3.0, kSpeedA = 20.0, kSpeedB = -10.0;

ReferenceScene elasticCollision() {
    ReferenceScene s;
    s.name = "elastic-collision";
    s.title = "Elastic head-on collision";
    s.setup = "Zero gravity: spheres of r = 10 cm, 1 kg at x = −1 m moving at +20 m/s and 3 kg at x = +1 m moving "
              "at −10 m/s, restitution 1, friction 0; velocities read 0.5 s later. At dt = 1/30 s each sphere "
              "moves 3–7 radii per step, so this is also a tunnelling test.";
    s.metric = "largest velocity error after the impact over the closing speed, max(|vA − vA*|, |vB − vB*|) / 30 m/s";
    s.errorAxis = "velocity error / closing speed";
    s.answer = "vA* = ((mA − mB) uA + 2 mB uB) / (mA + mB) = −25 m/s, vB* = ((mB − mA) uB + 2 mA uA) / (mA + mB) = 5 m/s";
    s.base = zeroGravity();
    s.toggles = {Effect::Ccd};
    s.seconds = 0.5;
    s.quickSeconds = 0.5;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        auto sphere = [&](float x, double mass, double speed) {
            BodyCreationSettings b;
            b.name = "sphere";
            b.shape = Shape::sphere(0.1f);
            b.position = Vec3(x, 0.0f, 0.0f);
            b.mass = static_cast<float>(mass);
            b.linearVelocity = Vec3(static_cast<float>(speed), 0.0f, 0.0f);
            b.friction = 0.0f;
            b.restitution = 1.0f;
            return world.createBody(b);
        };
        const BodyId a = sphere(-1.0f, kMassA, kSpeedA);
        const BodyId b = sphere(1.0f, kMassB, kSpeedB);
        stepFor(world, seconds, timer);
        return observation(world, {world.linearVelocity(a).x, world.linearVelocity(b).x});
    };
    s.error = [](const Observation& o, const Observation*) {
        const double total = kMassA + kMassB;
        const double exactA = ((kMassA - kMassB) * kSpeedA + 2.0 * kMassB * kSpeedB) / total;
        const double exactB = ((kMassB - kMassA) * kSpeedB + 2.0 * kMassA * kSpeedA) / total;
        return std::max(std::abs(o.values[0] - exactA), std::abs(o.values[1] - exactB)) / (kSpeedA - kSpeedB);
    };
    return s;
}

// ---- free tumbling body

ReferenceScene tumbling() {
    ReferenceScene s;
    s.name = "tumbling";
    s.title = "Free tumbling body: angular momentum and energy";
    s.setup = "Zero gravity: a 0.2 × 0.8 × 1.6 m box (1 kg) spinning at 4 rad/s about its intermediate axis (y), "
              "perturbed by 0.05 rad/s about x and z, so it flips over and back (the tennis-racket effect).";
    // The vector, not only |L|: without the gyroscopic term the body spins about a fixed axis, which
    // keeps |L| and E exactly but turns L.
    s.metric = "largest relative drift over the run of the angular momentum vector and of the kinetic energy, "
               "max(|L − L0| / |L0|, |E/E0 − 1|)";
    s.errorAxis = "relative drift of L or energy";
    s.answer = "L (so also |L|) and E are constant (torque-free motion)";
    s.base = zeroGravity();
    s.toggles = {Effect::Gyroscopic};
    s.seconds = 6.0;
    s.quickSeconds = 3.0;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        BodyCreationSettings b;
        b.name = "box";
        b.shape = Shape::box(Vec3(0.1f, 0.4f, 0.8f));
        b.mass = 1.0f;
        b.angularVelocity = Vec3(0.05f, 4.0f, 0.05f);
        world.createBody(b);
        const Vec3 l0 = world.angularMomentum();
        const double e0 = world.kineticEnergy();
        double worst = 0.0;
        stepFor(world, seconds, timer, [&] {
            const double drift = glm::length(world.angularMomentum() - l0) / glm::length(l0);
            worst = std::max({worst, drift, std::abs(world.kineticEnergy() / e0 - 1.0)});
        });
        return observation(world, {worst});
    };
    s.error = [](const Observation& o, const Observation*) { return o.values[0]; };
    return s;
}

// ---- hard scenes, against a converged run

// Unit cubes (friction 0.5) standing on a static ground, compared with a converged run on where
// every cube's centre ends up. `cubes` gives each cube's centre and mass.
ReferenceScene standingCubes(std::vector<std::pair<Vec3, float>> cubes) {
    ReferenceScene s;
    s.metric = "largest distance (m) of any cube's centre at the end from where the converged run has it";
    s.errorAxis = "largest distance from the converged run (m)";
    s.reference = ReferenceKind::ConvergedRun;
    s.toggles = {Effect::Sleeping};
    s.run = [cubes = std::move(cubes)](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        addGround(world, 20.0f);
        std::vector<BodyId> ids;
        for (const auto& [centre, mass] : cubes) ids.push_back(world.createBody(unitCube(centre, mass)));
        stepFor(world, seconds, timer);
        return centres(world, ids);
    };
    s.error = largestCentreDistance;
    return s;
}

ReferenceScene tower() {
    std::vector<std::pair<Vec3, float>> cubes;
    for (const Vec3& centre : scene_builders::towerCentres(16)) cubes.emplace_back(centre, 1.0f);
    ReferenceScene s = standingCubes(std::move(cubes));
    s.name = "tower-drift";
    s.title = "Tower of 16 cubes: drift";
    s.setup = "16 unit cubes (1 kg, friction 0.5) stacked exactly on a static ground, left to stand for 4 s.";
    s.answer = "every cube's centre of mass at t = 4 s";
    s.seconds = 4.0;
    s.quickSeconds = 2.0;
    return s;
}

ReferenceScene pyramid() {
    std::vector<std::pair<Vec3, float>> cubes;
    for (const Vec3& centre : scene_builders::squarePyramidCentres(5)) cubes.emplace_back(centre, 1.0f);
    ReferenceScene s = standingCubes(std::move(cubes));
    s.name = "pyramid-drift";
    s.title = "Pyramid of 55 cubes: drift";
    s.setup = "A square pyramid of unit cubes (1 kg, friction 0.5), 5 × 5 at the base, 5 layers, 55 cubes, each "
              "layer centred on the one below, left to stand for 3 s.";
    s.answer = "every cube's centre of mass at t = 3 s";
    s.seconds = 3.0;
    s.quickSeconds = 1.0;
    return s;
}

ReferenceScene massRatioStack() {
    ReferenceScene s = standingCubes({{Vec3(0.0f, 0.5f, 0.0f), 1.0f}, {Vec3(0.0f, 1.5f, 0.0f), 100.0f}});
    s.name = "mass-ratio-sink";
    s.title = "100:1 mass ratio stack: sink";
    s.setup = "A 100 kg unit cube resting on a 1 kg unit cube on a static ground (friction 0.5), 3 s.";
    s.metric = "largest distance (m) of either cube's centre at the end from where the converged run has it "
               "(mostly how far the heavy cube has sunk into the light one)";
    s.answer = "both centres of mass at t = 3 s";
    s.seconds = 3.0;
    s.quickSeconds = 1.0;
    return s;
}

ReferenceScene chain() {
    ReferenceScene s;
    s.name = "chain-joint-error";
    s.title = "20-link hinge chain: joint error";
    s.setup = "A chain of 20 links (0.25 × 0.06 × 0.06 m boxes, 0.5 kg) joined by hinges (axis z), the first hinged "
              "to the world, released horizontally; it swings for 4 s, its end whipping through at over 10 m/s.";
    s.metric = "largest joint separation (m) in any step, World::worstJointError().position";
    s.errorAxis = "largest joint separation (m)";
    s.answer = "0: rigid hinges never separate";
    s.toggles = {Effect::Ccd};
    s.seconds = 4.0;
    s.quickSeconds = 2.0;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        constexpr int kLinks = 20;
        constexpr float kHalfLength = 0.125f;
        BodyId previous;
        for (int i = 0; i < kLinks; ++i) {
            const float x0 = 2.0f * kHalfLength * static_cast<float>(i);
            BodyCreationSettings b;
            b.name = "link";
            b.shape = Shape::box(Vec3(kHalfLength, 0.03f, 0.03f));
            b.position = Vec3(x0 + kHalfLength, 0.0f, 0.0f);
            b.mass = 0.5f;
            const BodyId link = world.createBody(b);
            JointCreationSettings j;
            j.type = JointType::Hinge;
            j.bodyA = link;
            j.bodyB = previous;
            j.anchor = Vec3(x0, 0.0f, 0.0f);
            j.axis = Vec3(0.0f, 0.0f, 1.0f);
            world.createJoint(j);
            previous = link;
        }
        double worst = 0.0;
        stepFor(world, seconds, timer, [&] { worst = std::max(worst, static_cast<double>(world.worstJointError().position)); });
        return observation(world, {worst});
    };
    s.error = [](const Observation& o, const Observation*) { return o.values[0]; };
    return s;
}

ReferenceScene pile() {
    ReferenceScene s;
    s.name = "pile-penetration";
    s.title = "Pile of 64 cubes: penetration";
    s.setup = "64 unit cubes (1 kg, friction 0.5) in a 4 × 4 × 4 grid, 1.2 m apart, the lowest 2 m up, dropped on a "
              "static ground; 3 s (they land at about 0.5 s and settle).";
    s.metric = "deepest contact overlap (m) at the start of any step, StepProfile::maxPenetration";
    s.errorAxis = "deepest overlap in any step (m)";
    s.answer = "0: rigid bodies do not overlap";
    s.toggles = {Effect::Ccd, Effect::Sleeping};
    s.seconds = 3.0;
    s.quickSeconds = 1.5;
    s.run = [](const WorldSettings& settings, double seconds, SteppingTimer& timer) {
        World world(settings);
        addGround(world, 50.0f);
        for (const Vec3& centre : scene_builders::gridCentres(4, 4, 4, 1.2f, 2.0f)) world.createBody(unitCube(centre, 1.0f));
        double worst = 0.0;
        stepFor(world, seconds, timer, [&] { worst = std::max(worst, static_cast<double>(world.lastStepProfile().maxPenetration)); });
        return observation(world, {worst});
    };
    s.error = [](const Observation& o, const Observation*) { return o.values[0]; };
    return s;
}

// Each joint's frame now, in world coordinates, as JointCreationSettings reads it.
class JointFrames final : public simcore::DebugDraw {
public:
    void drawJoint(const simcore::DebugJoint& joint) override { frames.push_back(joint); }
    std::vector<simcore::DebugJoint> frames;
};

simcore::Scene sceneOf(const World& world) {
    simcore::Scene scene;
    scene.settings = world.settings();
    const std::vector<BodyId> bodies = world.bodyIds();
    // Files refer to jointed bodies by name, so a name the scene gives several bodies is numbered.
    std::map<std::string, int> uses, seen;
    for (BodyId id : bodies) ++uses[world.name(id)];
    for (BodyId id : bodies) {
        BodyCreationSettings b;
        b.name = world.name(id);
        if (uses[b.name] > 1) b.name += "-" + std::to_string(++seen[b.name]);
        b.shape = world.shape(id);
        b.motion = world.motionType(id);
        b.position = world.position(id);
        b.orientation = world.orientation(id);
        b.linearVelocity = world.linearVelocity(id);
        b.angularVelocity = world.angularVelocity(id);
        if (b.motion == MotionType::Dynamic) b.mass = world.mass(id);
        b.density = world.density(id);
        b.friction = world.friction(id);
        b.restitution = world.restitution(id);
        b.rollingResistance = world.rollingResistance(id);
        b.ccd = world.ccdEnabled(id);
        scene.bodies.push_back({std::move(b), std::nullopt, std::nullopt});
    }
    auto indexOf = [&bodies](BodyId id) {
        return static_cast<std::size_t>(std::find(bodies.begin(), bodies.end(), id) - bodies.begin());
    };
    JointFrames frames;
    simcore::DebugDrawOptions options;
    options.bodies = false;
    options.joints = true;
    world.draw(frames, options);
    for (const simcore::DebugJoint& frame : frames.frames) {
        simcore::SceneJoint joint;
        JointCreationSettings& j = joint.joint;
        j.name = world.jointName(frame.id);
        j.type = frame.type;
        j.anchor = frame.anchorA;
        j.anchorB = frame.anchorB;
        j.axis = frame.axis;
        j.limits = world.jointLimits(frame.id);
        j.motor = world.jointMotor(frame.id);
        j.spring = world.jointSpring(frame.id);
        if (frame.type == JointType::Distance) {
            const simcore::DistanceLengths lengths = world.jointLengths(frame.id);
            j.minLength = lengths.min;
            j.maxLength = lengths.max;
        }
        j.collideConnected = world.jointCollidesConnected(frame.id);
        joint.bodyA = indexOf(frame.bodyA);
        if (frame.bodyB.isValid()) joint.bodyB = indexOf(frame.bodyB);
        scene.joints.push_back(std::move(joint));
    }
    return scene;
}

}  // namespace

simcore::Scene sceneFile(const ReferenceScene& scene) {
    std::optional<simcore::Scene> built;
    SteppingTimer timer([&built](const World& world) { built = sceneOf(world); });
    scene.run(scene.base, static_cast<double>(scene.base.timeStep), timer);  // one step
    if (!built) throw std::logic_error(scene.name + ": its run did not step the world");
    return std::move(*built);
}

std::vector<ReferenceScene> referenceScenes() {
    return {inclineSlide(), inclineRoll(), pendulum(), elasticCollision(), tumbling(),
            tower(),        pyramid(),     massRatioStack(), chain(),          pile()};
}

}  // namespace accuracy
