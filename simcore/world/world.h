#pragma once
// The world: bodies, settings, and the step. World::step is the one place that says what a step
// does, in order; see world.cpp.

#include "simcore/collision/broad_phase.h"
#include "simcore/dynamics/contact_manager.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/dynamics/contact_solver.h"
#include "simcore/dynamics/integrator.h"
#include "simcore/dynamics/islands.h"
#include "simcore/dynamics/joint_solver.h"
#include "simcore/dynamics/joint_storage.h"
#include "simcore/parallel/task_pool.h"
#include "simcore/parallel/worker_tuner.h"
#include "simcore/world/profiler.h"
#include "simcore/world_settings.h"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace simcore {

class DebugDraw;
struct DebugDrawOptions;

// Which effects actually ran, counted over steps (an effect that is enabled but not needed by
// anything in the world is skipped and not counted).
struct EffectUsage {
    std::array<std::uint64_t, kEffectCount> stepsRun{};
    bool ran(Effect e) const { return stepsRun[static_cast<int>(e)] > 0; }
};

struct WorldRayHit {
    BodyId body;
    float fraction = 0.0f;  // along the ray: point = origin + fraction * direction
    Vec3 point{0.0f};       // world frame (m)
    Vec3 normal{0.0f};      // unit, outward from the body at the point
    std::uint32_t subShape = 0;  // which of the body's sub-shapes (shape.h): a compound's child, a surface's triangle
};

// A persistent contact as the engine's public API shows it (touching or speculative).
struct ContactInfo {
    BodyId bodyA, bodyB;
    std::uint32_t subShapeA = 0, subShapeB = 0;  // the sub-shapes touching (shape.h): compound children
    float friction = 0.0f;     // combined coefficient
    float restitution = 0.0f;  // combined coefficient
    Vec3 normal{0.0f};         // unit, world frame, from A towards B (zero while pointCount is 0)
    int pointCount = 0;        // 0 while the bodies' fat boxes overlap but the shapes are apart
    std::array<ContactPoint, kMaxManifoldPoints> points{};
    std::array<float, kMaxManifoldPoints> normalImpulses{};  // N s, accumulated (warm start)
    Vec3 frictionImpulse{0.0f};                              // N s, accumulated, in the contact plane
};

// The contacts touching one body and what they carry (ContactInfo summed over the body's manifolds).
struct ContactLoad {
    int contacts = 0;          // touching manifolds (at least one point) with other bodies
    float normalForce = 0.0f;  // N: their points' normal impulses over the last substep, per second
};

// The world's worker threads, and whether a step uses them, learnt from the steps' times
// (WorkerTuner). A step uses them in every stage or in none: a stage run with workers leaves its
// data in both cores' caches for the next, so stages tuned one by one judged each other's moves
// (pyramid10 at 2 threads, 2-core machine, 2026-12-06: 1.18x the time of 1 thread stage by stage,
// 1.02x with the step's own choice), and kept stages inline that gained with workers (the first
// 100 steps of mixed1k at 2 threads, against 1 thread's, medians of 74 alternating rounds with the
// cores near, 2026-12-07: 0.72 with the stages tuned under the step, 0.69 with every stage the
// step's way; pile1k 0.67 and 0.66).
// A copied world gets a pool of its own with as many threads, made when it first steps, and learns
// anew: a copy kept as a snapshot holds no threads.
class WorldThreads {
public:
    WorldThreads() = default;
    WorldThreads(const WorldThreads& other) : threads_(other.threads_) {}
    WorldThreads& operator=(const WorldThreads& other) {
        if (this != &other) {
            threads_ = other.threads_;
            pool_.reset();
            forgetTimings();
        }
        return *this;
    }
    WorldThreads(WorldThreads&&) noexcept = default;
    WorldThreads& operator=(WorldThreads&&) noexcept = default;

    bool configured() const { return threads_.has_value(); }
    int threads() const { return threads_.value_or(1); }
    // Starts the workers now, not in the first step: starting a thread took about 0.2 ms, which a
    // tower of 40 (5 us a step) paid back over hundreds of steps. A copy starts its own in its
    // first step: the timeline keeps copies of the world as keyframes, and most never step.
    void configure(int threads) {
        threads_ = threads;
        pool_ = std::make_unique<TaskPool>(threads);
        forgetTimings();
    }
    TaskPool& pool() const {
        if (!pool_) pool_ = std::make_unique<TaskPool>(threads());
        return *pool_;
    }

