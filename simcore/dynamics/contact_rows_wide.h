#pragma once
// The contact solver's rows in wide form: kLanes manifolds at once, one per SIMD lane. Shared by
// the solve and warm-start passes (contact_solver.cpp) and the collision pass (contact_impacts.cpp).

#include "simcore/math/simd.h"
#include "simcore/math/math.h"

#include <cstdint>

namespace simcore::contact_rows_wide {

using simd::FloatW;
using simd::MaskW;
using simd::SymMat3W;
using simd::Vec3W;

inline void setLanes(FloatW (&wide)[3], int lane, const Vec3& v) {
    wide[0].setLane(lane, v.x);
    wide[1].setLane(lane, v.y);
    wide[2].setLane(lane, v.z);
}

inline void setLanes(FloatW (&wide)[6], int lane, const Mat3& m) {  // symmetric: xx yy zz xy xz yz
    wide[0].setLane(lane, m[0][0]);
    wide[1].setLane(lane, m[1][1]);
    wide[2].setLane(lane, m[2][2]);
    wide[3].setLane(lane, m[1][0]);
    wide[4].setLane(lane, m[2][0]);
    wide[5].setLane(lane, m[2][1]);
}

// One lane of a wide vector or symmetric matrix: what setLanes wrote.
inline Vec3 laneOf(const FloatW (&wide)[3], int lane) { return {wide[0].lane(lane), wide[1].lane(lane), wide[2].lane(lane)}; }
inline Mat3 laneOf(const FloatW (&wide)[6], int lane) {
    const float xx = wide[0].lane(lane), yy = wide[1].lane(lane), zz = wide[2].lane(lane);
    const float xy = wide[3].lane(lane), xz = wide[4].lane(lane), yz = wide[5].lane(lane);
    return Mat3(xx, xy, xz, xy, yy, yz, xz, yz, zz);
}

SIMCORE_SIMD_INLINE Vec3W load(const FloatW (&wide)[3]) { return {wide[0], wide[1], wide[2]}; }
SIMCORE_SIMD_INLINE SymMat3W load(const FloatW (&wide)[6]) { return {wide[0], wide[1], wide[2], wide[3], wide[4], wide[5]}; }
SIMCORE_SIMD_INLINE void store(FloatW (&wide)[3], const Vec3W& v) {
    wide[0] = v.x;
    wide[1] = v.y;
    wide[2] = v.z;
}

// The two bodies of every lane, gathered from the solver's body rows and scattered back after.
struct WideBodies {
    Vec3W linearA, angularA, linearB, angularB;
};

// Per lane: `ifTrue`'s velocities where `m` is set, else `ifFalse`'s.
SIMCORE_SIMD_INLINE WideBodies selectLanes(MaskW m, const WideBodies& ifTrue, const WideBodies& ifFalse) {
    auto pick = [m](const Vec3W& t, const Vec3W& f) { return Vec3W{select(m, t.x, f.x), select(m, t.y, f.y), select(m, t.z, f.z)}; };
    return {pick(ifTrue.linearA, ifFalse.linearA), pick(ifTrue.angularA, ifFalse.angularA),
            pick(ifTrue.linearB, ifFalse.linearB), pick(ifTrue.angularB, ifFalse.angularB)};
}

// Gives lanes whose velocities a pass took beyond float (a contact between bodies flung kilometres
// apart at the speed bound has arms of kilometres) their velocities from before the pass, so no inf
// or NaN reaches a body, as the joint solver drops such a pass; returns the lanes kept. Zero times
// a value is zero unless the value is inf or NaN, and the ordered comparison fails on NaN.
SIMCORE_SIMD_INLINE MaskW keepFiniteLanes(WideBodies& v, const WideBodies& before) {
    const Vec3W sum = v.linearA + v.angularA + v.linearB + v.angularB;
    const MaskW finite = (sum.x + sum.y + sum.z) * FloatW::zero() < FloatW::splat(1.0f);
    if (!simd::all(finite)) v = selectLanes(finite, v, before);
    return finite;
}

SIMCORE_SIMD_INLINE WideBodies gatherVelocities(const float* rows, const std::int32_t* bodyA, const std::int32_t* bodyB) {
    FloatW a[8], b[8];
    simd::gatherRows(rows, bodyA, a);
    simd::gatherRows(rows, bodyB, b);
    return {{a[0], a[1], a[2]}, {a[4], a[5], a[6]}, {b[0], b[1], b[2]}, {b[4], b[5], b[6]}};
}

// storeA and storeB: the batch's rows to write (ManifoldBatch::storeA), not the bodies' own.
SIMCORE_SIMD_INLINE void scatterVelocities(float* rows, const std::int32_t* storeA, const std::int32_t* storeB, const WideBodies& v) {
    const FloatW zero = FloatW::zero();
    const FloatW a[8] = {v.linearA.x, v.linearA.y, v.linearA.z, zero, v.angularA.x, v.angularA.y, v.angularA.z, zero};
    const FloatW b[8] = {v.linearB.x, v.linearB.y, v.linearB.z, zero, v.angularB.x, v.angularB.y, v.angularB.z, zero};
    // The lanes of non-moving bodies (whose velocities are unchanged) all go to one scratch row.
    simd::scatterRows(rows, storeA, a);
    simd::scatterRows(rows, storeB, b);
}

// (R - I) for the rotation of a unit quaternion (x, y, z, w): how a body's anchors moved.
struct RotationDeltaW {
    FloatW m[3][3];

