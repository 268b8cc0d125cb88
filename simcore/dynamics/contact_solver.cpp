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

float effectiveMass(float inverseMassSum, const Mat3& inverseInertiaA, const Mat3& inverseInertiaB,
                    const Vec3& anchorA, const Vec3& anchorB, const Vec3& direction) {
    const Vec3 ra = glm::cross(anchorA, direction);
    const Vec3 rb = glm::cross(anchorB, direction);
    const float k = inverseMassSum + glm::dot(ra, inverseInertiaA * ra) + glm::dot(rb, inverseInertiaB * rb);
    return k > 0.0f ? 1.0f / k : 0.0f;
}

struct Velocities {
    Vec3 linearA, angularA, linearB, angularB;
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
        c.inverseInertiaA = movesA ? bodies.inverseInertiaWorld[a] : Mat3(0.0f);
        c.inverseInertiaB = movesB ? bodies.inverseInertiaWorld[b] : Mat3(0.0f);
        c.normal = manifold.normal;
        tangentBasis(c.normal, c.tangent1, c.tangent2);
        // With friction off (or zero for this pair) no friction rows are built at all.
        c.friction = params.friction ? contact.friction : 0.0f;
        c.restitution = params.restitution ? contact.restitution : 0.0f;
        usesFriction_ = usesFriction_ || c.friction > 0.0f;
        usesRestitution_ = usesRestitution_ || c.restitution > 0.0f;
        c.pointCount = manifold.pointCount;

        const float inverseMassSum = c.inverseMassA + c.inverseMassB;
        const Quat inverseRotationA = glm::conjugate(bodies.orientation[a]);
        const Quat inverseRotationB = glm::conjugate(bodies.orientation[b]);
        for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& mp = manifold.points[i];
            Point& p = c.points[i];
            // Both anchors at the midpoint: then the separation's change is just the change of
            // (anchorB - anchorA) along the normal as the bodies move.
            const Vec3 mid = 0.5f * (mp.pointA + mp.pointB);
            p.anchorA = mid - bodies.centerOfMass[a];
            p.anchorB = mid - bodies.centerOfMass[b];
            p.localAnchorA = inverseRotationA * p.anchorA;
            p.localAnchorB = inverseRotationB * p.anchorB;
            p.baseSeparation = mp.separation;
            p.normalMass = effectiveMass(inverseMassSum, c.inverseInertiaA, c.inverseInertiaB, p.anchorA, p.anchorB, c.normal);
            const ContactImpulse& warm = contact.impulses[i];
            p.normalImpulse = warm.normal;
            if (c.friction > 0.0f) {
                p.tangentMass1 = effectiveMass(inverseMassSum, c.inverseInertiaA, c.inverseInertiaB, p.anchorA, p.anchorB, c.tangent1);
                p.tangentMass2 = effectiveMass(inverseMassSum, c.inverseInertiaA, c.inverseInertiaB, p.anchorA, p.anchorB, c.tangent2);
                p.tangentImpulse1 = warm.tangent1;
                p.tangentImpulse2 = warm.tangent2;
            } else {
                p.tangentMass1 = p.tangentMass2 = p.tangentImpulse1 = p.tangentImpulse2 = 0.0f;
            }
            p.maxNormalImpulse = 0.0f;
            const Vec3 dv = bodies.linearVelocity[b] + glm::cross(bodies.angularVelocity[b], p.anchorB) -
                            bodies.linearVelocity[a] - glm::cross(bodies.angularVelocity[a], p.anchorA);
            p.approachVelocity = glm::dot(dv, c.normal);
            maxPenetration_ = std::max(maxPenetration_, -mp.separation);
        }
    }
}

void ContactSolver::warmStart(BodyStorage& bodies) const {
    for (const Constraint& c : constraints_) {
        Vec3 vA = bodies.linearVelocity[c.bodyA], wA = bodies.angularVelocity[c.bodyA];
        Vec3 vB = bodies.linearVelocity[c.bodyB], wB = bodies.angularVelocity[c.bodyB];
        for (int i = 0; i < c.pointCount; ++i) {
            const Point& p = c.points[i];
            const Vec3 impulse = p.normalImpulse * c.normal + p.tangentImpulse1 * c.tangent1 + p.tangentImpulse2 * c.tangent2;
            vA -= c.inverseMassA * impulse;
            wA -= c.inverseInertiaA * glm::cross(p.anchorA, impulse);
            vB += c.inverseMassB * impulse;
            wB += c.inverseInertiaB * glm::cross(p.anchorB, impulse);
        }
        // Static, kinematic and sleeping bodies have zero inverse mass: writing back is a no-op.
        bodies.linearVelocity[c.bodyA] = vA;
        bodies.angularVelocity[c.bodyA] = wA;
        bodies.linearVelocity[c.bodyB] = vB;
        bodies.angularVelocity[c.bodyB] = wB;
    }
}

