#include "simcore/dynamics/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace simcore {

namespace {

// Orthonormal tangents from a unit normal without branches on near-parallel axes (Duff et al.,
// "Building an Orthonormal Basis, Revisited", 2017). Continuous in the normal, so warm-started
// friction impulses stay meaningful from step to step.
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    t1 = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

// Friction tangents. While the bodies slip, the first tangent follows the slip: each row then has
// its own effective mass, and with axes at an angle to the slip the two rows' updates would not be
// parallel to it, so the clamped friction would point off the slip direction and come out weak (3.6 %
// on a box sliding down a 30-degree incline). Without slip any continuous basis serves.
void frictionAxes(const ContactManifold& manifold, const BodyStorage& bodies, std::size_t a, std::size_t b, Vec3& t1,
                  Vec3& t2) {
    const Vec3& n = manifold.normal;
    Vec3 centre(0.0f);
    for (int i = 0; i < manifold.pointCount; ++i) centre += manifold.points[i].pointA + manifold.points[i].pointB;
    centre *= 0.5f / static_cast<float>(manifold.pointCount);
    const Vec3 relative = bodies.linearVelocity[b] + glm::cross(bodies.angularVelocity[b], centre - bodies.centerOfMass[b]) -
                          bodies.linearVelocity[a] - glm::cross(bodies.angularVelocity[a], centre - bodies.centerOfMass[a]);
    const Vec3 slip = relative - glm::dot(relative, n) * n;
    constexpr float kMinSlipSpeed = 1e-3f;  // m/s; below it the direction is noise
    if (lengthSquared(slip) > kMinSlipSpeed * kMinSlipSpeed) {
        t1 = glm::normalize(slip);
        t2 = glm::cross(n, t1);
    } else {
        tangentBasis(n, t1, t2);
    }
}

// Velocities of a constraint's two bodies, loaded once per constraint and written back after.
struct BodyPairVelocity {
    Vec3 linearA, angularA, linearB, angularB;

    // Relative velocity of B with respect to A along a row.
    float along(const Vec3& axis, const Vec3& angularJacobianA, const Vec3& angularJacobianB) const {
        return glm::dot(linearB - linearA, axis) + glm::dot(angularB, angularJacobianB) -
               glm::dot(angularA, angularJacobianA);
    }
};

}  // namespace

