#include "simcore/world/world.h"

#include "simcore/collision/ray_cast.h"
#include "simcore/collision/time_of_impact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace simcore {

namespace {

void require(bool condition, const std::string& what) {
    if (!condition) throw std::invalid_argument(what);
}

bool isPositiveFinite(float v) { return isFinite(v) && v > 0.0f; }

void validateShape(const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Sphere:
            require(isPositiveFinite(shape.radius), "shape.radius must be a positive finite number");
            break;
        case ShapeType::Box:
            require(isPositiveFinite(shape.halfExtents.x) && isPositiveFinite(shape.halfExtents.y) &&
                        isPositiveFinite(shape.halfExtents.z),
                    "shape.halfExtents must be positive finite numbers");
            break;
        case ShapeType::Capsule:
        case ShapeType::Cylinder:
            require(isPositiveFinite(shape.radius), "shape.radius must be a positive finite number");
            require(isPositiveFinite(shape.halfHeight), "shape.halfHeight must be a positive finite number");
            break;
        case ShapeType::ConvexHull:
            require(shape.hull != nullptr, "shape.hull is missing");
            break;
    }
}

void validateMass(float mass) { require(isPositiveFinite(mass), "mass must be a positive finite number"); }
void validateDensity(float density) { require(isPositiveFinite(density), "density must be a positive finite number"); }
void validateFriction(float friction) {
    require(isFinite(friction) && friction >= 0.0f, "friction must be finite and >= 0");
}
void validateRestitution(float restitution) {
    require(isFinite(restitution) && restitution >= 0.0f && restitution <= 1.0f, "restitution must be in [0, 1]");
}
void validateRollingResistance(float coefficient) {
    require(isFinite(coefficient) && coefficient >= 0.0f, "rollingResistance must be finite and >= 0");
}

