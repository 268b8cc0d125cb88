// The world's life cycle (settings, creating and destroying bodies and joints) and the step with
// its stages. Live edits are in world_edits.cpp, read-only queries in world_queries.cpp.

#include "simcore/world/world.h"

#include "simcore/collision/time_of_impact.h"
#include "simcore/world/validation.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace simcore {

using namespace validation;

World::World(const WorldSettings& settings) { setSettings(settings); }

void World::setSettings(const WorldSettings& settings) {
    validateSettings(settings);
    if (!threads_.configured() || settings.threads != settings_.threads) threads_.configure(settings.threads);
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

World::Activity World::scanActivity() const {
    Activity activity;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] == MotionType::Static || !bodies_.awake[i]) continue;
        activity.anyAwakeMoving = true;
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
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

// One step: the stages of kStages (stages.h), in that order; docs/architecture.md says what each
// does and when it is skipped. Each runs only when the plan says so, and is timed as it runs.
void World::step() {
    const auto stepStart = std::chrono::steady_clock::now();
    StepProfile profile;
    StepPlan plan = planStep(profile.skipped);
    profile.withWorkers = threads_.startStep();
    const auto run = [&profile, this](Stage stage, auto&& work) {
        const auto s = static_cast<std::size_t>(stage);
        if (profile.skipped[s] != StageSkip::Ran) return;
        const std::uint64_t offered = threads_.pool().jobsOffered();
        {
            ScopedStageTimer timer(profile.stageMs[s]);
            work();
        }
        profile.handOvers[s] += static_cast<std::uint32_t>(threads_.pool().jobsOffered() - offered);
    };
    const float h = plan.substepDt;

    run(Stage::Pairs, [&] {
        profile.counters.droppedPairs = static_cast<std::uint32_t>(updateBroadPhase(settings_.timeStep));
        proxiesStale_ = false;
    });
    run(Stage::Collide, [&] { updateContacts(); });
    run(Stage::Islands, [&] { buildIslandsAndWake(); });
    run(Stage::Prepare, [&] { prepareConstraints(plan); });
    planSolve(plan, profile.skipped);
    for (int substep = 0; substep < settings_.substeps; ++substep) {
        run(Stage::IntegrateVelocities, [&] {
            profile.counters.boundedVelocities += integrator_.integrateVelocities(bodies_, settings_.integrator, plan.velocity, h, threads_.pool());
        });
        if (substep == 0) run(Stage::Restitution, [&] { contactSolver_.resolveCollisions(bodies_, ContactSolver::ImpactTiming::BeforePositions); });
        run(Stage::WarmStart, [&] { warmStart(plan); });
        run(Stage::Solve, [&] { solveVelocities(plan); });
        run(Stage::IntegratePositions, [&] {
            profile.counters.boundedVelocities += integrator_.integratePositions(bodies_, settings_.integrator, h, threads_.pool());
            if (plan.solveContacts) contactSolver_.followPositions(bodies_);
        });
        // Before relax, which would slow a body about to hit down to the speed that just closes the
        // gap (speculative contact) and so take away the impact the bounce needs.
        run(Stage::Restitution, [&] { contactSolver_.resolveCollisions(bodies_, ContactSolver::ImpactTiming::AfterPositions); });
        run(Stage::Relax, [&] { relaxConstraints(plan); });
    }
    run(Stage::StoreImpulses, [&] { storeImpulses(plan, profile.counters); });
    run(Stage::Continuous, [&] {
        if (sweepFastBodies()) countEffect(Effect::Ccd);
        else profile.skipped[static_cast<std::size_t>(Stage::Continuous)] = StageSkip::NoFastBody;
    });
    run(Stage::Sleep, [&] { sleepRestingIslands(plan); });

    finishStep(plan, profile);
    threads_.learn(profile);
    profile.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stepStart).count();
    lastProfile_ = profile;
}

