#pragma once
// Sequential impulses on joints, in the same soft step as the contact solver: accumulated
// impulses per row (a joint's rigid rows solved together as one block), warm started from the
// previous step;
// rigid rows are soft constraints (joint hertz and damping ratio) while the bias is on and rigid
// without it (the relax passes); limits are one-sided rows met speculatively, motors are rows
// clamped to their maximum force, and a distance spring is a soft row of its own stiffness.
//
// Within one World::step the solver is used as the contact solver is:
//   prepare (once) -> for each substep { warmStart, solve(useBias=true) x N, [positions move],
//   relax = solve(useBias=false) x M }. Impulses live in the joints, so nothing is stored after.
// solve(useBias=true) must follow warmStart with no position change between.

#include "simcore/dynamics/body_storage.h"
#include "simcore/dynamics/constraint_math.h"
#include "simcore/dynamics/joint_storage.h"
#include "simcore/world_settings.h"

#include <vector>

namespace simcore {

class JointSolver {
public:
    struct Params {
        float substepDt = 1.0f / 240.0f;
        JointSettings joint;
    };

    // Builds a constraint for every joint with an awake dynamic body; sleeping, static and
    // kinematic bodies (and the world) take part with infinite mass. `joints` must outlive the
    // step's solver calls.
    void prepare(JointStorage& joints, const BodyStorage& bodies, const Params& params);
    void warmStart(BodyStorage& bodies);
    void solve(BodyStorage& bodies, bool useBias);

    std::size_t constraintCount() const { return constraints_.size(); }

private:
    static constexpr std::uint32_t kWorld = 0xFFFFFFFFu;  // dense index standing for the world

    struct Constraint {
        std::uint32_t joint = 0;             // dense index in the storage
        std::uint32_t bodyA = 0, bodyB = 0;  // dense indices, or kWorld
        float inverseMassA = 0.0f, inverseMassB = 0.0f;  // zero for a body that does not move
        SoftConstraint spring;               // distance spring (unused otherwise)
    };
    // The two bodies' velocities, and their world inverse inertia as of now (not of prepare: a
    // long link turns a lot within a step, and a stale inertia misjudges the joint's mass).
    struct BodyPairState;
    // A joint's rigid rows' mass matrix for one pose, factored (see solveConstraint).
    struct RigidFactor {
        Mat3 turnA{0.0f}, turnB{0.0f};  // angular velocity of A, B per unit impulse at the anchor
        Mat3 kap{0.0f};                 // rotation-anchor coupling block of K, free direction out
        Mat3 kaaInverse{0.0f};          // inverse of the rotation block
        Mat3 couplingThrough{0.0f};     // Kap^T Kaa^-1
        Mat3 pointInverse{0.0f};        // inverse of the anchor block once rotation is eliminated
    };
    RigidFactor factor(const Constraint& c, const Joint& joint, const BodyPairState& state, const JointGeometry& g) const;
    BodyPairState load(const Constraint& c, const BodyStorage& bodies) const;
    void store(const Constraint& c, Joint& joint, const BodyPairState& state, BodyStorage& bodies) const;

    JointBodyPose poseOf(std::uint32_t body, const BodyStorage& bodies) const;
    void solveConstraint(const Constraint& c, Joint& joint, BodyPairState& state, const JointGeometry& g,
                         const RigidFactor& rigidFactor, bool useBias) const;

    std::vector<Constraint> constraints_;
    // Each constraint's geometry and factored mass matrix, from warmStart: the bodies do not move
    // until the substep's positions are integrated, so the velocity passes reuse them; the relax
    // passes, after the move, compute their own.
    std::vector<JointGeometry> substepGeometry_;
    std::vector<RigidFactor> substepFactor_;
    JointStorage* joints_ = nullptr;
    Params params_;
    SoftConstraint soft_;  // rigid rows while the bias is on
};

}  // namespace simcore