void validateBody(const BodyCreationSettings& s) {
    validateShape(s.shape);
    require(isFinite(s.position), "position must be finite");
    require(isFinite(s.orientation) && glm::length(s.orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    require(isFinite(s.linearVelocity), "linearVelocity must be finite");
    require(isFinite(s.angularVelocity), "angularVelocity must be finite");
    if (s.mass) validateMass(*s.mass);
    validateDensity(s.density);
    validateFriction(s.friction);
    validateRestitution(s.restitution);
    validateRollingResistance(s.rollingResistance);
}

// A body's mass properties: from its mass or density when dynamic; static and kinematic bodies
// have infinite mass, and only the centre of mass matters (as the integrated point of a kinematic
// body). Throws when the shape gives no usable mass.
MassProperties bodyMassProperties(const Shape& shape, MotionType motion, std::optional<float> mass, float density) {
    if (motion != MotionType::Dynamic) {
        MassProperties centreOnly;
        centreOnly.centerOfMass = massProperties(shape, 1.0f).centerOfMass;
        return centreOnly;
    }
    const MassProperties result = mass ? massPropertiesForMass(shape, *mass) : massProperties(shape, density);
    require(isPositiveFinite(result.mass), "the shape's mass is not a positive finite number");
    // A huge mass on a large shape overflows the moments to infinity, whose inverse is NaN.
    for (int c = 0; c < 3; ++c)
        require(isFinite(result.inertia[c]), "mass and shape give a non-finite inertia (a smaller mass or density)");
    return result;
}

void validateSettings(const WorldSettings& s) {
    require(isFinite(s.gravity), "gravity must be finite");
    require(isPositiveFinite(s.timeStep), "timeStep must be a positive finite number");
    require(s.substeps >= 1, "substeps must be at least 1");
    require(s.solver.velocityIterations >= 0, "solver.velocityIterations must be >= 0");
    require(s.solver.positionIterations >= 0, "solver.positionIterations must be >= 0");
    require(isFinite(s.damping.linear) && s.damping.linear >= 0.0f, "damping.linear must be finite and >= 0");
    require(isFinite(s.damping.angular) && s.damping.angular >= 0.0f, "damping.angular must be finite and >= 0");
    require(isFinite(s.sleep.linearVelocity) && s.sleep.linearVelocity >= 0.0f,
            "sleep.linearVelocity must be finite and >= 0");
    require(isFinite(s.sleep.angularVelocity) && s.sleep.angularVelocity >= 0.0f,
            "sleep.angularVelocity must be finite and >= 0");
    require(isFinite(s.sleep.timeToSleep) && s.sleep.timeToSleep >= 0.0f,
            "sleep.timeToSleep must be finite and >= 0");
    require(isPositiveFinite(s.joint.hertz), "joint.hertz must be a positive finite number");
    require(isFinite(s.joint.dampingRatio) && s.joint.dampingRatio >= 0.0f, "joint.dampingRatio must be finite and >= 0");
}

// The options a joint type takes, each checked on its own so the live setters check the same.
void validateJointLimits(JointType type, const std::optional<JointLimits>& limits) {
    if (!limits) return;
    require(type == JointType::Hinge || type == JointType::Slider, "limits apply to hinge and slider joints only");
    require(isFinite(limits->lower) && isFinite(limits->upper), "limits must be finite");
    require(limits->lower <= limits->upper, "limits.lower must not exceed limits.upper");
    if (type == JointType::Hinge)
        require(limits->lower >= -kPi && limits->upper <= kPi, "hinge limits must lie within [-pi, pi] rad");
}

void validateJointMotor(JointType type, const std::optional<JointMotor>& motor) {
    if (!motor) return;
    require(type == JointType::Hinge || type == JointType::Slider, "motor applies to hinge and slider joints only");
    require(isFinite(motor->speed), "motor.speed must be finite");
    require(isFinite(motor->maxForce) && motor->maxForce >= 0.0f, "motor.maxForce must be finite and >= 0");
}

void validateJointSpring(JointType type, const std::optional<JointSpring>& spring) {
    if (!spring) return;
    require(type == JointType::Distance, "spring applies to distance joints only");
    require(isPositiveFinite(spring->hertz), "spring.hertz must be a positive finite number");
    require(isFinite(spring->dampingRatio) && spring->dampingRatio >= 0.0f, "spring.dampingRatio must be finite and >= 0");
}

// A distance joint's limits given its rest length (m) and whether it has a spring.
void validateJointLengths(JointType type, float restLength, bool hasSpring, std::optional<float> minLength,
                          std::optional<float> maxLength) {
    if (minLength || maxLength) {
        require(type == JointType::Distance, "minLength and maxLength apply to distance joints only");
        require(!minLength || (isFinite(*minLength) && *minLength >= 0.0f), "minLength must be finite and >= 0");
        require(!maxLength || (isFinite(*maxLength) && *maxLength >= 0.0f), "maxLength must be finite and >= 0");
    }
    if (type == JointType::Distance) {
        const DistanceLengths lengths = distanceLengths(restLength, hasSpring, minLength, maxLength);
        require(lengths.min <= lengths.max, "minLength must not exceed maxLength (unset, each is the rest length)");
    }
}

// What can be checked without the bodies: numbers, and which options the type takes.
void validateJoint(const JointCreationSettings& s) {
    const bool hingeOrSlider = s.type == JointType::Hinge || s.type == JointType::Slider;
    const bool distance = s.type == JointType::Distance;
    require(isFinite(s.anchor), "anchor must be finite");
    if (distance) {
        require(isFinite(s.anchorB), "anchorB must be finite");
        require(glm::length(s.anchorB - s.anchor) >= 1e-4f, "anchorB must be at least 0.1 mm from anchor");
    }
    if (hingeOrSlider) require(isFinite(s.axis) && glm::length(s.axis) > 1e-6f, "axis must be a finite, non-zero vector");
    validateJointLimits(s.type, s.limits);
    validateJointMotor(s.type, s.motor);
    validateJointSpring(s.type, s.spring);
    validateJointLengths(s.type, distanceLengths(s).rest, s.spring.has_value(), s.minLength, s.maxLength);
}

}  // namespace

World::World(const WorldSettings& settings) { setSettings(settings); }

void World::setSettings(const WorldSettings& settings) {
    validateSettings(settings);
    settings_ = settings;
    if (!settings_.effects[Effect::Sleeping] || !settings_.sleep.enabled) {
        for (std::size_t i = 0; i < bodies_.size(); ++i) wakeIndex(i);
    }
}

BodyId World::createBody(const BodyCreationSettings& settings) {
    validateBody(settings);
    const MassProperties properties = bodyMassProperties(settings.shape, settings.motion, settings.mass, settings.density);
    const BodyId id = bodies_.add(settings, properties);
    const std::size_t i = bodies_.size() - 1;
    // Static bodies never move, so their proxies are inactive: pairs need an active side.
    bodies_.proxy[i] = broadPhase_.addProxy(bodies_.bounds[i], id.index, settings.motion != MotionType::Static);
    return id;
}

void World::destroyBody(BodyId id) {
    const std::size_t i = indexOf(id);
    for (std::size_t j = joints_.size(); j-- > 0;) {
        const Joint& joint = joints_.joints[j];
        if (joint.bodyA == id || joint.bodyB == id) destroyJoint(joints_.idAt(j));
    }
    contactManager_.removeContactsOf(id.index);
    broadPhase_.removeProxy(bodies_.proxy[i]);
    bodies_.remove(id);
}

JointId World::createJoint(const JointCreationSettings& settings) {
    validateJoint(settings);
    require(contains(settings.bodyA), "bodyA is not a body of this world");
    require(!settings.bodyB.isValid() || contains(settings.bodyB), "bodyB is not a body of this world");
    require(!(settings.bodyA == settings.bodyB), "bodyB must differ from bodyA");
    const JointId id = joints_.add(settings, bodies_);
    wakeIndex(indexOf(settings.bodyA));
    if (settings.bodyB.isValid()) {
        wakeIndex(indexOf(settings.bodyB));
        if (!settings.collideConnected) filterJointPair(settings.bodyA, settings.bodyB);
    }
    return id;
}

void World::destroyJoint(JointId id) {
    const Joint joint = joints_.joints[indexOf(id)];
    joints_.remove(id);
    wakeIndex(indexOf(joint.bodyA));
    if (!joint.bodyB.isValid()) return;
    wakeIndex(indexOf(joint.bodyB));
    if (!joint.collideConnected) unfilterJointPair(joint.bodyA, joint.bodyB);
}

void World::filterJointPair(BodyId a, BodyId b) {
    const std::uint64_t key = PairTable::key(a.index, b.index);
    const std::uint32_t count = jointFilteredPairs_.find(key);
    if (count == PairTable::kNotFound) jointFilteredPairs_.insert(key, 1);
    else jointFilteredPairs_.assign(key, count + 1);
    contactManager_.removePair(a.index, b.index);
}

void World::unfilterJointPair(BodyId a, BodyId b) {
    const std::uint64_t key = PairTable::key(a.index, b.index);
    const std::uint32_t count = jointFilteredPairs_.find(key);
    if (count > 1) {
        jointFilteredPairs_.assign(key, count - 1);
        return;
    }
    jointFilteredPairs_.erase(key);
    // The broad phase reports a pair again only when a proxy moves: mark both moved.
    broadPhase_.touchProxy(bodies_.proxy[indexOf(a)]);
    broadPhase_.touchProxy(bodies_.proxy[indexOf(b)]);
}

std::vector<JointId> World::jointIds() const {
    std::vector<JointId> ids;
    ids.reserve(joints_.size());
    for (std::size_t i = 0; i < joints_.size(); ++i) ids.push_back(joints_.idAt(i));
    return ids;
}

JointType World::jointType(JointId id) const { return joints_.joints[indexOf(id)].type; }
BodyId World::jointBodyA(JointId id) const { return joints_.joints[indexOf(id)].bodyA; }
BodyId World::jointBodyB(JointId id) const { return joints_.joints[indexOf(id)].bodyB; }
const std::string& World::jointName(JointId id) const { return joints_.names[indexOf(id)]; }
JointError World::jointError(JointId id) const { return joints_.error(indexOf(id), bodies_); }

JointError World::worstJointError() const {
    JointError worst;
    for (std::size_t i = 0; i < joints_.size(); ++i) {
        const JointError e = joints_.error(i, bodies_);
        worst.position = std::max(worst.position, e.position);
        worst.angle = std::max(worst.angle, e.angle);
    }
    return worst;
}

std::vector<BodyId> World::bodyIds() const {
    std::vector<BodyId> ids;
    ids.reserve(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) ids.push_back(bodies_.idAt(i));
    return ids;
}

World::Activity World::scanActivity() const {
    Activity activity;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic || !bodies_.awake[i]) continue;
        activity.anyAwakeDynamic = true;
        if (lengthSquared(bodies_.angularVelocity[i]) > 0.0f) {
            activity.anySpinning = true;
            break;  // nothing more to learn
        }
    }
    return activity;
}