World::StepPlan World::planStep(StageSkips& skipped) const {
    StepPlan plan;
    plan.activity = scanActivity();
    plan.gravity = needs(Effect::Gravity, plan.activity);
    plan.damping = needs(Effect::Damping, plan.activity);
    plan.gyroscopic = needs(Effect::Gyroscopic, plan.activity);
    plan.contacts = needs(Effect::Contacts, plan.activity);
    plan.joints = needs(Effect::Joints, plan.activity);
    plan.sleeping = needs(Effect::Sleeping, plan.activity);
    plan.continuous = needs(Effect::Ccd, plan.activity);

    plan.substepDt = settings_.timeStep / static_cast<float>(settings_.substeps);
    plan.velocity.gravity = plan.gravity ? settings_.gravity : Vec3(0.0f);
    plan.velocity.gyroscopic = plan.gyroscopic;
    if (plan.damping) {
        plan.velocity.linearRetention = std::exp(-settings_.damping.linear * plan.substepDt);
        plan.velocity.angularRetention = std::exp(-settings_.damping.angular * plan.substepDt);
    }

    const StageSkip noContacts = !settings_.effects[Effect::Contacts] ? StageSkip::ContactsOff
                                 : !plan.activity.anyAwakeDynamic     ? StageSkip::NothingAwake
                                 : bodies_.size() <= 1                ? StageSkip::SingleBody
                                                                      : StageSkip::Ran;
    const StageSkip nothingToSolve = plan.contacts || plan.joints    ? StageSkip::Ran
                                     : !plan.activity.anyAwakeDynamic ? StageSkip::NothingAwake
                                                                      : StageSkip::NothingToSolve;
    skipped.fill(StageSkip::Ran);
    auto skip = [&skipped](Stage stage, StageSkip why) { skipped[static_cast<std::size_t>(stage)] = why; };
    // Sleeping and static bodies are not integrated; a world where nothing else is left costs only
    // this scan.
    const StageSkip nothingMoves = plan.activity.anyAwakeMoving ? StageSkip::Ran : StageSkip::NothingMoves;
    skip(Stage::IntegrateVelocities, nothingMoves);
    skip(Stage::IntegratePositions, nothingMoves);
    skip(Stage::Pairs, noContacts);
    skip(Stage::Collide, noContacts);
    skip(Stage::Islands, nothingToSolve);
    skip(Stage::Prepare, nothingToSolve);
    skip(Stage::Continuous, !settings_.effects[Effect::Ccd] ? StageSkip::CcdOff : noContacts);
    skip(Stage::Sleep, plan.sleeping                                                    ? StageSkip::Ran
                       : !settings_.effects[Effect::Sleeping] || !settings_.sleep.enabled ? StageSkip::SleepOff
                                                                                          : StageSkip::NothingAwake);
    return plan;
}

void World::planSolve(StepPlan& plan, StageSkips& skipped) const {
    plan.solveContacts = plan.contacts && contactSolver_.constraintCount() > 0;
    // Joints are always soft, so they always relax; contacts only under soft step.
    plan.relaxContacts = plan.solveContacts && settings_.solver.positionCorrection == PositionCorrection::SoftStep;
    plan.solveJoints = plan.joints && jointSolver_.constraintCount() > 0;
    plan.bounce = plan.solveContacts && contactSolver_.usesRestitution();

    const StageSkip prepared = skipped[static_cast<std::size_t>(Stage::Prepare)];
    const StageSkip noConstraint = prepared != StageSkip::Ran ? prepared : StageSkip::NoConstraint;
    const bool anyConstraint = plan.solveContacts || plan.solveJoints;
    auto skip = [&skipped](Stage stage, StageSkip why) { skipped[static_cast<std::size_t>(stage)] = why; };
    skip(Stage::WarmStart, anyConstraint ? StageSkip::Ran : noConstraint);
    skip(Stage::Solve, anyConstraint ? StageSkip::Ran : noConstraint);
    skip(Stage::Restitution, plan.bounce                                  ? StageSkip::Ran
                             : !settings_.effects[Effect::Restitution]      ? StageSkip::RestitutionOff
                             : !plan.solveContacts                          ? noConstraint
                                                                            : StageSkip::NoBouncyContact);
    skip(Stage::Relax, plan.relaxContacts || plan.solveJoints ? StageSkip::Ran
                       : anyConstraint                         ? StageSkip::Baumgarte
                                                               : noConstraint);
    skip(Stage::StoreImpulses, anyConstraint ? StageSkip::Ran : noConstraint);
}

void World::prepareConstraints(const StepPlan& plan) {
    if (plan.contacts) {
        ContactSolver::Params params;
        params.substepDt = plan.substepDt;
        params.timeStep = settings_.timeStep;
        params.friction = settings_.effects[Effect::Friction];
        params.restitution = settings_.effects[Effect::Restitution];
        params.gravity = plan.velocity.gravity;
        params.solver = settings_.solver;
        params.contact = settings_.contact;
        contactSolver_.prepare(contactManager_, bodies_, joints_, params, threads_.pool());
    }
    if (plan.joints) jointSolver_.prepare(joints_, bodies_, {plan.substepDt, settings_.joint});
    // The poses continuous collision sweeps from (it runs only with contacts, so only with this stage).
    if (plan.continuous) recordSweepStarts();
}