    // Sets on the pool whether this step's stages run with workers, and returns it.
    bool startStep() const {
        const bool withWorkers = pool().threadCount() > 1 && tuner_.useWorkers();
        pool().setWorkersEnabled(withWorkers);
        return withWorkers;
    }
    // After a step: what its stages took, as they ran; outside a step the workers are on again.
    void learn(const StepProfile& profile) {
        TaskPool& workers = pool();
        // A step with no job the workers could have shared ran the same either way and teaches
        // nothing: a tower's, whose jobs are all too narrow to share (learning from its steps cost
        // tower20 about 0.1 us of its 15 us step).
        const bool anySharable = workers.sharableJobs() != sharableJobsSeen_;
        sharableJobsSeen_ = workers.sharableJobs();
        if (workers.threadCount() > 1 && anySharable) {
            double stepMs = 0.0;
            bool anyRan = false;
            for (std::size_t s = 0; s < kStageCount; ++s) {
                if (profile.skipped[s] != StageSkip::Ran) continue;
                stepMs += profile.stageMs[s];
                anyRan = true;
            }
            // A step in which no stage ran (everything asleep) says nothing about either way.
            if (anyRan) tuner_.record(stepMs);
        }
        workers.setWorkersEnabled(true);
    }

private:
    void forgetTimings() {
        tuner_ = WorkerTuner(kFirstWay);
        sharableJobsSeen_ = pool_ ? pool_->sharableJobs() : 0;
    }
    std::optional<int> threads_;                 // settings.threads (0: one per core)
    mutable std::unique_ptr<TaskPool> pool_;
    // Workers first: a world's first step makes every pair and manifold (pyramid20: 45-70 ms, then
    // about 12), and its narrow phase and batches then fill on every core.
    static constexpr WorkerTuner::FirstWay kFirstWay = WorkerTuner::FirstWay::Workers;
    WorkerTuner tuner_{kFirstWay};
    std::uint64_t sharableJobsSeen_ = 0;         // the pool's sharableJobs() after the last step
};

struct NonFiniteBody {
    BodyId id;
    std::string name;
    std::string quantity;  // "position", "orientation", "linearVelocity", "angularVelocity"
};

class World {
public:
    explicit World(const WorldSettings& settings = {});
    // A copy holds the whole state (bodies, contacts with their warm starts, joints, the broad
    // phase's tree, sleep timers, counters), so stepping it gives the bits the original would.
    World(const World&) = default;
    World& operator=(const World&) = default;
    World(World&&) noexcept = default;
    World& operator=(World&&) noexcept = default;

    const WorldSettings& settings() const { return settings_; }
    void setSettings(const WorldSettings& settings);  // throws std::invalid_argument naming the bad field

    // Throws std::invalid_argument naming the bad field (non-finite value, non-positive size or
    // mass, degenerate orientation, ...).
    BodyId createBody(const BodyCreationSettings& settings);
    void destroyBody(BodyId id);
    bool contains(BodyId id) const { return bodies_.denseIndex(id) >= 0; }
    std::size_t bodyCount() const { return bodies_.size(); }
    std::vector<BodyId> bodyIds() const;  // in dense (creation, modulo removals) order

    // Joints hold two bodies together (or one to the world); destroying a body destroys its
    // joints. Jointed bodies do not collide with each other unless collideConnected is set.
    // createJoint throws std::invalid_argument naming the bad field (unknown body, the same body
    // twice, non-finite anchor, zero axis, limits.lower > limits.upper, ...).
    JointId createJoint(const JointCreationSettings& settings);
    void destroyJoint(JointId id);
    bool contains(JointId id) const { return joints_.denseIndex(id) >= 0; }
    std::size_t jointCount() const { return joints_.size(); }
    std::vector<JointId> jointIds() const;  // in dense (creation, modulo removals) order
    JointType jointType(JointId id) const;
    BodyId jointBodyA(JointId id) const;
    BodyId jointBodyB(JointId id) const;  // invalid for a joint to the world
    const std::string& jointName(JointId id) const;
    const std::optional<JointLimits>& jointLimits(JointId id) const;
    const std::optional<JointMotor>& jointMotor(JointId id) const;
    const std::optional<JointSpring>& jointSpring(JointId id) const;
    DistanceLengths jointLengths(JointId id) const;  // a distance joint's rest length and limits in effect
    bool jointCollidesConnected(JointId id) const;
    // The joint's points in its bodies' frames (from each centre of mass; the world's: world frame).
    Vec3 jointLocalAnchorA(JointId id) const;
    Vec3 jointLocalAnchorB(JointId id) const;