// An effect runs when the settings enable it and something in the world would be affected.
bool World::needs(Effect effect, const Activity& activity) const {
    if (!settings_.effects[effect]) return false;
    switch (effect) {
        case Effect::Gravity: return activity.anyAwakeDynamic && lengthSquared(settings_.gravity) > 0.0f;
        case Effect::Damping:
            return activity.anyAwakeDynamic && (settings_.damping.linear > 0.0f || settings_.damping.angular > 0.0f);
        case Effect::Gyroscopic: return activity.anySpinning;
        case Effect::Sleeping: return settings_.sleep.enabled && activity.anyAwakeDynamic;
        case Effect::Contacts: return activity.anyAwakeDynamic && bodies_.size() > 1;
        case Effect::Joints: return activity.anyAwakeDynamic && !joints_.empty();
        // Continuous collision guards contacts against fast bodies; sweepFastBodies decides per
        // step whether any body is fast enough to need it.
        case Effect::Ccd: return needs(Effect::Contacts, activity);
        // Friction and restitution are decided per constraint by the contact solver.
        case Effect::Friction:
        case Effect::Restitution:
        case Effect::Count: return false;
    }
    return false;
}

// One step, in order of execution:
//   1. broad phase: move the fat boxes of awake bodies; new overlapping pairs become contacts
//   2. narrow phase: a fresh manifold for every contact with an awake body (impulses carried over)
//   3. islands (through contacts and joints): bodies touching an awake island wake up with it
//   4. prepare contact and joint constraints (once per step, with last step's impulses)
//   for each substep of h = timeStep / substeps:
//     5. integrate velocities: gravity, applied forces, gyroscopic torque, damping
//     6. warm start, then velocity iterations with position correction (joints, then contacts);
//        collisions (restitution) first in the first substep
//     7. integrate positions: centres of mass and orientations, by the chosen integrator
//     8. collisions (restitution), then relax iterations: the same constraints without the push,
//        so it does not become bounce
//   9. impulses stored for the next step's warm start
//  10. continuous collision: a fast body that would pass through another stops at the time of impact
//  11. sleep: islands that stayed slow long enough stop being simulated
//  12. applied forces and torques, having acted over the whole step, are cleared
// Stages 1-4, 6 and 8-9 run only when contacts or joints are needed; see needs() for every effect.
void World::step() {
    const auto stepStart = std::chrono::steady_clock::now();
    StepProfile profile;
    auto& ms = profile.stageMs;
    auto slot = [&ms](Stage stage) -> double& { return ms[static_cast<int>(stage)]; };

    const Activity activity = scanActivity();
    const bool gravity = needs(Effect::Gravity, activity);
    const bool damping = needs(Effect::Damping, activity);
    const bool gyroscopic = needs(Effect::Gyroscopic, activity);
    const bool contacts = needs(Effect::Contacts, activity);
    const bool joints = needs(Effect::Joints, activity);
    const bool sleeping = needs(Effect::Sleeping, activity);
    const bool continuous = needs(Effect::Ccd, activity);

    const float h = settings_.timeStep / static_cast<float>(settings_.substeps);
    VelocityIntegration velocityParams;
    velocityParams.gravity = gravity ? settings_.gravity : Vec3(0.0f);
    velocityParams.gyroscopic = gyroscopic;
    if (damping) {
        velocityParams.linearRetention = std::exp(-settings_.damping.linear * h);
        velocityParams.angularRetention = std::exp(-settings_.damping.angular * h);
    }

    if (contacts) {
        {
            ScopedStageTimer timer(slot(Stage::BroadPhase));
            profile.counters.droppedPairs = static_cast<std::uint32_t>(updateBroadPhase(settings_.timeStep));
            proxiesStale_ = false;
        }
        {
            ScopedStageTimer timer(slot(Stage::NarrowPhase));
            updateContacts();
        }
        {
            ScopedStageTimer timer(slot(Stage::Sleep));
            buildIslandsAndWake();
        }
        ScopedStageTimer timer(slot(Stage::SolveConstraints));
        ContactSolver::Params params;
        params.substepDt = h;
        params.friction = settings_.effects[Effect::Friction];
        params.restitution = settings_.effects[Effect::Restitution];
        params.gravity = velocityParams.gravity;
        params.solver = settings_.solver;
        params.contact = settings_.contact;
        contactSolver_.prepare(contactManager_.contacts(), bodies_, params);
    }
    if (joints) {
        if (!contacts) {
            ScopedStageTimer timer(slot(Stage::Sleep));
            buildIslandsAndWake();
        }
        ScopedStageTimer timer(slot(Stage::SolveConstraints));
        jointSolver_.prepare(joints_, bodies_, {h, settings_.joint});
    }
    if (continuous) recordSweepStarts();
    const bool solveContacts = contacts && contactSolver_.constraintCount() > 0;
    const bool relax = solveContacts && settings_.solver.positionCorrection == PositionCorrection::SoftStep;
    // Joints are always soft, so they always relax. In each pass joints go first and contacts
    // have the last word (Box2D v3's order): penetration shows more than joint stretch.
    const bool solveJoints = joints && jointSolver_.constraintCount() > 0;
    const bool bounce = solveContacts && contactSolver_.usesRestitution();

    for (int substep = 0; substep < settings_.substeps; ++substep) {
        {
            ScopedStageTimer timer(slot(Stage::IntegrateVelocities));
            profile.counters.boundedVelocities += integrator_.integrateVelocities(bodies_, settings_.integrator, velocityParams, h);
        }
        if (solveContacts || solveJoints) {
            ScopedStageTimer timer(slot(Stage::SolveConstraints));
            if (bounce && substep == 0) contactSolver_.resolveCollisions(bodies_, ContactSolver::ImpactTiming::BeforePositions);
            if (solveJoints) jointSolver_.warmStart(bodies_);
            if (solveContacts) contactSolver_.warmStart(bodies_);
            for (int i = 0; i < settings_.solver.velocityIterations; ++i) {
                if (solveJoints) jointSolver_.solve(bodies_, true);
                if (solveContacts) contactSolver_.solve(bodies_, true);
            }
        }
        {
            ScopedStageTimer timer(slot(Stage::IntegratePositions));
            profile.counters.boundedVelocities += integrator_.integratePositions(bodies_, settings_.integrator, h);
        }
        if (bounce) {
            // Before relax, which would slow a body about to hit down to the speed that just closes
            // the gap (speculative contact) and so take away the impact the bounce needs.
            ScopedStageTimer timer(slot(Stage::SolveConstraints));
            contactSolver_.resolveCollisions(bodies_, ContactSolver::ImpactTiming::AfterPositions);
        }
        if (relax || solveJoints) {
            ScopedStageTimer timer(slot(Stage::SolveConstraints));
            bool pushLeft = false;
            for (int i = 0; i < settings_.solver.positionIterations; ++i) {
                if (solveJoints) jointSolver_.solve(bodies_, false);
                if (relax) pushLeft = contactSolver_.solve(bodies_, false);
            }
            for (int i = 0; pushLeft && i < ContactSolver::kMaxExtraRelaxPasses; ++i) pushLeft = contactSolver_.solve(bodies_, false);
        }
    }
    if (solveJoints) {
        // Joints are the one source that can pass the bound within a step (a torn assembly, in its
        // last relax passes), so only they pay for holding the state between steps to it.
        ScopedStageTimer timer(slot(Stage::SolveConstraints));
        profile.counters.boundedVelocities += integrator_.boundVelocities(bodies_, h);
    }
    if (solveContacts) {
        ScopedStageTimer timer(slot(Stage::SolveConstraints));
        contactSolver_.storeImpulses(contactManager_.contacts());
    }
    if (continuous) {
        ScopedStageTimer timer(slot(Stage::ContinuousCollision));
        if (sweepFastBodies()) countEffect(Effect::Ccd);
    }
    if (sleeping) {
        ScopedStageTimer timer(slot(Stage::Sleep));
        if (!contacts && !joints) islands_.build(bodies_, contactManager_.contacts(), joints_);
        islands_.sleepRestingIslands(bodies_, settings_.sleep, settings_.timeStep,
                                     [this](std::size_t i) { setAwake(i, false); });
    }

    clearAppliedForces();

    proxiesStale_ = proxiesStale_ || (!contacts && activity.anyAwakeDynamic);

    if (gravity) countEffect(Effect::Gravity);
    if (damping) countEffect(Effect::Damping);
    if (gyroscopic) countEffect(Effect::Gyroscopic);
    if (contacts) countEffect(Effect::Contacts);
    if (solveJoints) countEffect(Effect::Joints);
    if (solveContacts && contactSolver_.usesFriction()) countEffect(Effect::Friction);
    if (bounce) countEffect(Effect::Restitution);
    if (sleeping) countEffect(Effect::Sleeping);

    StepCounters& counters = profile.counters;
    counters.bodies = static_cast<std::uint32_t>(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] == MotionType::Dynamic) ++counters.dynamicBodies;
        if (bodies_.awake[i]) ++counters.awakeBodies;
    }
    counters.pairs = static_cast<std::uint32_t>(contactManager_.contacts().size());
    for (const Contact& contact : contactManager_.contacts()) {
        if (contact.manifold.pointCount == 0) continue;
        ++counters.manifolds;
        counters.contactPoints += static_cast<std::uint32_t>(contact.manifold.pointCount);
    }
    counters.islands = contacts || joints ? islands_.awakeIslandCount() : 0;
    profile.maxPenetration = solveContacts ? contactSolver_.maxPenetration() : 0.0f;

    ++stepCount_;
    simulatedTime_ += settings_.timeStep;
    profile.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stepStart).count();
    lastProfile_ = profile;
}