void ContactSolver::prepare(const std::vector<Contact>& contacts, const BodyStorage& bodies, const Params& params) {
    params_ = params;
    constraints_.clear();
    maxPenetration_ = 0.0f;
    usesFriction_ = false;
    usesRestitution_ = false;

    // Soft contact as a mass-spring-damper solved implicitly (Catto, "Solver2D", 2024): stiffness
    // from the frequency, capped at a quarter of the substep rate so the spring stays resolvable.
    const float h = params.substepDt;
    const float hertz = std::min(params.solver.contactHertz, 0.25f / h);
    const float omega = 2.0f * kPi * hertz;
    const float zeta = params.solver.contactDampingRatio;
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    biasRate_ = omega / a1;
    massScale_ = a2 * a3;
    impulseScale_ = a3;

    for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& contact = contacts[ci];
        const ContactManifold& manifold = contact.manifold;
        if (manifold.pointCount == 0) continue;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.motion[a] == MotionType::Dynamic && bodies.awake[a];
        const bool movesB = bodies.motion[b] == MotionType::Dynamic && bodies.awake[b];
        if (!movesA && !movesB) continue;

        Constraint& c = constraints_.emplace_back();
        c.contactIndex = static_cast<std::uint32_t>(ci);
        c.bodyA = static_cast<std::uint32_t>(a);
        c.bodyB = static_cast<std::uint32_t>(b);
        c.inverseMassA = movesA ? bodies.inverseMass[a] : 0.0f;
        c.inverseMassB = movesB ? bodies.inverseMass[b] : 0.0f;
        const Mat3 inverseInertiaA = movesA ? bodies.inverseInertiaWorld[a] : Mat3(0.0f);
        const Mat3 inverseInertiaB = movesB ? bodies.inverseInertiaWorld[b] : Mat3(0.0f);
        c.axes[kNormal] = manifold.normal;
        frictionAxes(manifold, bodies, a, b, c.axes[kTangent1], c.axes[kTangent2]);
        // With friction off (or zero for this pair) no friction rows are built at all.
        c.friction = params.friction ? contact.friction : 0.0f;
        c.restitution = params.restitution ? contact.restitution : 0.0f;
        usesFriction_ = usesFriction_ || c.friction > 0.0f;
        usesRestitution_ = usesRestitution_ || c.restitution > 0.0f;
        c.pointCount = manifold.pointCount;
        const int rows = c.friction > 0.0f ? kRowCount : 1;

        const float inverseMassSum = c.inverseMassA + c.inverseMassB;
        const Quat inverseRotationA = glm::conjugate(bodies.orientation[a]);
        const Quat inverseRotationB = glm::conjugate(bodies.orientation[b]);
        for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& mp = manifold.points[i];
            Point& p = c.points[i];
            // Both anchors at the midpoint: then the separation's change is just the change of
            // (anchorB - anchorA) along the normal as the bodies move.
            const Vec3 mid = 0.5f * (mp.pointA + mp.pointB);
            const Vec3 anchorA = mid - bodies.centerOfMass[a];
            const Vec3 anchorB = mid - bodies.centerOfMass[b];
            p.localAnchorA = inverseRotationA * anchorA;
            p.localAnchorB = inverseRotationB * anchorB;
            p.baseSeparation = mp.separation;
            for (int row = 0; row < rows; ++row) {
                p.angularA[row] = glm::cross(anchorA, c.axes[row]);
                p.angularB[row] = glm::cross(anchorB, c.axes[row]);
                p.weightedA[row] = inverseInertiaA * p.angularA[row];
                p.weightedB[row] = inverseInertiaB * p.angularB[row];
                const float k = inverseMassSum + glm::dot(p.angularA[row], p.weightedA[row]) +
                                glm::dot(p.angularB[row], p.weightedB[row]);
                p.mass[row] = k > 0.0f ? 1.0f / k : 0.0f;
            }
            const ContactImpulse& warm = contact.impulses[i];
            p.impulse[kNormal] = warm.normal;
            p.impulse[kTangent1] = rows > 1 ? glm::dot(warm.friction, c.axes[kTangent1]) : 0.0f;
            p.impulse[kTangent2] = rows > 1 ? glm::dot(warm.friction, c.axes[kTangent2]) : 0.0f;
            p.maxNormalImpulse = 0.0f;
            const BodyPairVelocity v{bodies.linearVelocity[a], bodies.angularVelocity[a], bodies.linearVelocity[b],
                                     bodies.angularVelocity[b]};
            p.approachVelocity = v.along(c.axes[kNormal], p.angularA[kNormal], p.angularB[kNormal]);
            maxPenetration_ = std::max(maxPenetration_, -mp.separation);
        }
    }
}

namespace {

// Loads and stores the two bodies' velocities around a constraint's update. Static, kinematic
// and sleeping bodies have zero inverse mass in the constraint: their write-back is a no-op.
template <typename Constraint, typename Update>
void updateVelocities(BodyStorage& bodies, Constraint& c, Update&& update) {
    BodyPairVelocity v{bodies.linearVelocity[c.bodyA], bodies.angularVelocity[c.bodyA],
                       bodies.linearVelocity[c.bodyB], bodies.angularVelocity[c.bodyB]};
    update(v);
    bodies.linearVelocity[c.bodyA] = v.linearA;
    bodies.angularVelocity[c.bodyA] = v.angularA;
    bodies.linearVelocity[c.bodyB] = v.linearB;
    bodies.angularVelocity[c.bodyB] = v.angularB;
}

template <typename Constraint, typename Point>
void applyRow(BodyPairVelocity& v, const Constraint& c, const Point& p, int row, float impulse) {
    const Vec3 linear = impulse * c.axes[row];
    v.linearA -= c.inverseMassA * linear;
    v.angularA -= impulse * p.weightedA[row];
    v.linearB += c.inverseMassB * linear;
    v.angularB += impulse * p.weightedB[row];
}

}  // namespace

void ContactSolver::warmStart(BodyStorage& bodies) const {
    for (const Constraint& c : constraints_) {
        const int rows = c.friction > 0.0f ? kRowCount : 1;
        updateVelocities(bodies, c, [&](BodyPairVelocity& v) {
            for (int i = 0; i < c.pointCount; ++i)
                for (int row = 0; row < rows; ++row) applyRow(v, c, c.points[i], row, c.points[i].impulse[row]);
        });
    }
}