void ContactSolver::solve(BodyStorage& bodies, bool useBias) {
    const float inverseH = 1.0f / params_.substepDt;
    const bool soft = params_.solver.positionCorrection == PositionCorrection::SoftStep;
    const float maxPush = params_.solver.maxPushVelocity;

    for (Constraint& c : constraints_) {
        Vec3 vA = bodies.linearVelocity[c.bodyA], wA = bodies.angularVelocity[c.bodyA];
        Vec3 vB = bodies.linearVelocity[c.bodyB], wB = bodies.angularVelocity[c.bodyB];
        const Vec3 xA = bodies.centerOfMass[c.bodyA], xB = bodies.centerOfMass[c.bodyB];
        const Quat qA = bodies.orientation[c.bodyA], qB = bodies.orientation[c.bodyB];

        auto apply = [&](const Point& p, const Vec3& impulse) {
            vA -= c.inverseMassA * impulse;
            wA -= c.inverseInertiaA * glm::cross(p.anchorA, impulse);
            vB += c.inverseMassB * impulse;
            wB += c.inverseInertiaB * glm::cross(p.anchorB, impulse);
        };
        auto relativeVelocity = [&](const Point& p) {
            return vB + glm::cross(wB, p.anchorB) - vA - glm::cross(wA, p.anchorA);
        };

        for (int i = 0; i < c.pointCount; ++i) {
            Point& p = c.points[i];
            // Separation now, from how far the anchors moved since prepare.
            const Vec3 d = (xB + qB * p.localAnchorB) - (xA + qA * p.localAnchorA);
            const float separation = p.baseSeparation + glm::dot(d, c.normal);

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
            const float vn = glm::dot(relativeVelocity(p), c.normal);
            const float lambda = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
            const float accumulated = std::max(p.normalImpulse + lambda, 0.0f);
            const float delta = accumulated - p.normalImpulse;
            p.normalImpulse = accumulated;
            p.maxNormalImpulse = std::max(p.maxNormalImpulse, delta);
            apply(p, delta * c.normal);
        }

        if (c.friction > 0.0f) {
            for (int i = 0; i < c.pointCount; ++i) {
                Point& p = c.points[i];
                const Vec3 dv = relativeVelocity(p);
                float t1 = p.tangentImpulse1 - p.tangentMass1 * glm::dot(dv, c.tangent1);
                float t2 = p.tangentImpulse2 - p.tangentMass2 * glm::dot(dv, c.tangent2);
                // Coulomb: the tangential impulse lies in a disc of radius friction * normal impulse.
                const float limit = c.friction * p.normalImpulse;
                const float length2 = t1 * t1 + t2 * t2;
                if (length2 > limit * limit) {
                    const float scale = limit / std::sqrt(length2);
                    t1 *= scale;
                    t2 *= scale;
                }
                apply(p, (t1 - p.tangentImpulse1) * c.tangent1 + (t2 - p.tangentImpulse2) * c.tangent2);
                p.tangentImpulse1 = t1;
                p.tangentImpulse2 = t2;
            }
        }

        bodies.linearVelocity[c.bodyA] = vA;
        bodies.angularVelocity[c.bodyA] = wA;
        bodies.linearVelocity[c.bodyB] = vB;
        bodies.angularVelocity[c.bodyB] = wB;
    }
}

void ContactSolver::applyRestitution(BodyStorage& bodies) {
    const float threshold = params_.contact.restitutionThreshold;
    for (Constraint& c : constraints_) {
        if (c.restitution == 0.0f) continue;
        Vec3 vA = bodies.linearVelocity[c.bodyA], wA = bodies.angularVelocity[c.bodyA];
        Vec3 vB = bodies.linearVelocity[c.bodyB], wB = bodies.angularVelocity[c.bodyB];
        for (int i = 0; i < c.pointCount; ++i) {
            Point& p = c.points[i];
            // Only points that approached fast enough and actually pushed bounce.
            if (p.approachVelocity > -threshold || p.maxNormalImpulse == 0.0f) continue;
            const Vec3 dv = vB + glm::cross(wB, p.anchorB) - vA - glm::cross(wA, p.anchorA);
            const float vn = glm::dot(dv, c.normal);
            const float lambda = -p.normalMass * (vn + c.restitution * p.approachVelocity);
            const float accumulated = std::max(p.normalImpulse + lambda, 0.0f);
            const Vec3 impulse = (accumulated - p.normalImpulse) * c.normal;
            p.normalImpulse = accumulated;
            vA -= c.inverseMassA * impulse;
            wA -= c.inverseInertiaA * glm::cross(p.anchorA, impulse);
            vB += c.inverseMassB * impulse;
            wB += c.inverseInertiaB * glm::cross(p.anchorB, impulse);
        }
        bodies.linearVelocity[c.bodyA] = vA;
        bodies.angularVelocity[c.bodyA] = wA;
        bodies.linearVelocity[c.bodyB] = vB;
        bodies.angularVelocity[c.bodyB] = wB;
    }
}

void ContactSolver::storeImpulses(std::vector<Contact>& contacts) const {
    for (const Constraint& c : constraints_) {
        Contact& contact = contacts[c.contactIndex];
        for (int i = 0; i < c.pointCount; ++i) {
            const Point& p = c.points[i];
            contact.impulses[i] = {p.normalImpulse, p.tangentImpulse1, p.tangentImpulse2};
        }
    }
}

}  // namespace simcore