void World::clearAppliedForces() {
    std::fill(bodies_.force.begin(), bodies_.force.end(), Vec3(0.0f));
    std::fill(bodies_.torque.begin(), bodies_.torque.end(), Vec3(0.0f));
}

std::size_t World::updateBroadPhase(float dt) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] == MotionType::Static || !bodies_.awake[i]) continue;
        bodies_.bounds[i] = worldBounds(bodies_.shape[i], bodies_.transform(i));
        broadPhase_.moveProxy(bodies_.proxy[i], bodies_.bounds[i], dt * bodies_.linearVelocity[i]);
    }
    broadPhase_.updatePairs(newPairs_);
    // Jointed bodies do not collide unless their joint asks for it (collideConnected).
    if (jointFilteredPairs_.size() > 0) {
        std::erase_if(newPairs_, [this](const BodyPair& pair) {
            return jointFilteredPairs_.find(PairTable::key(pair.a, pair.b)) != PairTable::kNotFound;
        });
    }
    return contactManager_.addPairs(newPairs_, bodies_, settings_.contact.maxContactsPerBody);
}

void World::updateContacts() {
    contactManager_.updateManifolds(bodies_, broadPhase_, settings_.contact.speculativeDistance, settings_.timeStep);
}

void World::recordSweepStarts() {
    sweepStartCenter_.resize(bodies_.size());
    sweepStartRotation_.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        sweepStartCenter_[i] = bodies_.centerOfMass[i];
        sweepStartRotation_[i] = bodies_.orientation[i];
    }
}

