#include "simcore/dynamics/contact_solver.h"

#include "simcore/dynamics/contact_rows_wide.h"

namespace simcore {

using namespace contact_rows_wide;

void ContactSolver::currentInverseInertia(const std::int32_t (&solverBodies)[kLanes], const BodyStorage& bodies,
                                          FloatW (&inverseInertia)[6]) const {
    for (int lane = 0; lane < kLanes; ++lane) {
        const BodyReference& ref = references_[solverBodies[lane]];
        setLanes(inverseInertia, lane, ref.moves ? bodies.inverseInertiaWorld[ref.denseIndex] : Mat3(0.0f));
    }
}

void ContactSolver::resolveCollisions(BodyStorage& bodies, ImpactTiming timing) {
    startFromVelocities(bodies);
    const FloatW zero = FloatW::zero(), one = FloatW::splat(1.0f);
    const FloatW threshold = FloatW::splat(-params_.contact.restitutionThreshold);
    const FloatW h = FloatW::splat(params_.substepDt);
    // Half a substep of gravity, signed: the velocities are staggered half a substep from the
    // positions (symplectic Euler), so the velocity at the instant of the positions is the stored one
    // plus (after the position update) or minus (before it) half a substep of acceleration. The
    // impact reverses that instantaneous velocity; reversing the stored one instead took g h |vn| of
    // energy out of every bounce (a ball dropped from 5 m came back 4 cm low each time).
    const float halfStep = (timing == ImpactTiming::AfterPositions ? 0.5f : -0.5f) * params_.substepDt;
    const Vec3W gravity{FloatW::splat(params_.gravity.x), FloatW::splat(params_.gravity.y), FloatW::splat(params_.gravity.z)};
    float* rows = velocities_.data()->value;
    const float* motion = motion_.data()->value;
    for (int pass = 0; pass < kMaxCollisionPasses; ++pass) {
        const bool collided = forEachBatch([&](ManifoldBatch& c) {
            if (!c.anyRestitution) return false;
            WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
            const WideBodies before = v;
            const PairMotionW pairMotion = gatherMotion(motion, c.bodyA, c.bodyB);
            const Vec3W normal = load(c.normal);
            // Impacts are large, so they take the bodies as they are now rather than at prepare: a box
            // spinning at 30 rad/s turns half a radian in a step, and impulses through the inertia
            // and arms of the step's start gave it up to a fifth more energy at every bounce.
            FloatW inertiaA[6], inertiaB[6];
            currentInverseInertia(c.bodyA, bodies, inertiaA);
            currentInverseInertia(c.bodyB, bodies, inertiaB);
            const SymMat3W inverseInertiaA = load(inertiaA), inverseInertiaB = load(inertiaB);

            // The points that collide (closing faster than the threshold and touching within a
            // substep) meet as one impact at their centre: a box landing flat bounces as a whole,
            // where impacts at its corners one after another set it spinning and took most of the
            // energy (a cube dropped flat from 40 m with restitution 1 came back to 6 m).
            FloatW count = zero, reach = zero;
            Vec3W centreA{zero, zero, zero}, centreB{zero, zero, zero};
            for (int i = 0; i < c.maxPointCount; ++i) {
                const PointBatch& p = c.points[i];
                const Vec3W preparedA = load(p.anchorA), preparedB = load(p.anchorB);
                const FloatW separation =
                    separationNow(pairMotion, normal, preparedA, preparedB, p.baseSeparation, c.radiusA, c.radiusB);
                const Vec3W anchorA = preparedA + pairMotion.turnA * preparedA;
                const Vec3W anchorB = preparedB + pairMotion.turnB * preparedB;
                const FloatW vn = alongAxis(v, normal, cross(anchorA, normal), cross(anchorB, normal));
                const MaskW collides = (vn < threshold) & (mulAdd(vn, h, separation) < zero) &
                                       (c.restitution > zero) & (p.normalMass > zero);
                const FloatW weight = select(collides, one, zero);
                count = count + weight;
                reach = mulAdd(weight, p.leverArm, reach);
                centreA = mulAdd(anchorA, weight, centreA);
                centreB = mulAdd(anchorB, weight, centreB);
            }
            const MaskW any = count > zero;
            if (!simd::any(any)) return false;
            const FloatW inverseCount = one / simd::max(count, one);
            centreA = centreA * inverseCount;
            centreB = centreB * inverseCount;
            const Vec3W angularA = cross(centreA, normal), angularB = cross(centreB, normal);
            const FloatW vn = alongAxis(v, normal, angularA, angularB);
            // Gravity's relative acceleration along the normal: it pulls on moving bodies only.
            const FloatW movesA = select(c.inverseMassA > zero, one, zero), movesB = select(c.inverseMassB > zero, one, zero);
            const FloatW halfStepApproach = FloatW::splat(halfStep) * dot(gravity, normal) * (movesB - movesA);
            const FloatW target = -(c.restitution * (vn + halfStepApproach)) - halfStepApproach;
            const FloatW mass =
                effectiveMass(c.inverseMassA + c.inverseMassB, inverseInertiaA, inverseInertiaB, angularA, angularB);
            const FloatW normalImpulse = select(any, simd::max(mass * (target - vn), zero), zero);
            applyImpulse(v, normal * normalImpulse, angularA * normalImpulse, angularB * normalImpulse, c.inverseMassA,
                         c.inverseMassB, inverseInertiaA, inverseInertiaB);
            if (c.anyFriction) {
                // Friction during the impact, bounded by the impact's own normal impulse.
                FloatW t1 = zero, t2 = zero, twist = zero;
                solveFriction(v, frictionRows(c), t1, t2, twist, c.friction * normalImpulse,
                              c.friction * normalImpulse * reach * inverseCount);
            }
            keepFiniteLanes(v, before);
            scatterVelocities(rows, c.storeA, c.storeB, v);
            return true;
        });
        if (!collided) break;
    }
    storeVelocities(bodies);
}

}  // namespace simcore