void ContactSolver::solve(BodyStorage& bodies, bool useBias) {
    const float inverseH = 1.0f / params_.substepDt;
    const bool soft = params_.solver.positionCorrection == PositionCorrection::SoftStep;
    const float maxPush = params_.solver.maxPushVelocity;

    for (Constraint& c : constraints_) {
        // Separation now, from how far the anchors moved since prepare: one rotation matrix per
        // body serves all of the constraint's points.
        const Mat3 rotationA = glm::mat3_cast(bodies.orientation[c.bodyA]);
        const Mat3 rotationB = glm::mat3_cast(bodies.orientation[c.bodyB]);
        const Vec3 offset = bodies.centerOfMass[c.bodyB] - bodies.centerOfMass[c.bodyA];
        const Vec3& normal = c.axes[kNormal];

        updateVelocities(bodies, c, [&](BodyPairVelocity& v) {
            for (int i = 0; i < c.pointCount; ++i) {
                Point& p = c.points[i];
                const Vec3 d = offset + rotationB * p.localAnchorB - rotationA * p.localAnchorA;
                const float separation = p.baseSeparation + glm::dot(d, normal);

                float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
                if (separation > 0.0f) {
                    bias = separation * inverseH;  // speculative: arrive exactly at contact, no earlier
                } else if (useBias) {
                    if (soft) {
                        bias = std::max(biasRate_ * separation, -maxPush);
                        massScale = massScale_;
                        impulseScale = impulseScale_;
                    } else {
                        const float overlap = std::min(separation + params_.contact.linearSlop, 0.0f);
                        bias = std::max(params_.solver.baumgarte * inverseH * overlap, -maxPush);
                    }
                }
                const float vn = v.along(normal, p.angularA[kNormal], p.angularB[kNormal]);
                const float lambda = -p.mass[kNormal] * massScale * (vn + bias) - impulseScale * p.impulse[kNormal];
                const float accumulated = std::max(p.impulse[kNormal] + lambda, 0.0f);
                const float delta = accumulated - p.impulse[kNormal];
                p.impulse[kNormal] = accumulated;
                p.maxNormalImpulse = std::max(p.maxNormalImpulse, delta);
                applyRow(v, c, p, kNormal, delta);
            }
            if (c.friction == 0.0f) return;
            for (int i = 0; i < c.pointCount; ++i) {
                Point& p = c.points[i];
                const float limit = c.friction * p.impulse[kNormal];
                // A point that pushes nothing and holds no friction would clamp to zero again:
                // skip it (side contacts in piles and pyramids carry no load).
                if (limit == 0.0f && p.impulse[kTangent1] == 0.0f && p.impulse[kTangent2] == 0.0f) continue;
                float t1 = p.impulse[kTangent1] -
                           p.mass[kTangent1] * v.along(c.axes[kTangent1], p.angularA[kTangent1], p.angularB[kTangent1]);
                float t2 = p.impulse[kTangent2] -
                           p.mass[kTangent2] * v.along(c.axes[kTangent2], p.angularA[kTangent2], p.angularB[kTangent2]);
                // Coulomb: the tangential impulse lies in a disc of radius friction * normal impulse.
                const float length2 = t1 * t1 + t2 * t2;
                if (length2 > limit * limit) {
                    const float scale = limit / std::sqrt(length2);
                    t1 *= scale;
                    t2 *= scale;
                }
                applyRow(v, c, p, kTangent1, t1 - p.impulse[kTangent1]);
                applyRow(v, c, p, kTangent2, t2 - p.impulse[kTangent2]);
                p.impulse[kTangent1] = t1;
                p.impulse[kTangent2] = t2;
            }
        });
    }
}

void ContactSolver::applyRestitution(BodyStorage& bodies) {
    const float threshold = params_.contact.restitutionThreshold;
    for (Constraint& c : constraints_) {
        if (c.restitution == 0.0f) continue;
        updateVelocities(bodies, c, [&](BodyPairVelocity& v) {
            for (int i = 0; i < c.pointCount; ++i) {
                Point& p = c.points[i];
                // Only points that approached fast enough and actually pushed bounce.
                if (p.approachVelocity > -threshold || p.maxNormalImpulse == 0.0f) continue;
                const float vn = v.along(c.axes[kNormal], p.angularA[kNormal], p.angularB[kNormal]);
                const float lambda = -p.mass[kNormal] * (vn + c.restitution * p.approachVelocity);
                const float accumulated = std::max(p.impulse[kNormal] + lambda, 0.0f);
                applyRow(v, c, p, kNormal, accumulated - p.impulse[kNormal]);
                p.impulse[kNormal] = accumulated;
            }
        });
    }
}

void ContactSolver::storeImpulses(std::vector<Contact>& contacts) const {
    for (const Constraint& c : constraints_) {
        Contact& contact = contacts[c.contactIndex];
        for (int i = 0; i < c.pointCount; ++i) {
            const Point& p = c.points[i];
            contact.impulses[i] = {p.impulse[kNormal],
                                   p.impulse[kTangent1] * c.axes[kTangent1] + p.impulse[kTangent2] * c.axes[kTangent2]};
        }
    }
}

}  // namespace simcore