// Speculative contacts stop most fast bodies at the surface they approach; this catches the rest
// (a body that meets something its start-of-step contacts did not see). A body is swept when it is
// flagged `ccd` or moved more than half its thinnest dimension: against static bodies, or, when
// flagged, against every other body at that body's end pose. It is put back to the first time of
// impact, keeping its velocity: the next step's contacts take it from there. Returns whether any
// body was fast.
bool World::sweepFastBodies() {
    constexpr float kFastFraction = 0.5f;
    const float target = settings_.contact.linearSlop;
    bool anyFast = false;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic || !bodies_.awake[i]) continue;
        const Sweep sweep{bodies_.localCenterOfMass[i], sweepStartCenter_[i], bodies_.centerOfMass[i],
                          sweepStartRotation_[i], bodies_.orientation[i]};
        const Shape& shape = bodies_.shape[i];
        const float travel = glm::length(sweep.center1 - sweep.center0) +
                             sweep.rotationAngle() * glm::length(bodies_.bounds[i].halfExtents());
        const float thin = kFastFraction * minimumExtent(shape);
        if (!bodies_.ccd[i] && travel <= thin) continue;
        anyFast = true;

        Aabb swept = worldBounds(shape, sweep.at(0.0f));
        swept.grow(worldBounds(shape, sweep.at(1.0f)));
        float first = 1.0f;
        const std::uint32_t slot = bodies_.idAt(i).index;
        broadPhase_.tree().query(swept, [&](ProxyId proxy) {
            const std::uint32_t otherSlot = broadPhase_.userData(proxy);
            if (otherSlot == slot) return;
            // Bodies a joint keeps from colliding may pass through each other.
            if (jointFilteredPairs_.find(PairTable::key(slot, otherSlot)) != PairTable::kNotFound) return;
            const std::size_t j = bodies_.denseIndexOfSlot(otherSlot);
            // Between moving bodies speculative contacts suffice unless the body asked for sweeps.
            if (!bodies_.ccd[i] && bodies_.motion[j] != MotionType::Static) return;
            const Sweep resting{bodies_.localCenterOfMass[j], bodies_.centerOfMass[j], bodies_.centerOfMass[j],
                                bodies_.orientation[j], bodies_.orientation[j]};
            const TimeOfImpact toi = timeOfImpact(shape, sweep, bodies_.shape[j], resting, target, 0.25f * target);
            if (toi.outcome != TimeOfImpact::Outcome::Hit) return;
            // A body grazing past (sliding along the ground, a link swinging by a post) comes within
            // the target without any risk of passing through: its contacts handle it, and putting it
            // back would only stall it. Only a hit whose remaining approach along the normal could
            // carry the body through counts, unless the body is flagged.
            const float approach = glm::dot(sweep.center1 - sweep.center0, toi.normal) * (1.0f - toi.fraction);
            if (bodies_.ccd[i] || approach > thin) first = std::min(first, toi.fraction);
        });
        if (first < 1.0f) {
            const Transform pose = sweep.at(first);
            bodies_.orientation[i] = pose.rotation;
            bodies_.centerOfMass[i] = pose.position + pose.rotation * bodies_.localCenterOfMass[i];
            bodies_.refreshInverseInertiaWorld(i);
        }
    }
    return anyFast;
}

void World::setAwake(std::size_t i, bool awake) {
    bodies_.awake[i] = awake ? 1 : 0;
    if (awake) bodies_.sleepTime[i] = 0.0f;
    broadPhase_.setActive(bodies_.proxy[i], awake);
}

std::size_t World::indexOf(BodyId id) const {
    const int i = bodies_.denseIndex(id);
    if (i < 0) throw std::out_of_range("stale or invalid body id");
    return static_cast<std::size_t>(i);
}

std::size_t World::indexOf(JointId id) const {
    const int i = joints_.denseIndex(id);
    if (i < 0) throw std::out_of_range("stale or invalid joint id");
    return static_cast<std::size_t>(i);
}

void World::buildIslandsAndWake() {
    islands_.build(bodies_, contactManager_.contacts(), joints_);
    islands_.wakeTouchedIslands(bodies_, [this](std::size_t i) { setAwake(i, true); });
}