// In each pass joints go first and contacts have the last word (Box2D v3's order): penetration
// shows more than joint stretch.
void World::warmStart(const StepPlan& plan) {
    if (plan.solveJoints) jointSolver_.warmStart(bodies_);
    if (plan.solveContacts)
        contactSolver_.warmStart(bodies_, plan.solveJoints ? ContactSolver::AfterWarmStart::Store
                                                           : ContactSolver::AfterWarmStart::HoldForSolve);
}

namespace {

// Up to `passes` contact passes, `contactPasses(n)` running n of them and saying whether to go on:
// with joints one at a time, each after a joint pass (contact-only passes tear a chain's joints);
// without, all in one call.
template <class ContactPasses>
void interleaveWithJoints(bool withJoints, JointSolver& jointSolver, BodyStorage& bodies, bool useBias, int passes,
                          ContactPasses&& contactPasses) {
    const int passesPerCall = withJoints ? 1 : passes;
    for (int done = 0; done < passes; done += passesPerCall) {
        if (withJoints) jointSolver.solve(bodies, useBias);
        if (!contactPasses(passesPerCall)) return;
    }
}

}  // namespace

void World::solveVelocities(const StepPlan& plan) {
    interleaveWithJoints(plan.solveJoints, jointSolver_, bodies_, true, settings_.solver.velocityIterations,
                         [&](int passes) {
                             if (plan.solveContacts) contactSolver_.solve(bodies_, true, passes);
                             return true;
                         });
}

void World::relaxConstraints(const StepPlan& plan) {
    bool pushLeft = false;
    interleaveWithJoints(plan.solveJoints, jointSolver_, bodies_, false, settings_.solver.positionIterations,
                         [&](int passes) {
                             if (plan.relaxContacts) pushLeft = contactSolver_.solve(bodies_, false, passes);
                             return true;
                         });
    if (pushLeft)
        interleaveWithJoints(plan.solveJoints, jointSolver_, bodies_, false, ContactSolver::kMaxExtraRelaxPasses,
                             [&](int passes) { return contactSolver_.relaxWherePushing(bodies_, passes); });
    if (plan.relaxContacts) contactSolver_.settleOnSupports(bodies_);
}

void World::storeImpulses(const StepPlan& plan, StepCounters& counters) {
    // Joints are the one source that can pass the bound within a step (a torn assembly, in its
    // last relax passes), so only they pay for holding the state between steps to it.
    if (plan.solveJoints) counters.boundedVelocities += integrator_.boundVelocities(bodies_, plan.substepDt);
    if (plan.solveContacts) contactSolver_.storeImpulses(contactManager_);
}

void World::sleepRestingIslands(const StepPlan& plan) {
    if (!plan.contacts && !plan.joints) islands_.build(bodies_, contactManager_.contacts(), joints_);
    islands_.sleepRestingIslands(bodies_, settings_.sleep, settings_.timeStep, [this](std::size_t i) { setAwake(i, false); });
}

void World::finishStep(const StepPlan& plan, StepProfile& profile) {
    clearAppliedForces();
    proxiesStale_ = proxiesStale_ || (!plan.contacts && plan.activity.anyAwakeDynamic);

    if (plan.gravity) countEffect(Effect::Gravity);
    if (plan.damping) countEffect(Effect::Damping);
    if (plan.gyroscopic) countEffect(Effect::Gyroscopic);
    if (plan.contacts) countEffect(Effect::Contacts);
    if (plan.solveJoints) countEffect(Effect::Joints);
    if (plan.solveContacts && contactSolver_.usesFriction()) countEffect(Effect::Friction);
    if (plan.bounce) countEffect(Effect::Restitution);
    if (plan.sleeping) countEffect(Effect::Sleeping);

    StepCounters& counters = profile.counters;
    counters.bodies = static_cast<std::uint32_t>(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] == MotionType::Dynamic) ++counters.dynamicBodies;
        if (bodies_.awake[i]) ++counters.awakeBodies;
    }
    const std::vector<Contact>& contacts = contactManager_.contacts();
    counters.pairs = static_cast<std::uint32_t>(contacts.size());
    // Each touching pair's record is a cache miss (20 540 of them in pyramid20: 0.08 ms on one
    // thread), so the count runs on the pool, as the last stage left it; manifolds in the high half
    // of each chunk's sum, points in the low.
    constexpr std::size_t kCountGrain = 1024;
    const std::uint64_t touching = threads_.pool().parallelSum(contacts.size(), kCountGrain, [&](std::size_t begin, std::size_t end) {
        std::uint64_t sum = 0;
        for (std::size_t c = begin; c < end; ++c)
            if (contacts[c].hasPoints()) sum += (std::uint64_t{1} << 32) + contactManager_.manifoldOf(contacts[c]).manifold.pointCount;
        return sum;
    });
    counters.manifolds = static_cast<std::uint32_t>(touching >> 32);
    counters.contactPoints = static_cast<std::uint32_t>(touching);
    counters.islands = plan.contacts || plan.joints ? islands_.awakeIslandCount() : 0;
    profile.maxPenetration = plan.solveContacts ? contactSolver_.maxPenetration() : 0.0f;

    ++stepCount_;
    simulatedTime_ += settings_.timeStep;
}

