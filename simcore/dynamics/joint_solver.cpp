#include "simcore/dynamics/joint_solver.h"

#include <algorithm>
#include <cassert>
#include <cmath>

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

// Bodies that do not move in the constraint get their velocities back unchanged.
void JointSolver::store(const Constraint& c, const BodyPairState& state, BodyStorage& bodies) const {
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
    const float h = params.substepDt;
    soft_ = SoftConstraint::make(SoftConstraint::cappedHertz(params.joint.hertz, h), params.joint.dampingRatio, h);

    auto moves = [&bodies](int i) {
        return i >= 0 && bodies.motion[static_cast<std::size_t>(i)] == MotionType::Dynamic &&
               bodies.awake[static_cast<std::size_t>(i)];
    };
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

void JointSolver::warmStart(BodyStorage& bodies) const {
    for (const Constraint& c : constraints_) {
        const Joint& j = joints_->joints[c.joint];
        const JointGeometry g = jointGeometry(j, poseOf(c.bodyA, bodies), poseOf(c.bodyB, bodies));
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
        v.linearA -= c.inverseMassA * linear;
        v.angularA -= v.inverseInertiaA * (glm::cross(armA, linear) + angular);
        v.linearB += c.inverseMassB * linear;
        v.angularB += v.inverseInertiaB * (glm::cross(g.armB, linear) + angular);
        store(c, v, bodies);
    }
}

void JointSolver::solve(BodyStorage& bodies, bool useBias) {
    for (const Constraint& c : constraints_) {
        Joint& j = joints_->joints[c.joint];
        const JointGeometry g = jointGeometry(j, poseOf(c.bodyA, bodies), poseOf(c.bodyB, bodies));
        BodyPairState state = load(c, bodies);
        solveConstraint(c, j, state, g, useBias);
        store(c, state, bodies);
    }
}

// Rows in order of importance, the most important last so it has the final word: motor, limits,
// then the rigid rows (rotation, then the anchor point).
void JointSolver::solveConstraint(const Constraint& c, Joint& j, BodyPairState& v, const JointGeometry& g,
                                  bool useBias) const {
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
    auto applyPoint = [&](const Vec3& impulse, const Vec3& armA, const Vec3& armB) {
        v.linearA -= c.inverseMassA * impulse;
        v.angularA -= inertiaA * glm::cross(armA, impulse);
        v.linearB += c.inverseMassB * impulse;
        v.angularB += inertiaB * glm::cross(armB, impulse);
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
    // Two rows along perpendicular directions d1, d2 solved as a block; `accumulated` is the
    // block's impulse as a world vector (its d1, d2 components), since the directions turn.
    auto solvePair = [&](const Row& r1, const Row& r2, const Vec3& d1, const Vec3& d2, float position1,
                         float position2, Vec3& accumulated) {
        const float k11 = coupling(r1, r1), k22 = coupling(r2, r2), k12 = coupling(r1, r2);
        const float determinant = k11 * k22 - k12 * k12;
        if (!(determinant > 0.0f)) return;
        const float rhs1 = velocityAlong(r1) + rigid.biasRate * position1;
        const float rhs2 = velocityAlong(r2) + rigid.biasRate * position2;
        const float old1 = glm::dot(accumulated, d1), old2 = glm::dot(accumulated, d2);
        const float lambda1 = -rigid.massScale * (k22 * rhs1 - k12 * rhs2) / determinant - rigid.impulseScale * old1;
        const float lambda2 = -rigid.massScale * (k11 * rhs2 - k12 * rhs1) / determinant - rigid.impulseScale * old2;
        apply(r1, lambda1);
        apply(r2, lambda2);
        accumulated = (old1 + lambda1) * d1 + (old2 + lambda2) * d2;
    };
    // No relative rotation: three angular rows, K = IA^-1 + IB^-1.
    auto solveAngularBlock = [&](const Vec3& error) {
        const Mat3 k = inertiaA + inertiaB;
        const Vec3 rhs = v.angularB - v.angularA + rigid.biasRate * error;
        const Vec3 impulse = -rigid.massScale * (glm::inverse(k) * rhs) - rigid.impulseScale * j.impulses.angular;
        v.angularA -= inertiaA * impulse;
        v.angularB += inertiaB * impulse;
        j.impulses.angular += impulse;
    };
    // Anchors coincide: three linear rows, K = (mA + mB) 1 - [rA]x IA^-1 [rA]x - [rB]x IB^-1 [rB]x.
    auto solvePoint = [&]() {
        const Mat3 skewA = skew(g.armA), skewB = skew(g.armB);
        const Mat3 k = Mat3(inverseMassSum) - skewA * inertiaA * skewA - skewB * inertiaB * skewB;
        const Vec3 relative = v.linearB + glm::cross(v.angularB, g.armB) - v.linearA - glm::cross(v.angularA, g.armA);
        const Vec3 rhs = relative + rigid.biasRate * g.separation;
        const Vec3 impulse = -rigid.massScale * (glm::inverse(k) * rhs) - rigid.impulseScale * j.impulses.point;
        applyPoint(impulse, g.armA, g.armB);
        j.impulses.point += impulse;
    };

    switch (j.type) {
        case JointType::Ball: solvePoint(); break;
        case JointType::Hinge: {
            // Motor and limits drive the angle of A relative to B: rows along minus the axis.
            const Row twist = angularRow(-g.axisA);
            if (j.motor) solveMotor(twist);
            if (j.limits) solveLimits(twist, g.hingeAngle(j), j.limits->lower, j.limits->upper);
            // Axis alignment: B's axis leaves A's by the rotation a x b, perpendicular to a.
            Vec3 d1, d2;
            orthonormalBasis(g.axisA, d1, d2);
            const Vec3 misalignment = glm::cross(g.axisA, g.axisB);
            solvePair(angularRow(d1), angularRow(d2), d1, d2, glm::dot(misalignment, d1), glm::dot(misalignment, d2),
                      j.impulses.angular);
            solvePoint();
            break;
        }
        case JointType::Slider: {
            // Rows act at B's anchor: on A that point is armA + separation from its centre of mass.
            const Vec3 armA = g.armA + g.separation;
            const Row slide = linearRow(-g.axisA, armA, g.armB);  // A relative to B, as the twist
            if (j.motor) solveMotor(slide);
            if (j.limits) solveLimits(slide, g.slide(), j.limits->lower, j.limits->upper);
            solveAngularBlock(g.rotationError());
            Vec3 d1, d2;
            orthonormalBasis(g.axisA, d1, d2);
            solvePair(linearRow(d1, armA, g.armB), linearRow(d2, armA, g.armB), d1, d2, glm::dot(g.separation, d1),
                      glm::dot(g.separation, d2), j.impulses.point);
            break;
        }
        case JointType::Fixed:
            solveAngularBlock(g.rotationError());
            solvePoint();
            break;
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