    SIMCORE_SIMD_INLINE RotationDeltaW(FloatW x, FloatW y, FloatW z, FloatW w) {
        const FloatW two = FloatW::splat(2.0f);
        const FloatW xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z;
        const FloatW wx = w * x, wy = w * y, wz = w * z;
        m[0][0] = -two * (yy + zz);
        m[0][1] = two * (xy - wz);
        m[0][2] = two * (xz + wy);
        m[1][0] = two * (xy + wz);
        m[1][1] = -two * (xx + zz);
        m[1][2] = two * (yz - wx);
        m[2][0] = two * (xz - wy);
        m[2][1] = two * (yz + wx);
        m[2][2] = -two * (xx + yy);
    }
    SIMCORE_SIMD_INLINE Vec3W operator*(const Vec3W& v) const {
        return {mulAdd(m[0][0], v.x, mulAdd(m[0][1], v.y, m[0][2] * v.z)),
                mulAdd(m[1][0], v.x, mulAdd(m[1][1], v.y, m[1][2] * v.z)),
                mulAdd(m[2][0], v.x, mulAdd(m[2][1], v.y, m[2][2] * v.z))};
    }
};

// Applies an impulse `linear` at the anchors: -linear on A, +linear on B.
SIMCORE_SIMD_INLINE void applyImpulse(WideBodies& v, const Vec3W& linear, const Vec3W& angularA, const Vec3W& angularB,
                  FloatW inverseMassA, FloatW inverseMassB, const SymMat3W& inverseInertiaA,
                  const SymMat3W& inverseInertiaB) {
    v.linearA = v.linearA - linear * inverseMassA;
    v.angularA = v.angularA - inverseInertiaA * angularA;
    v.linearB = mulAdd(linear, inverseMassB, v.linearB);
    v.angularB = v.angularB + inverseInertiaB * angularB;
}

// Relative velocity of B's anchor with respect to A's along an axis; rA x axis and rB x axis given.
SIMCORE_SIMD_INLINE FloatW alongAxis(const WideBodies& v, const Vec3W& axis, const Vec3W& angularA, const Vec3W& angularB) {
    return dot(v.linearB - v.linearA, axis) + dot(v.angularB, angularB) - dot(v.angularA, angularA);
}

// How far the two bodies of every lane moved and turned since prepare.
struct PairMotionW {
    Vec3W shift;  // B's displacement minus A's
    RotationDeltaW turnA, turnB;
};

SIMCORE_SIMD_INLINE PairMotionW gatherMotion(const float* rows, const std::int32_t* bodyA, const std::int32_t* bodyB) {
    FloatW a[8], b[8];
    simd::gatherRows(rows, bodyA, a);
    simd::gatherRows(rows, bodyB, b);
    return {Vec3W{b[0], b[1], b[2]} - Vec3W{a[0], a[1], a[2]}, RotationDeltaW(a[4], a[5], a[6], a[7]),
            RotationDeltaW(b[4], b[5], b[6], b[7])};
}

// A point's separation now. Each anchor sits on its body's surface at prepare, and its core
// (centre or segment) a rounding radius further in along the normal.
SIMCORE_SIMD_INLINE FloatW separationNow(const PairMotionW& motion, const Vec3W& normal, const Vec3W& anchorA,
                                         const Vec3W& anchorB, FloatW baseSeparation, FloatW radiusA, FloatW radiusB) {
    const Vec3W coreA = mulAdd(normal, -radiusA, anchorA);
    const Vec3W coreB = mulAdd(normal, radiusB, anchorB);
    const Vec3W d = motion.shift + motion.turnB * coreB - motion.turnA * coreA;
    return baseSeparation + dot(d, normal);
}

// The factor that scales a vector of squared length `length2` into the ball of radius `limit`
// (1 inside it).
SIMCORE_SIMD_INLINE FloatW clampScale(FloatW length2, FloatW limit) {
    return select(length2 > limit * limit, limit / simd::sqrt(simd::max(length2, FloatW::splat(1e-30f))),
                  FloatW::splat(1.0f));
}

// Coulomb: scales the tangential impulse (t1, t2) into the disc of radius `limit`.
SIMCORE_SIMD_INLINE void clampToDisc(FloatW& t1, FloatW& t2, FloatW limit) {
    const FloatW scale = clampScale(t1 * t1 + t2 * t2, limit);
    t1 = t1 * scale;
    t2 = t2 * scale;
}

// A pure angular impulse: -impulse on A, +impulse on B.
SIMCORE_SIMD_INLINE void applyAngularImpulse(WideBodies& v, const Vec3W& impulse, const SymMat3W& inverseInertiaA,
                                             const SymMat3W& inverseInertiaB) {
    v.angularA = v.angularA - inverseInertiaA * impulse;
    v.angularB = v.angularB + inverseInertiaB * impulse;
}

// Rolling resistance: the angular impulse that stops the relative turning wB - wA, accumulated and
// clamped to the ball of radius `limit` (the rolling lever times the summed normal impulse).
SIMCORE_SIMD_INLINE void solveRolling(WideBodies& v, const SymMat3W& rollingMass, const SymMat3W& inverseInertiaA,
                                      const SymMat3W& inverseInertiaB, FloatW (&impulse)[3], FloatW limit) {
    const Vec3W old{impulse[0], impulse[1], impulse[2]};
    const Vec3W unclamped = old - rollingMass * (v.angularB - v.angularA);
    const Vec3W clamped = unclamped * clampScale(dot(unclamped, unclamped), limit);
    applyAngularImpulse(v, clamped - old, inverseInertiaA, inverseInertiaB);
    impulse[0] = clamped.x;
    impulse[1] = clamped.y;
    impulse[2] = clamped.z;
}

// A manifold's friction rows, as prepared, and the bodies' inverse masses.
struct FrictionRowsW {
    Vec3W normal, tangent1, tangent2, centerA, centerB;
    FloatW tangentMass11, tangentMass22, tangentMass12;  // the 2x2 tangent block's inverse
    FloatW twistMass31, twistMass32, twistMass33;        // the 3x3 block inverse's twist row
    FloatW inverseMassA, inverseMassB;
    SymMat3W inverseInertiaA, inverseInertiaB;
};

SIMCORE_SIMD_INLINE void applyFriction(WideBodies& v, const FrictionRowsW& f, FloatW delta1, FloatW delta2,
                                       FloatW deltaTwist) {
    const Vec3W linear = mulAdd(f.tangent1, delta1, f.tangent2 * delta2);
    applyImpulse(v, linear, mulAdd(f.normal, deltaTwist, cross(f.centerA, linear)),
                 mulAdd(f.normal, deltaTwist, cross(f.centerB, linear)), f.inverseMassA, f.inverseMassB,
                 f.inverseInertiaA, f.inverseInertiaB);
}

// The twist about the normal as the three rows together would have it, clamped to twistLimit; then
// the two-row block at the friction centre, clamped into the disc of radius linearLimit. Unclamped,
// the two solves are the 3x3 block's solution.
SIMCORE_SIMD_INLINE void solveFriction(WideBodies& v, const FrictionRowsW& f, FloatW& impulse1, FloatW& impulse2,
                                       FloatW& twist, FloatW linearLimit, FloatW twistLimit) {
    const Vec3W angularA1 = cross(f.centerA, f.tangent1), angularB1 = cross(f.centerB, f.tangent1);
    const Vec3W angularA2 = cross(f.centerA, f.tangent2), angularB2 = cross(f.centerB, f.tangent2);
    FloatW slip1 = alongAxis(v, f.tangent1, angularA1, angularB1);
    FloatW slip2 = alongAxis(v, f.tangent2, angularA2, angularB2);
    const FloatW twistSpeed = dot(v.angularB - v.angularA, f.normal);
    const FloatW twistChange = f.twistMass31 * slip1 + f.twistMass32 * slip2 + f.twistMass33 * twistSpeed;
    const FloatW newTwist = simd::min(simd::max(twist - twistChange, -twistLimit), twistLimit);
    applyFriction(v, f, FloatW::zero(), FloatW::zero(), newTwist - twist);
    twist = newTwist;

    slip1 = alongAxis(v, f.tangent1, angularA1, angularB1);
    slip2 = alongAxis(v, f.tangent2, angularA2, angularB2);
    FloatW t1 = impulse1 - mulAdd(f.tangentMass11, slip1, f.tangentMass12 * slip2);
    FloatW t2 = impulse2 - mulAdd(f.tangentMass12, slip1, f.tangentMass22 * slip2);
    clampToDisc(t1, t2, linearLimit);
    applyFriction(v, f, t1 - impulse1, t2 - impulse2, FloatW::zero());
    impulse1 = t1;
    impulse2 = t2;
}

// Any batch type with the prepared friction members (ContactSolver::ManifoldBatch).
template <class Batch>
SIMCORE_SIMD_INLINE FrictionRowsW frictionRows(const Batch& c) {
    return {load(c.normal),         load(c.tangent1),       load(c.tangent2),       load(c.centerA),
            load(c.centerB),        c.tangentMass[0],       c.tangentMass[1],       c.tangentMass[2],
            c.twistMass[0],         c.twistMass[1],         c.twistMass[2],         c.inverseMassA,
            c.inverseMassB,         load(c.inverseInertiaA), load(c.inverseInertiaB)};
}

// 1 / (J M^-1 J^T) of a row with levers anchor x axis on each body; zero where neither body can move.
SIMCORE_SIMD_INLINE FloatW effectiveMass(FloatW inverseMassSum, const SymMat3W& inverseInertiaA,
                                         const SymMat3W& inverseInertiaB, const Vec3W& angularA,
                                         const Vec3W& angularB) {
    const FloatW k = inverseMassSum + dot(angularA, inverseInertiaA * angularA) + dot(angularB, inverseInertiaB * angularB);
    const FloatW zero = FloatW::zero();
    return select(k > zero, FloatW::splat(1.0f) / simd::max(k, FloatW::splat(1e-30f)), zero);
}

}  // namespace simcore::contact_rows_wide