    // Live edits of a joint's parameters (as Box2D v3's b2RevoluteJoint_SetLimits...). Each
    // validates like createJoint (the same messages and limits), keeps the rest pose taken at
    // creation (limits still count from it, a distance joint's rest length stays), wakes both
    // bodies, and keeps the accumulated impulses of the rows that remain.
    void setJointLimits(JointId id, const std::optional<JointLimits>& limits);
    void setJointMotor(JointId id, const std::optional<JointMotor>& motor);
    void setJointSpring(JointId id, const std::optional<JointSpring>& spring);
    // Unset: the rest length without a spring, unbounded with one (as in JointCreationSettings).
    void setJointLengths(JointId id, std::optional<float> minLength, std::optional<float> maxLength);
    void setJointCollideConnected(JointId id, bool collideConnected);
    void setJointName(JointId id, const std::string& name);
    // Where the joint holds its bodies, in world coordinates at their current poses, as
    // JointCreationSettings reads them (anchor; a hinge's or slider's axis; a distance joint's
    // anchorB, whose distance from anchor becomes the rest length). The rest rotation stays the
    // one taken at creation, so hinge angles and slides still count from it.
    void setJointFrame(JointId id, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB);

    // How far the joint is from satisfied now: worst position (m) and angle (rad) error.
    JointError jointError(JointId id) const;
    // The largest position and the largest angle error over all joints (each its own maximum).
    JointError worstJointError() const;

    // Advances the world by settings().timeStep.
    void step();

    // Body state (origin and orientation as authored; velocities of the centre of mass).
    Vec3 position(BodyId id) const;
    Quat orientation(BodyId id) const;
    Vec3 centerOfMass(BodyId id) const;
    Vec3 linearVelocity(BodyId id) const;
    Vec3 angularVelocity(BodyId id) const;
    bool isAwake(BodyId id) const;
    const std::string& name(BodyId id) const;
    const Shape& shape(BodyId id) const;
    MotionType motionType(BodyId id) const;
    float mass(BodyId id) const;

    float friction(BodyId id) const;
    float restitution(BodyId id) const;
    float rollingResistance(BodyId id) const;
    bool ccdEnabled(BodyId id) const;
    float density(BodyId id) const;       // kg/m^3; what the mass follows from unless it was given
    Mat3 localInertia(BodyId id) const;   // kg m^2 about the centre of mass, body axes; zero unless dynamic

    // Live edits of a body's properties (as Box2D v3's b2Body_SetType, b2Shape_SetFriction...).
    // Each validates like createBody (std::invalid_argument naming the field; nothing changes on
    // refusal), wakes the body and the bodies it touches, and keeps what the change allows: a
    // material or mass change keeps the contacts and their accumulated impulses (warm starts);
    // a motion type or shape change drops the body's contacts (they were made for the old kind of
    // pair, or the old shape's features) and the broad phase finds them again in the next step.
    void setMotionType(BodyId id, MotionType motion);
    void setShape(BodyId id, const Shape& shape);  // the body's origin stays; its centre of mass follows the shape
    void setMass(BodyId id, float mass);           // kg; the inertia scales with it
    void setDensity(BodyId id, float density);     // kg/m^3: the mass follows from the shape's volume
    void setFriction(BodyId id, float friction);
    void setRestitution(BodyId id, float restitution);
    void setRollingResistance(BodyId id, float coefficient);
    void setCcd(BodyId id, bool ccd);
    void setName(BodyId id, const std::string& name);  // does not wake

    // Edits wake the body.
    void setTransform(BodyId id, const Vec3& position, const Quat& orientation);
    void setLinearVelocity(BodyId id, const Vec3& velocity);
    void setAngularVelocity(BodyId id, const Vec3& velocity);
    // A force or torque acts over the next step, in every substep, and is cleared when it ends:
    // a constant one is added before every step.
    void addForce(BodyId id, const Vec3& force);                      // at the centre of mass (N)
    void addTorque(BodyId id, const Vec3& torque);                    // N m
    void addImpulse(BodyId id, const Vec3& impulse, const Vec3& worldPoint);  // N s, applied now
    void wake(BodyId id);

    // Energies of dynamic bodies (J); potential is relative to the origin along gravity.
    double kineticEnergy() const;
    double kineticEnergy(BodyId id) const;  // of one body (J): translation and rotation; 0 unless dynamic
    double potentialEnergy() const;
    Vec3 linearMomentum() const;
    Vec3 angularMomentum() const;  // about the world origin

    std::optional<NonFiniteBody> findNonFiniteBody() const;

    // Closest body hit by the ray origin + t * direction, t in [0, maxFraction]. Rays starting
    // inside a body do not hit it. Candidates come from the broad phase.
    std::optional<WorldRayHit> castRay(const Vec3& origin, const Vec3& direction, float maxFraction = 1.0f) const;

    // Hands the bodies, bounds, contacts and joints the options ask for to `drawer` (debug_draw.h).
    void draw(DebugDraw& drawer, const DebugDrawOptions& options) const;

    const StepProfile& lastStepProfile() const { return lastProfile_; }
    const EffectUsage& effectUsage() const { return effectUsage_; }
    std::uint64_t stepCount() const { return stepCount_; }
    double simulatedTime() const { return simulatedTime_; }