Vec3 World::position(BodyId id) const { return bodies_.origin(indexOf(id)); }
Quat World::orientation(BodyId id) const { return bodies_.orientation[indexOf(id)]; }
Vec3 World::centerOfMass(BodyId id) const { return bodies_.centerOfMass[indexOf(id)]; }
Vec3 World::linearVelocity(BodyId id) const { return bodies_.linearVelocity[indexOf(id)]; }
Vec3 World::angularVelocity(BodyId id) const { return bodies_.angularVelocity[indexOf(id)]; }
bool World::isAwake(BodyId id) const { return bodies_.awake[indexOf(id)] != 0; }
const std::string& World::name(BodyId id) const { return bodies_.name[indexOf(id)]; }
const Shape& World::shape(BodyId id) const { return bodies_.shape[indexOf(id)]; }
MotionType World::motionType(BodyId id) const { return bodies_.motion[indexOf(id)]; }
float World::mass(BodyId id) const { return bodies_.mass[indexOf(id)]; }

void World::setTransform(BodyId id, const Vec3& position, const Quat& orientation) {
    const std::size_t i = indexOf(id);
    require(isFinite(position), "position must be finite");
    require(isFinite(orientation) && glm::length(orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    bodies_.orientation[i] = glm::normalize(orientation);
    bodies_.centerOfMass[i] = position + bodies_.orientation[i] * bodies_.localCenterOfMass[i];
    bodies_.refreshInverseInertiaWorld(i);
    bodies_.bounds[i] = worldBounds(bodies_.shape[i], bodies_.transform(i));
    broadPhase_.moveProxy(bodies_.proxy[i], bodies_.bounds[i], Vec3(0.0f));
    wakeIndex(i);
}

void World::setLinearVelocity(BodyId id, const Vec3& velocity) {
    const std::size_t i = indexOf(id);
    require(isFinite(velocity), "linearVelocity must be finite");
    if (bodies_.motion[i] == MotionType::Static) return;
    bodies_.linearVelocity[i] = velocity;
    wakeIndex(i);
}

void World::setAngularVelocity(BodyId id, const Vec3& velocity) {
    const std::size_t i = indexOf(id);
    require(isFinite(velocity), "angularVelocity must be finite");
    if (bodies_.motion[i] == MotionType::Static) return;
    bodies_.angularVelocity[i] = velocity;
    wakeIndex(i);
}

void World::addForce(BodyId id, const Vec3& force) {
    const std::size_t i = indexOf(id);
    require(isFinite(force), "force must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.force[i] += force;
    wakeIndex(i);
}

void World::addTorque(BodyId id, const Vec3& torque) {
    const std::size_t i = indexOf(id);
    require(isFinite(torque), "torque must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.torque[i] += torque;
    wakeIndex(i);
}

void World::addImpulse(BodyId id, const Vec3& impulse, const Vec3& worldPoint) {
    const std::size_t i = indexOf(id);
    require(isFinite(impulse) && isFinite(worldPoint), "impulse and point must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.linearVelocity[i] += bodies_.inverseMass[i] * impulse;
    bodies_.angularVelocity[i] +=
        bodies_.inverseInertiaWorld[i] * glm::cross(worldPoint - bodies_.centerOfMass[i], impulse);
    wakeIndex(i);
}

void World::wake(BodyId id) { wakeIndex(indexOf(id)); }

void World::wakeIndex(std::size_t i) {
    if (bodies_.motion[i] != MotionType::Static) setAwake(i, true);
}

// ---- Live edits of bodies ------------------------------------------------------------------------

float World::friction(BodyId id) const { return bodies_.friction[indexOf(id)]; }
float World::restitution(BodyId id) const { return bodies_.restitution[indexOf(id)]; }
float World::rollingResistance(BodyId id) const { return bodies_.rollingResistance[indexOf(id)]; }
bool World::ccdEnabled(BodyId id) const { return bodies_.ccd[indexOf(id)] != 0; }
float World::density(BodyId id) const { return bodies_.density[indexOf(id)]; }
Mat3 World::localInertia(BodyId id) const { return bodies_.inertiaLocal[indexOf(id)]; }

void World::setMotionType(BodyId id, MotionType motion) {
    const std::size_t i = indexOf(id);
    if (bodies_.motion[i] == motion) return;
    // Checked before anything changes: a shape with no usable mass cannot become dynamic.
    const MassProperties properties =
        bodyMassProperties(bodies_.shape[i], motion, bodies_.massSetting[i], bodies_.density[i]);
    wakeContactPartners(i);  // what rested on it, or was pushed by it, must notice
    bodies_.motion[i] = motion;
    bodies_.setMassProperties(i, properties);  // the centre of mass is the shape's whatever the motion
    bodies_.refreshInverseInertiaWorld(i);
    if (motion == MotionType::Static) {
        bodies_.linearVelocity[i] = Vec3(0.0f);
        bodies_.angularVelocity[i] = Vec3(0.0f);
        bodies_.force[i] = Vec3(0.0f);
        bodies_.torque[i] = Vec3(0.0f);
        bodies_.awake[i] = 0;
        bodies_.sleepTime[i] = 0.0f;
    } else {
        bodies_.awake[i] = 1;
        bodies_.sleepTime[i] = 0.0f;
    }
    // Contacts are made only for pairs with a dynamic body and count towards the cap by the
    // kinds they were made for: they are found again for the new kind.
    renewCollision(i);
}

void World::setShape(BodyId id, const Shape& shape) {
    const std::size_t i = indexOf(id);
    validateShape(shape);
    const MassProperties properties =
        bodyMassProperties(shape, bodies_.motion[i], bodies_.massSetting[i], bodies_.density[i]);
    const Vec3 origin = bodies_.origin(i);
    wakeContactPartners(i);
    bodies_.shape[i] = shape;
    const bool centreMoved = properties.centerOfMass != bodies_.localCenterOfMass[i];
    bodies_.setMassProperties(i, properties);
    // Recomputed only when it moved, so a shape centred like the old one rounds nothing.
    if (centreMoved) bodies_.centerOfMass[i] = origin + bodies_.orientation[i] * properties.centerOfMass;
    bodies_.refreshInverseInertiaWorld(i);
    bodies_.bounds[i] = worldBounds(shape, bodies_.transform(i));
    // The manifolds name the old shape's features, and its fat box may be far larger.
    renewCollision(i);
    wakeIndex(i);
}

void World::setMass(BodyId id, float mass) {
    const std::size_t i = indexOf(id);
    validateMass(mass);
    // Checked as for a dynamic body whatever the motion, so a static body keeps only a mass it can use.
    bodyMassProperties(bodies_.shape[i], MotionType::Dynamic, mass, bodies_.density[i]);
    const MassProperties properties = bodyMassProperties(bodies_.shape[i], bodies_.motion[i], mass, bodies_.density[i]);
    bodies_.massSetting[i] = mass;
    bodies_.setMassProperties(i, properties);
    bodies_.refreshInverseInertiaWorld(i);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setDensity(BodyId id, float density) {
    const std::size_t i = indexOf(id);
    validateDensity(density);
    bodyMassProperties(bodies_.shape[i], MotionType::Dynamic, std::nullopt, density);  // as in setMass
    const MassProperties properties =
        bodyMassProperties(bodies_.shape[i], bodies_.motion[i], std::nullopt, density);
    bodies_.massSetting[i].reset();
    bodies_.density[i] = density;
    bodies_.setMassProperties(i, properties);
    bodies_.refreshInverseInertiaWorld(i);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setFriction(BodyId id, float friction) {
    const std::size_t i = indexOf(id);
    validateFriction(friction);
    bodies_.friction[i] = friction;
    contactManager_.refreshMaterials(id.index, bodies_);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setRestitution(BodyId id, float restitution) {
    const std::size_t i = indexOf(id);
    validateRestitution(restitution);
    bodies_.restitution[i] = restitution;
    contactManager_.refreshMaterials(id.index, bodies_);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setRollingResistance(BodyId id, float coefficient) {
    const std::size_t i = indexOf(id);
    validateRollingResistance(coefficient);
    bodies_.rollingResistance[i] = coefficient;
    contactManager_.refreshMaterials(id.index, bodies_);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setCcd(BodyId id, bool ccd) {
    const std::size_t i = indexOf(id);
    bodies_.ccd[i] = ccd ? 1 : 0;
    wakeIndex(i);
}

void World::setName(BodyId id, const std::string& name) { bodies_.name[indexOf(id)] = name; }

void World::wakeContactPartners(std::size_t i) {
    const std::uint32_t slot = bodies_.idAt(i).index;
    for (const Contact& contact : contactManager_.contacts()) {
        if (contact.slotA == slot) wakeIndex(bodies_.denseIndexOfSlot(contact.slotB));
        else if (contact.slotB == slot) wakeIndex(bodies_.denseIndexOfSlot(contact.slotA));
    }
}

void World::renewCollision(std::size_t i) {
    const std::uint32_t slot = bodies_.idAt(i).index;
    contactManager_.removeContactsOf(slot);
    broadPhase_.removeProxy(bodies_.proxy[i]);
    // As createBody makes it: a new proxy counts as moved, so its pairs come in the next step.
    const bool active = bodies_.motion[i] != MotionType::Static && bodies_.awake[i];
    bodies_.proxy[i] = broadPhase_.addProxy(bodies_.bounds[i], slot, active);
}

// ---- Live edits of joints ------------------------------------------------------------------------

const std::optional<JointLimits>& World::jointLimits(JointId id) const { return joints_.joints[indexOf(id)].limits; }
const std::optional<JointMotor>& World::jointMotor(JointId id) const { return joints_.joints[indexOf(id)].motor; }
const std::optional<JointSpring>& World::jointSpring(JointId id) const { return joints_.joints[indexOf(id)].spring; }
bool World::jointCollidesConnected(JointId id) const { return joints_.joints[indexOf(id)].collideConnected; }
Vec3 World::jointLocalAnchorA(JointId id) const { return joints_.joints[indexOf(id)].localAnchorA; }
Vec3 World::jointLocalAnchorB(JointId id) const { return joints_.joints[indexOf(id)].localAnchorB; }

DistanceLengths World::jointLengths(JointId id) const {
    const Joint& joint = joints_.joints[indexOf(id)];
    return {joint.restLength, joint.minLength, joint.maxLength};
}

void World::setJointLimits(JointId id, const std::optional<JointLimits>& limits) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointLimits(joint.type, limits);
    joint.limits = limits;
    if (!limits) joint.impulses.lower = joint.impulses.upper = 0.0f;  // the rows are gone
    wakeJointBodies(joint);
}

void World::setJointMotor(JointId id, const std::optional<JointMotor>& motor) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointMotor(joint.type, motor);
    joint.motor = motor;
    if (!motor) joint.impulses.motor = 0.0f;
    wakeJointBodies(joint);
}

void World::setJointSpring(JointId id, const std::optional<JointSpring>& spring) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointSpring(joint.type, spring);
    validateJointLengths(joint.type, joint.restLength, spring.has_value(), joint.minLengthSetting, joint.maxLengthSetting);
    // With a spring or without, the axial row means another thing (a spring or a rigid rod).
    if (spring.has_value() != joint.spring.has_value()) joint.impulses.axial = 0.0f;
    joint.spring = spring;
    applyDistanceLengths(joint);
    wakeJointBodies(joint);
}

void World::setJointLengths(JointId id, std::optional<float> minLength, std::optional<float> maxLength) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointLengths(joint.type, joint.restLength, joint.spring.has_value(), minLength, maxLength);
    joint.minLengthSetting = minLength;
    joint.maxLengthSetting = maxLength;
    applyDistanceLengths(joint);
    wakeJointBodies(joint);
}

void World::applyDistanceLengths(Joint& joint) {
    if (joint.type != JointType::Distance) return;  // only a distance joint has lengths
    const DistanceLengths lengths =
        distanceLengths(joint.restLength, joint.spring.has_value(), joint.minLengthSetting, joint.maxLengthSetting);
    joint.minLength = lengths.min;
    joint.maxLength = lengths.max;
    // A bound that is no longer solved must not warm-start (see the joint solver's distance rows).
    const bool range = joint.minLength < joint.maxLength;
    if (!range || !(joint.minLength > 0.0f)) joint.impulses.lower = 0.0f;
    if (!range || !std::isfinite(joint.maxLength)) joint.impulses.upper = 0.0f;
    if (range && !joint.spring) joint.impulses.axial = 0.0f;
}

void World::setJointCollideConnected(JointId id, bool collideConnected) {
    Joint& joint = joints_.joints[indexOf(id)];
    if (joint.collideConnected == collideConnected) return;
    joint.collideConnected = collideConnected;
    if (joint.bodyB.isValid()) {
        if (collideConnected) unfilterJointPair(joint.bodyA, joint.bodyB);
        else filterJointPair(joint.bodyA, joint.bodyB);
    }
    wakeJointBodies(joint);
}

void World::setJointName(JointId id, const std::string& name) { joints_.names[indexOf(id)] = name; }

void World::wakeJointBodies(const Joint& joint) {
    wakeIndex(indexOf(joint.bodyA));
    if (joint.bodyB.isValid()) wakeIndex(indexOf(joint.bodyB));
}

// ---- Queries ---------------------------------------------------------------------------------------

ContactInfo World::contact(std::size_t index) const {
    const Contact& c = contactManager_.contacts().at(index);
    ContactInfo info;
    info.bodyA = bodies_.idAt(bodies_.denseIndexOfSlot(c.slotA));
    info.bodyB = bodies_.idAt(bodies_.denseIndexOfSlot(c.slotB));
    info.friction = c.friction;
    info.restitution = c.restitution;
    info.normal = c.manifold.normal;
    info.pointCount = c.manifold.pointCount;
    info.points = c.manifold.points;
    for (int k = 0; k < kMaxManifoldPoints; ++k) info.normalImpulses[k] = c.impulses[k].normal;
    info.frictionImpulse = c.frictionImpulse.linear;
    return info;
}

double World::kineticEnergy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        const Vec3& v = bodies_.linearVelocity[i];
        const Vec3& w = bodies_.angularVelocity[i];
        const Mat3 r = glm::mat3_cast(bodies_.orientation[i]);
        const Vec3 wLocal = glm::transpose(r) * w;
        energy += 0.5 * bodies_.mass[i] * glm::dot(v, v) +
                  0.5 * glm::dot(wLocal, bodies_.inertiaLocal[i] * wLocal);
    }
    return energy;
}

double World::potentialEnergy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        energy -= static_cast<double>(bodies_.mass[i]) * glm::dot(settings_.gravity, bodies_.centerOfMass[i]);
    }
    return energy;
}

Vec3 World::linearMomentum() const {
    Vec3 p(0.0f);
    for (std::size_t i = 0; i < bodies_.size(); ++i) p += bodies_.mass[i] * bodies_.linearVelocity[i];
    return p;
}

Vec3 World::angularMomentum() const {
    Vec3 l(0.0f);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        const Mat3 r = glm::mat3_cast(bodies_.orientation[i]);
        const Vec3 spin = r * (bodies_.inertiaLocal[i] * (glm::transpose(r) * bodies_.angularVelocity[i]));
        l += glm::cross(bodies_.centerOfMass[i], bodies_.mass[i] * bodies_.linearVelocity[i]) + spin;
    }
    return l;
}

std::optional<WorldRayHit> World::castRay(const Vec3& origin, const Vec3& direction, float maxFraction) const {
    std::optional<WorldRayHit> closest;
    const RayCastInput ray{origin, direction, maxFraction};
    auto testBody = [&](std::size_t i, float currentMax) {
        const RayCastInput clipped{ray.origin, ray.direction, currentMax};
        if (const auto hit = rayCastShape(bodies_.shape[i], bodies_.transform(i), clipped)) {
            closest = WorldRayHit{bodies_.idAt(i), hit->fraction, hit->point, hit->normal};
            return hit->fraction;
        }
        return currentMax;
    };
    if (proxiesStale_) {
        // The broad phase has not followed the bodies (contacts are off): test every body.
        float currentMax = maxFraction;
        for (std::size_t i = 0; i < bodies_.size(); ++i) currentMax = testBody(i, currentMax);
    } else {
        broadPhase_.tree().rayCast(origin, direction, maxFraction, [&](ProxyId proxy, float currentMax) {
            return testBody(bodies_.denseIndexOfSlot(broadPhase_.userData(proxy)), currentMax);
        });
    }
    return closest;
}

std::optional<NonFiniteBody> World::findNonFiniteBody() const {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const char* quantity = nullptr;
        if (!isFinite(bodies_.centerOfMass[i])) quantity = "position";
        else if (!isFinite(bodies_.orientation[i])) quantity = "orientation";
        else if (!isFinite(bodies_.linearVelocity[i])) quantity = "linearVelocity";
        else if (!isFinite(bodies_.angularVelocity[i])) quantity = "angularVelocity";
        if (quantity) return NonFiniteBody{bodies_.idAt(i), bodies_.name[i], quantity};
    }
    return std::nullopt;
}

}  // namespace simcore