void World::clearAppliedForces() {
    std::fill(bodies_.force.begin(), bodies_.force.end(), Vec3(0.0f));
    std::fill(bodies_.torque.begin(), bodies_.torque.end(), Vec3(0.0f));
}

std::size_t World::updateBroadPhase(float dt) {
    // Bodies per chunk of the bounds update: each costs tens of nanoseconds (a hull's, more).
    constexpr std::size_t kBoundsGrain = 256;
    const auto moves = [this](std::size_t i) { return bodies_.motion[i] != MotionType::Static && bodies_.awake[i]; };
    // Each body's bounds from its own pose: in parallel. The tree is shared: its updates at once,
    // then its queries for the moved proxies' pairs in parallel again.
    threads_.pool().parallelFor(bodies_.size(), kBoundsGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            if (moves(i)) bodies_.bounds[i] = worldBounds(bodies_.shape[i], bodies_.transform(i));
    });
    proxyMoves_.clear();
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (!moves(i)) continue;
        const Vec3 displacement = dt * bodies_.linearVelocity[i];
        if (broadPhase_.leavesFatBox(bodies_.proxy[i], bodies_.bounds[i], displacement))
            proxyMoves_.push_back({bodies_.proxy[i], bodies_.bounds[i], displacement});
    }
    broadPhase_.moveProxies(proxyMoves_);
    broadPhase_.updatePairs(newPairs_, threads_.pool());
    // Jointed bodies do not collide unless their joint asks for it (collideConnected).
    if (jointFilteredPairs_.size() > 0) {
        std::erase_if(newPairs_, [this](const BodyPair& pair) {
            return jointFilteredPairs_.find(PairTable::key(pair.a, pair.b)) != PairTable::kNotFound;
        });
    }
    return contactManager_.addPairs(newPairs_, bodies_, settings_.contact.maxContactsPerBody);
}

void World::updateContacts() {
    // A manifold is made again once its pair has moved against itself by a tenth of the slop
    // (0.5 mm at the defaults): its points are then at most that far from where fresh clipping
    // would put them, an error well inside what the slop already lets a contact overlap.
    constexpr float kManifoldReuseSlopFraction = 0.1f;
    contactManager_.updateManifolds(bodies_, broadPhase_, settings_.contact.speculativeDistance,
                                    kManifoldReuseSlopFraction * settings_.contact.linearSlop, settings_.timeStep,
                                    threads_.pool());
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
    constexpr std::size_t kCheckGrain = 512;  // bodies per chunk of finding the fast ones: ~10 ns each
    const float target = settings_.contact.linearSlop;
    const auto sweepOf = [this](std::size_t i) {
        return Sweep{bodies_.localCenterOfMass[i], sweepStartCenter_[i], bodies_.centerOfMass[i],
                     sweepStartRotation_[i], bodies_.orientation[i]};
    };
    const auto thinOf = [](const Shape& shape) { return kFastFraction * minimumExtent(shape); };
    // Which bodies are fast reads each body alone: on the pool (most steps find none). The sweeps
    // then run in body order, since a flagged body sweeps against the others' end poses, which
    // putting one back changes.
    fastBody_.resize(bodies_.size());
    const std::uint64_t fastCount =
        threads_.pool().parallelSum(bodies_.size(), kCheckGrain, [&](std::size_t begin, std::size_t end) {
            std::uint64_t count = 0;
            for (std::size_t i = begin; i < end; ++i) {
                bool fast = false;
                if (bodies_.isAwakeDynamic(i)) {
                    const Sweep sweep = sweepOf(i);
                    const float travel = glm::length(sweep.center1 - sweep.center0) +
                                         sweep.rotationAngle() * glm::length(bodies_.bounds[i].halfExtents());
                    fast = bodies_.ccd[i] || travel > thinOf(bodies_.shape[i]);
                }
                fastBody_[i] = fast;
                count += fast ? 1 : 0;
            }
            return count;
        });
    if (fastCount == 0) return false;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (!fastBody_[i]) continue;
        const Sweep sweep = sweepOf(i);
        const Shape& shape = bodies_.shape[i];
        const float thin = thinOf(shape);
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
    return true;
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

void World::wakeIndex(std::size_t i) {
    if (bodies_.motion[i] != MotionType::Static) setAwake(i, true);
}

}  // namespace simcore