    // Persistent contacts in the engine's order; index < contactCount(). The order changes as
    // contacts come and go.
    std::size_t contactCount() const { return contactManager_.contacts().size(); }
    ContactInfo contact(std::size_t index) const;
    // The touching contacts between `id` and other bodies, and the normal force they carry. The
    // accumulated impulses are those of the last substep, so they are divided by its length.
    ContactLoad contactLoad(BodyId id) const;

private:
    // The one way past the public API: tests inject faults (a NaN, as an engine bug would leave
    // one) that no setter accepts. Defined only in tests.
    friend struct WorldFaultInjection;

    // What the awake bodies are doing, gathered once per step to decide which effects run.
    struct Activity {
        bool anyAwakeMoving = false;  // an awake dynamic or kinematic body
        bool anyAwakeDynamic = false;
        bool anySpinning = false;
    };
    Activity scanActivity() const;
    bool needs(Effect effect, const Activity& activity) const;

    // What one step runs, decided before its first stage (the solver's stages once the
    // constraints are prepared); the stages it leaves out get their reason in StepProfile::skipped.
    struct StepPlan {
        Activity activity;
        bool gravity = false, damping = false, gyroscopic = false, contacts = false, joints = false;
        bool sleeping = false, continuous = false;
        bool solveContacts = false, solveJoints = false, relaxContacts = false, bounce = false;
        float substepDt = 0.0f;  // s
        VelocityIntegration velocity;
    };
    using StageSkips = std::array<StageSkip, kStageCount>;
    StepPlan planStep(StageSkips& skipped) const;
    void planSolve(StepPlan& plan, StageSkips& skipped) const;  // after Stage::Prepare
    // The stages of step() that are more than one call, in order.
    void prepareConstraints(const StepPlan& plan);
    void warmStart(const StepPlan& plan);
    void solveVelocities(const StepPlan& plan);
    void relaxConstraints(const StepPlan& plan);
    void storeImpulses(const StepPlan& plan, StepCounters& counters);
    void sleepRestingIslands(const StepPlan& plan);
    void finishStep(const StepPlan& plan, StepProfile& profile);  // effects counted, forces cleared, counters
    std::size_t updateBroadPhase(float dt);  // returns the pairs refused by the contact cap
    void updateContacts();
    void recordSweepStarts();
    bool sweepFastBodies();
    void setAwake(std::size_t i, bool awake);
    void countEffect(Effect effect) { ++effectUsage_.stepsRun[static_cast<int>(effect)]; }
    double kineticEnergyAt(std::size_t i) const;  // body at dense index i (J)
    std::size_t indexOf(BodyId id) const;  // dense index; throws std::out_of_range for a stale id
    std::size_t indexOf(JointId id) const;
    void buildIslandsAndWake();            // islands over contacts and joints; touched islands wake
    void clearAppliedForces();             // the step is over: added forces and torques are spent
    void wakeIndex(std::size_t i);
    void wakeContactPartners(std::size_t i);  // the bodies body i touches
    // Body i's friction, restitution or rolling resistance changed: its contacts combine them
    // anew, keeping their impulses, and the bodies it touches wake to feel it.
    void materialChanged(std::size_t i);
    // After a change of what body i is (motion type, shape): its contacts go, and its proxy is
    // made anew so the next broad phase pairs it as a new body.
    void renewCollision(std::size_t i);
    // Jointed bodies that do not collide: counted per pair, as several joints may filter one.
    void filterJointPair(BodyId a, BodyId b);
    void unfilterJointPair(BodyId a, BodyId b);
    void wakeJointBodies(const Joint& joint);
    // A distance joint's effective limits from its settings, with the impulses of dropped bounds cleared.
    static void applyDistanceLengths(Joint& joint);

    WorldSettings settings_;
    WorldThreads threads_;  // settings_.threads threads
    BodyStorage bodies_;
    BodyIntegrator integrator_;
    BroadPhase broadPhase_;
    ContactManager contactManager_;
    ContactSolver contactSolver_;
    Islands islands_;
    JointStorage joints_;
    JointSolver jointSolver_;
    PairTable jointFilteredPairs_;    // body-slot pair -> how many joints keep the two from colliding
    std::vector<BodyPair> newPairs_;  // scratch, reused every step
    std::vector<DynamicAabbTree::ProxyMove> proxyMoves_;  // scratch: bodies that left their fat boxes
    std::vector<std::uint8_t> fastBody_;                  // scratch: by body, 1 where continuous collision sweeps it
    std::vector<Vec3> sweepStartCenter_;     // scratch: awake bodies' poses at the start of the step,
    std::vector<Quat> sweepStartRotation_;   // for continuous collision
    bool proxiesStale_ = false;       // bodies moved while the broad phase did not run
    StepProfile lastProfile_;
    EffectUsage effectUsage_;
    std::uint64_t stepCount_ = 0;
    double simulatedTime_ = 0.0;
};

}  // namespace simcore
