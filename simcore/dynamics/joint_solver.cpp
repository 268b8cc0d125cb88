#include "simcore/dynamics/joint_solver.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

namespace simcore {

struct JointSolver::BodyPairState {
    Vec3 linearA{0.0f}, angularA{0.0f}, linearB{0.0f}, angularB{0.0f};
    Mat3 inverseInertiaA{0.0f}, inverseInertiaB{0.0f};
};

namespace {

// Below this anchor distance (m) a distance joint's direction is noise: its rows wait.
constexpr float kMinDirectionLength = 1e-6f;

// One scalar row: Cdot = linear . (vB - vA) + angularB . wB - angularA . wA.
struct Row {
    Vec3 linear{0.0f};
    Vec3 angularA{0.0f};
    Vec3 angularB{0.0f};
};

Row linearRow(const Vec3& direction, const Vec3& armA, const Vec3& armB) {
    return {direction, glm::cross(armA, direction), glm::cross(armB, direction)};
}
Row angularRow(const Vec3& axis) { return {Vec3(0.0f), axis, axis}; }
Row reversed(const Row& r) { return {-r.linear, -r.angularA, -r.angularB}; }

// The rigid rows of a hinge, slider or fixed joint in pose g: three rotation rows (two across a
// hinge's axis) and three anchor rows (two across a slider's).
struct RigidRows {
    Vec3 rotationError{0.0f}, separation{0.0f};  // C of the rotation and anchor rows
    Vec3 armA{0.0f}, armB{0.0f};                 // where the anchor rows act
    std::optional<Vec3> freeRotation, freeTranslation;
};
RigidRows rigidRows(const Joint& j, const JointGeometry& g) {
    switch (j.type) {
        // Axis alignment: B's axis leaves A's by the rotation a x b, perpendicular to a.
        case JointType::Hinge: return {glm::cross(g.axisA, g.axisB), g.separation, g.armA, g.armB, g.axisA, std::nullopt};
        // Rows act at B's anchor: on A that point is armA + separation from its centre of mass.
        case JointType::Slider: return {g.rotationError(), g.separation, g.armA + g.separation, g.armB, std::nullopt, g.axisA};
        case JointType::Fixed: return {g.rotationError(), g.separation, g.armA, g.armB, std::nullopt, std::nullopt};
        case JointType::Ball:
        case JointType::Distance: break;
    }
    assert(false && "only hinge, slider and fixed joints have a rigid block");
    return {};
}

}  // namespace

JointBodyPose JointSolver::poseOf(std::uint32_t body, const BodyStorage& bodies) const {
    if (body == kWorld) return {};
    return {bodies.centerOfMass[body], bodies.orientation[body]};
}

JointSolver::BodyPairState JointSolver::load(const Constraint& c, const BodyStorage& bodies) const {
    BodyPairState state;
    state.linearA = bodies.linearVelocity[c.bodyA];
    state.angularA = bodies.angularVelocity[c.bodyA];
    if (c.inverseMassA > 0.0f) state.inverseInertiaA = bodies.inverseInertiaWorld[c.bodyA];
    if (c.bodyB == kWorld) return state;
    state.linearB = bodies.linearVelocity[c.bodyB];
    state.angularB = bodies.angularVelocity[c.bodyB];
    if (c.inverseMassB > 0.0f) state.inverseInertiaB = bodies.inverseInertiaWorld[c.bodyB];
    return state;
}

// Bodies that do not move in the constraint get their velocities back unchanged. A joint torn far
// apart (lever arms of kilometres on a light body) can overflow float within one pass: then its
// result is dropped, and its accumulated impulses with it, so neither inf nor NaN reaches the
// bodies or the next warm start. Any finite state is kept as it is, so no other scene changes.
void JointSolver::store(const Constraint& c, Joint& joint, const BodyPairState& state, BodyStorage& bodies) const {
    if (!isFinite(state.linearA) || !isFinite(state.angularA) || !isFinite(state.linearB) || !isFinite(state.angularB)) {
        joint.impulses = {};
        return;
    }
    bodies.linearVelocity[c.bodyA] = state.linearA;
    bodies.angularVelocity[c.bodyA] = state.angularA;
    if (c.bodyB == kWorld) return;
    bodies.linearVelocity[c.bodyB] = state.linearB;
    bodies.angularVelocity[c.bodyB] = state.angularB;
}

void JointSolver::prepare(JointStorage& joints, const BodyStorage& bodies, const Params& params) {
    joints_ = &joints;
    params_ = params;
    constraints_.clear();
    substepGeometry_.clear();  // warmStart fills them for this step's constraints
    substepFactor_.clear();
    const float h = params.substepDt;
    soft_ = SoftConstraint::make(SoftConstraint::cappedHertz(params.joint.hertz, h), params.joint.dampingRatio, h);

    auto moves = [&bodies](int i) { return i >= 0 && bodies.isAwakeDynamic(static_cast<std::size_t>(i)); };
    for (std::size_t ji = 0; ji < joints.size(); ++ji) {
        const Joint& j = joints.joints[ji];
        const int a = bodies.denseIndex(j.bodyA);
        const int b = j.bodyB.isValid() ? bodies.denseIndex(j.bodyB) : -1;
        assert(a >= 0 && (b >= 0 || !j.bodyB.isValid()));  // the world destroys joints with their bodies
        const bool movesA = moves(a), movesB = moves(b);
        if (!movesA && !movesB) continue;

        Constraint& c = constraints_.emplace_back();
        c.joint = static_cast<std::uint32_t>(ji);
        c.bodyA = static_cast<std::uint32_t>(a);
        c.bodyB = b >= 0 ? static_cast<std::uint32_t>(b) : kWorld;
        if (movesA) c.inverseMassA = bodies.inverseMass[c.bodyA];
        if (movesB) c.inverseMassB = bodies.inverseMass[c.bodyB];
        if (j.spring) c.spring = SoftConstraint::make(j.spring->hertz, j.spring->dampingRatio, h);
    }
}

void JointSolver::warmStart(BodyStorage& bodies) {
    substepGeometry_.resize(constraints_.size());
    substepFactor_.resize(constraints_.size());
    for (std::size_t ci = 0; ci < constraints_.size(); ++ci) {
        const Constraint& c = constraints_[ci];
        Joint& j = joints_->joints[c.joint];
        const JointGeometry& g = substepGeometry_[ci] = jointGeometry(j, poseOf(c.bodyA, bodies), poseOf(c.bodyB, bodies));
        const JointImpulses& impulse = j.impulses;
        // Along the row of the motor and the lower limit (the upper limit's row is reversed).
        const float axial = impulse.motor + impulse.lower - impulse.upper;

        Vec3 linear = impulse.point;
        Vec3 armA = g.armA;
        Vec3 angular = impulse.angular;
        switch (j.type) {
            case JointType::Ball:
            case JointType::Fixed: break;
            // Hinge and slider rows drive A relative to B: along minus the axis.
            case JointType::Hinge: angular -= axial * g.axisA; break;
            case JointType::Slider:
                linear -= axial * g.axisA;
                armA += g.separation;  // A's point under B's anchor
                break;
            case JointType::Distance: {
                const float length = glm::length(g.separation);
                linear = length > kMinDirectionLength ? (impulse.axial + axial) / length * g.separation : Vec3(0.0f);
                break;
            }
        }
        BodyPairState v = load(c, bodies);
        substepFactor_[ci] = factor(c, j, v, g);
        v.linearA -= c.inverseMassA * linear;
        v.angularA -= v.inverseInertiaA * (glm::cross(armA, linear) + angular);
        v.linearB += c.inverseMassB * linear;
        v.angularB += v.inverseInertiaB * (glm::cross(g.armB, linear) + angular);
        store(c, j, v, bodies);
    }
}

void JointSolver::solve(BodyStorage& bodies, bool useBias) {
    assert(!useBias || substepGeometry_.size() == constraints_.size());  // warmStart came first
    for (std::size_t ci = 0; ci < constraints_.size(); ++ci) {
        const Constraint& c = constraints_[ci];
        Joint& j = joints_->joints[c.joint];
        BodyPairState state = load(c, bodies);
        if (useBias) {
            solveConstraint(c, j, state, substepGeometry_[ci], substepFactor_[ci], useBias);
        } else {
            const JointGeometry g = jointGeometry(j, poseOf(c.bodyA, bodies), poseOf(c.bodyB, bodies));
            solveConstraint(c, j, state, g, factor(c, j, state, g), useBias);
        }
        store(c, j, state, bodies);
    }
}

// All rigid rows of the joint as one soft constraint on their joint effective mass matrix
// K = J M^-1 J^T: up to three rotation rows (a torque impulse) and three anchor rows (an impulse
// at the anchors), K = [Kaa Kap; Kap^T Kpp]. Why one block: with an anchor far from a body's
// centre, the two kinds of row are strongly coupled (turning the body moves the anchor). Solved
// apart, each block's spring was scaled to the mass of its own rows alone (the inertia about
// the centre of mass, or the little mass that swings the anchor round it), not to what the
// joint holds (that inertia plus m r^2), so a long lever arm made the joint hundreds of times
// softer than its hertz: metres of stretch under load. A spring scaled to a mass matrix that
// turns with the bodies is not conservative, and at such stretch it pumped energy in until the
// bodies flew apart. Scaled to the joint's whole K, the stretch is that of the joint's hertz,
// and the pumping (which grows with the stretch squared) is negligible.
//
// A free direction f (a hinge's axis among the rotation rows, a slider's among the anchor rows)
// is taken out with the projection P = 1 - f f^T: the block P K P + f f^T on P's right-hand side
// gives the rows across f their solution and f's component zero.
//
// A ball joint has the anchor rows alone. Both blocks are positive definite unless float has lost
// them (a lever arm of kilometres on a small body): then the solve gives a non-finite impulse, and
// the rows wait for a better pose.
JointSolver::RigidFactor JointSolver::factor(const Constraint& c, const Joint& j, const BodyPairState& v,
                                             const JointGeometry& g) const {
    const Mat3& inertiaA = v.inverseInertiaA;
    const Mat3& inertiaB = v.inverseInertiaB;
    const float inverseMassSum = c.inverseMassA + c.inverseMassB;
    RigidFactor f;
    if (j.type == JointType::Distance) return f;
    if (j.type == JointType::Ball) {
        const Mat3 skewA = skew(g.armA), skewB = skew(g.armB);
        f.pointInverse = glm::inverse(Mat3(inverseMassSum) - skewA * inertiaA * skewA - skewB * inertiaB * skewB);
        return f;
    }
    const RigidRows rows = rigidRows(j, g);
    const Mat3 skewA = skew(rows.armA), skewB = skew(rows.armB);
    f.turnA = inertiaA * skewA;
    f.turnB = inertiaB * skewB;
    Mat3 kaa = inertiaA + inertiaB;
    Mat3 kap = f.turnA + f.turnB;
    Mat3 kpp = Mat3(inverseMassSum) - skewA * f.turnA - skewB * f.turnB;
    // P K P + f f^T for a symmetric K, by outer products (cheaper than two matrix products).
    auto projectSymmetric = [](const Mat3& k, const Vec3& axis) {
        const Vec3 kf = k * axis;
        return k - glm::outerProduct(axis, kf) - glm::outerProduct(kf, axis) +
               (glm::dot(axis, kf) + 1.0f) * glm::outerProduct(axis, axis);
    };
    if (rows.freeRotation) {
        const Vec3& axis = *rows.freeRotation;
        kaa = projectSymmetric(kaa, axis);
        kap -= glm::outerProduct(axis, glm::transpose(kap) * axis);  // P Kap = Kap - f (Kap^T f)^T
    }
    if (rows.freeTranslation) {
        const Vec3& axis = *rows.freeTranslation;
        kpp = projectSymmetric(kpp, axis);
        kap -= glm::outerProduct(kap * axis, axis);  // Kap P = Kap - (Kap f) f^T
    }
    // Block elimination of the rotation rows: the anchor rows on the Schur complement of Kaa.
    f.kap = kap;
    f.kaaInverse = glm::inverse(kaa);
    f.couplingThrough = glm::transpose(kap) * f.kaaInverse;
    f.pointInverse = glm::inverse(kpp - f.couplingThrough * kap);
    return f;
}

// Rows in order of importance, the most important last so it has the final word: motor, limits,
// then the rigid rows (rotation and anchor point together).
void JointSolver::solveConstraint(const Constraint& c, Joint& j, BodyPairState& v, const JointGeometry& g,
                                  const RigidFactor& f, bool useBias) const {
    const float inverseH = 1.0f / params_.substepDt;
    const Mat3& inertiaA = v.inverseInertiaA;
    const Mat3& inertiaB = v.inverseInertiaB;
    const float inverseMassSum = c.inverseMassA + c.inverseMassB;
    // Rigid rows are soft springs while the bias is on and plain velocity constraints in the relax
    // passes, which take out the velocity the push added.
    const SoftConstraint rigid = useBias ? soft_ : SoftConstraint{};

    auto velocityAlong = [&](const Row& r) {
        return glm::dot(r.linear, v.linearB - v.linearA) + glm::dot(r.angularB, v.angularB) -
               glm::dot(r.angularA, v.angularA);
    };
    // Entry of the rows' inverse mass matrix J1 M^-1 J2^T.
    auto coupling = [&](const Row& r1, const Row& r2) {
        return inverseMassSum * glm::dot(r1.linear, r2.linear) + glm::dot(r1.angularA, inertiaA * r2.angularA) +
               glm::dot(r1.angularB, inertiaB * r2.angularB);
    };
    auto massOf = [&](const Row& r) {
        const float k = coupling(r, r);
        return k > 0.0f ? 1.0f / k : 0.0f;
    };
    auto apply = [&](const Row& r, float impulse) {
        v.linearA -= (c.inverseMassA * impulse) * r.linear;
        v.angularA -= impulse * (inertiaA * r.angularA);
        v.linearB += (c.inverseMassB * impulse) * r.linear;
        v.angularB += impulse * (inertiaB * r.angularB);
    };
    // A row that only pushes (C >= 0 wanted, impulse >= 0). Ahead of the limit it is speculative:
    // it lets the row close the gap within the substep but no further.
    auto solveOneSided = [&](const Row& r, float mass, float position, float& accumulated) {
        float bias = rigid.biasRate * position, massScale = rigid.massScale, impulseScale = rigid.impulseScale;
        if (position > 0.0f) {
            bias = position * inverseH;
            massScale = 1.0f;
            impulseScale = 0.0f;
        }
        const float lambda = -mass * massScale * (velocityAlong(r) + bias) - impulseScale * accumulated;
        const float updated = std::max(accumulated + lambda, 0.0f);
        apply(r, updated - accumulated);
        accumulated = updated;
    };
    auto solveLimits = [&](const Row& r, float value, float lower, float upper) {
        const float mass = massOf(r);
        solveOneSided(r, mass, value - lower, j.impulses.lower);
        solveOneSided(reversed(r), mass, upper - value, j.impulses.upper);
    };
    auto solveMotor = [&](const Row& r) {
        const float maxImpulse = j.motor->maxForce * params_.substepDt;
        const float lambda = -massOf(r) * (velocityAlong(r) - j.motor->speed);
        const float updated = std::clamp(j.impulses.motor + lambda, -maxImpulse, maxImpulse);
        apply(r, updated - j.impulses.motor);
        j.impulses.motor = updated;
    };
    // The rigid rows, on the factor of their joint mass matrix (see factor).
    auto solveRigid = [&](const RigidRows& rows) {
        Vec3 ra = v.angularB - v.angularA + rigid.biasRate * rows.rotationError;
        Vec3 rp = v.linearB + glm::cross(v.angularB, rows.armB) - v.linearA - glm::cross(v.angularA, rows.armA) +
                  rigid.biasRate * rows.separation;
        Vec3 oldAngular = j.impulses.angular, oldPoint = j.impulses.point;
        auto project = [](const Vec3& x, const Vec3& axis) { return x - glm::dot(axis, x) * axis; };
        if (rows.freeRotation) {
            ra = project(ra, *rows.freeRotation);
            oldAngular = project(oldAngular, *rows.freeRotation);
        }
        if (rows.freeTranslation) {
            rp = project(rp, *rows.freeTranslation);
            oldPoint = project(oldPoint, *rows.freeTranslation);
        }
        const Vec3 xp = f.pointInverse * (rp - f.couplingThrough * ra);
        const Vec3 xa = f.kaaInverse * (ra - f.kap * xp);
        if (!std::isfinite(glm::dot(xa, xa) + glm::dot(xp, xp))) return;  // see factor
        const Vec3 angular = -rigid.massScale * xa - rigid.impulseScale * oldAngular;
        const Vec3 point = -rigid.massScale * xp - rigid.impulseScale * oldPoint;
        v.linearA -= c.inverseMassA * point;
        v.angularA -= inertiaA * angular + f.turnA * point;
        v.linearB += c.inverseMassB * point;
        v.angularB += inertiaB * angular + f.turnB * point;
        j.impulses.angular = oldAngular + angular;
        j.impulses.point = oldPoint + point;
    };

    switch (j.type) {
        case JointType::Ball: {
            // Anchors coincide; rotation is free, so there are no rotation rows: solved alone.
            const Vec3 relative =
                v.linearB + glm::cross(v.angularB, g.armB) - v.linearA - glm::cross(v.angularA, g.armA);
            const Vec3 rhs = relative + rigid.biasRate * g.separation;
            const Vec3 impulse = -rigid.massScale * (f.pointInverse * rhs) - rigid.impulseScale * j.impulses.point;
            v.linearA -= c.inverseMassA * impulse;
            v.angularA -= inertiaA * glm::cross(g.armA, impulse);
            v.linearB += c.inverseMassB * impulse;
            v.angularB += inertiaB * glm::cross(g.armB, impulse);
            j.impulses.point += impulse;
            break;
        }
        case JointType::Hinge: {
            // Motor and limits drive the angle of A relative to B: rows along minus the axis.
            const Row twist = angularRow(-g.axisA);
            if (j.motor) solveMotor(twist);
            if (j.limits) solveLimits(twist, g.hingeAngle(j), j.limits->lower, j.limits->upper);
            solveRigid(rigidRows(j, g));
            break;
        }
        case JointType::Slider: {
            const RigidRows rows = rigidRows(j, g);
            const Row slide = linearRow(-g.axisA, rows.armA, rows.armB);  // A relative to B, as the twist
            if (j.motor) solveMotor(slide);
            if (j.limits) solveLimits(slide, g.slide(), j.limits->lower, j.limits->upper);
            solveRigid(rows);
            break;
        }
        case JointType::Fixed: solveRigid(rigidRows(j, g)); break;
        case JointType::Distance: {
            const float length = glm::length(g.separation);
            if (length < kMinDirectionLength) break;
            const Row r = linearRow(g.separation / length, g.armA, g.armB);
            const float mass = massOf(r);
            if (j.minLength < j.maxLength) {
                if (j.spring) {
                    // The spring is physical: it acts in the relax passes too.
                    const SoftConstraint& s = c.spring;
                    const float lambda = -mass * s.massScale * (velocityAlong(r) + s.biasRate * (length - j.restLength)) -
                                         s.impulseScale * j.impulses.axial;
                    apply(r, lambda);
                    j.impulses.axial += lambda;
                }
                if (j.minLength > 0.0f) solveOneSided(r, mass, length - j.minLength, j.impulses.lower);
                if (std::isfinite(j.maxLength)) solveOneSided(reversed(r), mass, j.maxLength - length, j.impulses.upper);
            } else {
                const float lambda = -mass * rigid.massScale * (velocityAlong(r) + rigid.biasRate * (length - j.restLength)) -
                                     rigid.impulseScale * j.impulses.axial;
                apply(r, lambda);
                j.impulses.axial += lambda;
            }
            break;
        }
    }
}

}  // namespace simcore
