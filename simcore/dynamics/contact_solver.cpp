#include "simcore/dynamics/contact_solver.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace simcore {

namespace {

using simd::FloatW;
using simd::MaskW;
using simd::SymMat3W;
using simd::Vec3W;

// Batches per chunk of a colour run in parallel: a batch costs a few hundred nanoseconds, so a
// handful outweighs handing the chunk to a thread, and a colour of pyramid10 (some 20 batches)
// still splits.
constexpr std::size_t kBatchGrain = 4;

// Friction tangents for a manifold with friction centre `centre`. While the bodies slip there, the
// first tangent follows the slip: with axes at an angle to it, the clamped friction pointed off the
// slip direction and came out weak (3.6 % on a box sliding down a 30-degree incline, with the rows
// solved one after the other). Without slip any continuous basis serves.
void frictionAxes(const Vec3& n, const Vec3& centre, const BodyStorage& bodies, std::size_t a, std::size_t b, Vec3& t1,
                  Vec3& t2) {
    const Vec3 relative = bodies.linearVelocity[b] + glm::cross(bodies.angularVelocity[b], centre - bodies.centerOfMass[b]) -
                          bodies.linearVelocity[a] - glm::cross(bodies.angularVelocity[a], centre - bodies.centerOfMass[a]);
    const Vec3 slip = relative - glm::dot(relative, n) * n;
    constexpr float kMinSlipSpeed = 1e-3f;  // m/s; below it the direction is noise
    if (lengthSquared(slip) > kMinSlipSpeed * kMinSlipSpeed) {
        t1 = glm::normalize(slip);
        t2 = glm::cross(n, t1);
    } else {
        orthonormalBasis(n, t1, t2);
    }
}

float roundingRadius(const Shape& shape) {
    return shape.type == ShapeType::Sphere || shape.type == ShapeType::Capsule ? shape.radius : 0.0f;
}

void setLanes(FloatW (&wide)[3], int lane, const Vec3& v) {
    wide[0].setLane(lane, v.x);
    wide[1].setLane(lane, v.y);
    wide[2].setLane(lane, v.z);
}

void setLanes(FloatW (&wide)[6], int lane, const Mat3& m) {  // symmetric: xx yy zz xy xz yz
    wide[0].setLane(lane, m[0][0]);
    wide[1].setLane(lane, m[1][1]);
    wide[2].setLane(lane, m[2][2]);
    wide[3].setLane(lane, m[1][0]);
    wide[4].setLane(lane, m[2][0]);
    wide[5].setLane(lane, m[2][1]);
}

SIMCORE_SIMD_INLINE Vec3W load(const FloatW (&wide)[3]) { return {wide[0], wide[1], wide[2]}; }
SIMCORE_SIMD_INLINE SymMat3W load(const FloatW (&wide)[6]) { return {wide[0], wide[1], wide[2], wide[3], wide[4], wide[5]}; }

// The two bodies of every lane, gathered from the solver's body rows and scattered back after.
struct WideBodies {
    Vec3W linearA, angularA, linearB, angularB;
};

// Gives lanes whose velocities a pass took beyond float (a contact between bodies flung kilometres
// apart at the speed bound has arms of kilometres) their velocities from before the pass, so no inf
// or NaN reaches a body, as the joint solver drops such a pass; returns the lanes kept. Zero times
// a value is zero unless the value is inf or NaN, and the ordered comparison fails on NaN.
SIMCORE_SIMD_INLINE MaskW keepFiniteLanes(WideBodies& v, const WideBodies& before) {
    const Vec3W sum = v.linearA + v.angularA + v.linearB + v.angularB;
    const MaskW finite = (sum.x + sum.y + sum.z) * FloatW::zero() < FloatW::splat(1.0f);
    if (simd::all(finite)) return finite;
    auto keep = [&](Vec3W& now, const Vec3W& old) {
        now = {select(finite, now.x, old.x), select(finite, now.y, old.y), select(finite, now.z, old.z)};
    };
    keep(v.linearA, before.linearA);
    keep(v.angularA, before.angularA);
    keep(v.linearB, before.linearB);
    keep(v.angularB, before.angularB);
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

// A point's separation now. The anchors sit mid-gap at prepare; each body's surface is half the
// gap away along the normal and its core (centre or segment) a rounding radius further.
SIMCORE_SIMD_INLINE FloatW separationNow(const PairMotionW& motion, const Vec3W& normal, const Vec3W& anchorA,
                                         const Vec3W& anchorB, FloatW baseSeparation, FloatW radiusA, FloatW radiusB) {
    const FloatW halfGap = FloatW::splat(0.5f) * baseSeparation;
    const Vec3W coreA = mulAdd(normal, -(halfGap + radiusA), anchorA);
    const Vec3W coreB = mulAdd(normal, halfGap + radiusB, anchorB);
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
    FloatW tangentMass11, tangentMass22, tangentMass12, twistMass;
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

// Twist about the normal, then the two-row block at the friction centre, each accumulated impulse
// clamped to its Coulomb bound (the block's into the disc of radius linearLimit).
SIMCORE_SIMD_INLINE void solveFriction(WideBodies& v, const FrictionRowsW& f, FloatW& impulse1, FloatW& impulse2,
                                       FloatW& twist, FloatW linearLimit, FloatW twistLimit) {
    const FloatW twistSpeed = dot(v.angularB - v.angularA, f.normal);
    const FloatW newTwist = simd::min(simd::max(twist - f.twistMass * twistSpeed, -twistLimit), twistLimit);
    applyFriction(v, f, FloatW::zero(), FloatW::zero(), newTwist - twist);
    twist = newTwist;

    const FloatW slip1 = alongAxis(v, f.tangent1, cross(f.centerA, f.tangent1), cross(f.centerB, f.tangent1));
    const FloatW slip2 = alongAxis(v, f.tangent2, cross(f.centerA, f.tangent2), cross(f.centerB, f.tangent2));
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
            c.twistMass,            c.inverseMassA,         c.inverseMassB,         load(c.inverseInertiaA),
            load(c.inverseInertiaB)};
}

// (IA^-1 + IB^-1)^-1, the rolling block's mass matrix, inverted in double (a small body's inverse
// moments cubed overflow float); zero where it is singular (neither body can turn).
Mat3 rollingMass(const Mat3& inverseInertiaA, const Mat3& inverseInertiaB) {
    const glm::dmat3 k = glm::dmat3(inverseInertiaA) + glm::dmat3(inverseInertiaB);
    const double determinant = glm::determinant(k);
    if (!(determinant > 0.0) || !std::isfinite(determinant)) return Mat3(0.0f);
    return Mat3(glm::inverse(k));
}

// 1 / (J M^-1 J^T) of a row along `axis` at the two anchors; zero where neither body can move.
SIMCORE_SIMD_INLINE FloatW effectiveMass(FloatW inverseMassSum, const SymMat3W& inverseInertiaA,
                                         const SymMat3W& inverseInertiaB, const Vec3W& anchorA, const Vec3W& anchorB,
                                         const Vec3W& axis) {
    const Vec3W angularA = cross(anchorA, axis), angularB = cross(anchorB, axis);
    const FloatW k = inverseMassSum + dot(angularA, inverseInertiaA * angularA) + dot(angularB, inverseInertiaB * angularB);
    const FloatW zero = FloatW::zero();
    return select(k > zero, FloatW::splat(1.0f) / simd::max(k, FloatW::splat(1e-30f)), zero);
}

// How a solve pass turns separation into a velocity target. Speculative points (separation > 0)
// may close the gap in one substep and no more; overlapping ones are pushed out by the chosen
// position correction, or not at all in relax passes.
struct Correction {
    enum class Mode { None, Soft, Baumgarte } mode;
    FloatW inverseH, biasRate, massScale, impulseScale, maxPush, baumgarte, linearSlop;
};

}  // namespace

std::int32_t ContactSolver::solverBody(std::size_t denseIndex, const BodyStorage& bodies) {
    if (bodies.motion[denseIndex] == MotionType::Static) return 0;
    std::int32_t& index = denseToSolver_[denseIndex];
    if (index < 0) {
        index = static_cast<std::int32_t>(references_.size());
        const bool moves = bodies.motion[denseIndex] == MotionType::Dynamic && bodies.awake[denseIndex];
        references_.push_back({static_cast<std::uint32_t>(denseIndex), moves, bodies.centerOfMass[denseIndex],
                               bodies.orientation[denseIndex]});
        bodyColors_.push_back(0);
    }
    return index;
}

void ContactSolver::prepare(const std::vector<Contact>& contacts, const BodyStorage& bodies, const Params& params,
                            TaskPool& pool) {
    params_ = params;
    pool_ = &pool;
    maxPenetration_ = 0.0f;
    usesFriction_ = false;
    usesRestitution_ = false;

    const float h = params.substepDt;
    soft_ = SoftConstraint::make(SoftConstraint::cappedHertz(params.solver.contactHertz, h),
                                 params.solver.contactDampingRatio, h);

    // Solver bodies: entry 0 stands for every static body (zero velocity, never moves).
    references_.clear();
    references_.push_back({0, false, Vec3(0.0f), Quat(1.0f, 0.0f, 0.0f, 0.0f)});
    bodyColors_.assign(1, 0);
    denseToSolver_.assign(bodies.size(), -1);

    // Colour greedily in contact order (deterministic): the lowest colour free at both moving
    // bodies. Immovable bodies are only read, so any number of lanes may share them. A manifold
    // that finds no free colour goes to the overflow, solved one manifold per batch.
    std::array<std::uint32_t, kColorCount + 1> perColor{};
    order_.clear();
    colorOf_.clear();
    for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& contact = contacts[ci];
        if (contact.manifold.pointCount == 0) continue;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.motion[a] == MotionType::Dynamic && bodies.awake[a];
        const bool movesB = bodies.motion[b] == MotionType::Dynamic && bodies.awake[b];
        if (!movesA && !movesB) continue;
        const std::int32_t sa = solverBody(a, bodies), sb = solverBody(b, bodies);
        const std::uint64_t used = (movesA ? bodyColors_[sa] : 0) | (movesB ? bodyColors_[sb] : 0);
        int color = kOverflow;
        if (used != ~std::uint64_t{0}) {
            color = std::countr_zero(~used);
            const std::uint64_t bit = std::uint64_t{1} << color;
            if (movesA) bodyColors_[sa] |= bit;
            if (movesB) bodyColors_[sb] |= bit;
        }
        order_.push_back(static_cast<std::uint32_t>(ci));
        colorOf_.push_back(static_cast<std::uint8_t>(color));
        ++perColor[color];
    }
    constraintCount_ = order_.size();

    // Batches colour by colour; a colour's manifolds fill lanes in contact order.
    std::array<std::uint32_t, kColorCount + 1> filled{};
    std::uint32_t batchCount = 0;
    colorCount_ = 0;
    for (int color = 0; color <= kColorCount; ++color) {
        colorFirstBatch_[color] = batchCount;
        const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
        batchCount += (perColor[color] + lanes - 1) / lanes;
        if (perColor[color] > 0) ++colorCount_;
    }
    colorFirstBatch_[kOverflow + 1] = batchCount;
    batches_.assign(batchCount, ManifoldBatch{});
    // Every lane writes back to its batch's scratch row (after the solver bodies' rows) unless it
    // has a moving body, set below.
    for (std::size_t k = 0; k < batches_.size(); ++k) {
        const auto scratchRow = static_cast<std::int32_t>(references_.size() + k);
        std::fill(std::begin(batches_[k].storeA), std::end(batches_[k].storeA), scratchRow);
        std::fill(std::begin(batches_[k].storeB), std::end(batches_[k].storeB), scratchRow);
    }

    for (std::size_t k = 0; k < order_.size(); ++k) {
        const std::uint32_t ci = order_[k];
        const int color = colorOf_[k];
        const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
        const std::uint32_t slot = filled[color]++;
        ManifoldBatch& batch = batches_[colorFirstBatch_[color] + slot / lanes];
        const int lane = static_cast<int>(slot % lanes);

        const Contact& contact = contacts[ci];
        const ContactManifold& manifold = contact.manifold;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.motion[a] == MotionType::Dynamic && bodies.awake[a];
        const bool movesB = bodies.motion[b] == MotionType::Dynamic && bodies.awake[b];
        batch.bodyA[lane] = solverBody(a, bodies);
        batch.bodyB[lane] = solverBody(b, bodies);
        if (movesA) batch.storeA[lane] = batch.bodyA[lane];
        if (movesB) batch.storeB[lane] = batch.bodyB[lane];
        batch.contactIndex[lane] = ci;
        batch.pointCount[lane] = static_cast<std::uint8_t>(manifold.pointCount);
        batch.maxPointCount = std::max(batch.maxPointCount, batch.pointCount[lane]);

        const float inverseMassA = movesA ? bodies.inverseMass[a] : 0.0f;
        const float inverseMassB = movesB ? bodies.inverseMass[b] : 0.0f;
        const Mat3 inverseInertiaA = movesA ? bodies.inverseInertiaWorld[a] : Mat3(0.0f);
        const Mat3 inverseInertiaB = movesB ? bodies.inverseInertiaWorld[b] : Mat3(0.0f);
        batch.inverseMassA.setLane(lane, inverseMassA);
        batch.inverseMassB.setLane(lane, inverseMassB);
        setLanes(batch.inverseInertiaA, lane, inverseInertiaA);
        setLanes(batch.inverseInertiaB, lane, inverseInertiaB);

        // The friction centre: the mean of the points, each midway between the surfaces.
        Vec3 centre(0.0f);
        for (int i = 0; i < manifold.pointCount; ++i) centre += manifold.points[i].pointA + manifold.points[i].pointB;
        centre *= 0.5f / static_cast<float>(manifold.pointCount);
        const Vec3& normal = manifold.normal;
        Vec3 tangent1, tangent2;
        frictionAxes(normal, centre, bodies, a, b, tangent1, tangent2);
        setLanes(batch.normal, lane, normal);
        setLanes(batch.tangent1, lane, tangent1);
        setLanes(batch.tangent2, lane, tangent2);
        // With friction off (or zero for this pair) the friction rows have zero mass: no effect.
        const float friction = params.friction ? contact.friction : 0.0f;
        const float restitution = params.restitution ? contact.restitution : 0.0f;
        batch.radiusA.setLane(lane, roundingRadius(subShape(bodies.shape[a], contact.subShapeA)));
        batch.radiusB.setLane(lane, roundingRadius(subShape(bodies.shape[b], contact.subShapeB)));
        batch.friction.setLane(lane, friction);
        batch.restitution.setLane(lane, restitution);
        batch.anyFriction = batch.anyFriction || friction > 0.0f;
        batch.anyRestitution = batch.anyRestitution || restitution > 0.0f;
        usesFriction_ = usesFriction_ || friction > 0.0f;
        usesRestitution_ = usesRestitution_ || restitution > 0.0f;
        // Rolling resistance belongs to the friction effect: off with it.
        const float rollingLever = params.friction ? contact.rollingLever : 0.0f;
        if (rollingLever > 0.0f) {
            batch.rollingLever.setLane(lane, rollingLever);
            setLanes(batch.rollingMass, lane, rollingMass(inverseInertiaA, inverseInertiaB));
            setLanes(batch.rollingImpulse, lane, contact.frictionImpulse.rolling);
            batch.anyRolling = true;
            usesFriction_ = true;
        }

        setLanes(batch.centerA, lane, centre - bodies.centerOfMass[a]);
        setLanes(batch.centerB, lane, centre - bodies.centerOfMass[b]);
        if (friction > 0.0f) {
            batch.tangentImpulse1.setLane(lane, glm::dot(contact.frictionImpulse.linear, tangent1));
            batch.tangentImpulse2.setLane(lane, glm::dot(contact.frictionImpulse.linear, tangent2));
            batch.twistImpulse.setLane(lane, contact.frictionImpulse.twist);
        }
        for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& mp = manifold.points[i];
            PointBatch& p = batch.points[i];
            // Both anchors at the midpoint: then the separation's change is just the change of
            // (anchorB - anchorA) along the normal as the bodies move.
            const Vec3 mid = 0.5f * (mp.pointA + mp.pointB);
            const Vec3 anchorA = mid - bodies.centerOfMass[a];
            const Vec3 anchorB = mid - bodies.centerOfMass[b];
            setLanes(p.anchorA, lane, anchorA);
            setLanes(p.anchorB, lane, anchorB);
            p.baseSeparation.setLane(lane, mp.separation);
            p.leverArm.setLane(lane, glm::length(mid - centre));
            p.normalImpulse.setLane(lane, contact.impulses[i].normal);
            maxPenetration_ = std::max(maxPenetration_, -mp.separation);
        }
    }

    // Effective masses, a batch at a time (each on its own: in parallel).
    pool.parallelFor(batches_.size(), kBatchGrain, [this](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) computeEffectiveMasses(batches_[k]);
    });

    velocities_.assign(references_.size() + batches_.size(), BodyRow{});
    motion_.assign(references_.size(), BodyRow{});
    motion_[0].value[7] = 1.0f;  // the immovable body's rotation: identity
}

// A batch's effective masses; zero for the rows of absent points and of frictionless lanes, so those
// rows do nothing.
void ContactSolver::computeEffectiveMasses(ManifoldBatch& c) {
    const FloatW zero = FloatW::zero(), one = FloatW::splat(1.0f), tiny = FloatW::splat(1e-30f);
    const FloatW inverseMassSum = c.inverseMassA + c.inverseMassB;
    const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);
    const Vec3W normal = load(c.normal), tangent1 = load(c.tangent1), tangent2 = load(c.tangent2);
    FloatW pointCount = zero;
    for (int lane = 0; lane < kLanes; ++lane) pointCount.setLane(lane, c.pointCount[lane]);
    for (int i = 0; i < c.maxPointCount; ++i) {
        PointBatch& p = c.points[i];
        const MaskW exists = pointCount > FloatW::splat(static_cast<float>(i));
        p.normalMass = select(exists, effectiveMass(inverseMassSum, inverseInertiaA, inverseInertiaB, load(p.anchorA),
                                                    load(p.anchorB), normal),
                              zero);
    }
    if (!c.anyFriction) return;
    const MaskW hasFriction = c.friction > zero;
    const Vec3W centerA = load(c.centerA), centerB = load(c.centerB);
    const Vec3W a1 = cross(centerA, tangent1), a2 = cross(centerA, tangent2);
    const Vec3W b1 = cross(centerB, tangent1), b2 = cross(centerB, tangent2);
    const Vec3W ia1 = inverseInertiaA * a1, ib1 = inverseInertiaB * b1;
    const FloatW k11 = inverseMassSum + dot(a1, ia1) + dot(b1, ib1);
    const FloatW k22 = inverseMassSum + dot(a2, inverseInertiaA * a2) + dot(b2, inverseInertiaB * b2);
    const FloatW k12 = dot(a2, ia1) + dot(b2, ib1);
    const FloatW determinant = k11 * k22 - k12 * k12;
    const MaskW invertible = hasFriction & (determinant > zero);
    const FloatW inverseDeterminant = one / simd::max(determinant, tiny);
    c.tangentMass[0] = select(invertible, k22 * inverseDeterminant, zero);
    c.tangentMass[1] = select(invertible, k11 * inverseDeterminant, zero);
    c.tangentMass[2] = select(invertible, -(k12 * inverseDeterminant), zero);
    const FloatW kTwist = dot(normal, inverseInertiaA * normal) + dot(normal, inverseInertiaB * normal);
    c.twistMass = select(hasFriction & (kTwist > zero), one / simd::max(kTwist, tiny), zero);
}

void ContactSolver::loadVelocities(const BodyStorage& bodies) {
    for (std::size_t s = 1; s < references_.size(); ++s) {
        const std::uint32_t i = references_[s].denseIndex;
        const Vec3& v = bodies.linearVelocity[i];
        const Vec3& w = bodies.angularVelocity[i];
        velocities_[s] = {{v.x, v.y, v.z, 0.0f, w.x, w.y, w.z, 0.0f}};
    }
}

void ContactSolver::loadMotion(const BodyStorage& bodies) {
    for (std::size_t s = 1; s < references_.size(); ++s) {
        const BodyReference& ref = references_[s];
        const Vec3 d = bodies.centerOfMass[ref.denseIndex] - ref.centerOfMass;
        const Quat q = bodies.orientation[ref.denseIndex] * glm::conjugate(ref.orientation);
        motion_[s] = {{d.x, d.y, d.z, 0.0f, q.x, q.y, q.z, q.w}};
    }
}

void ContactSolver::storeVelocities(BodyStorage& bodies) const {
    for (std::size_t s = 1; s < references_.size(); ++s) {
        const BodyReference& ref = references_[s];
        if (!ref.moves) continue;
        const float* row = velocities_[s].value;
        bodies.linearVelocity[ref.denseIndex] = Vec3(row[0], row[1], row[2]);
        bodies.angularVelocity[ref.denseIndex] = Vec3(row[4], row[5], row[6]);
    }
}

template <class SolveBatch>
bool ContactSolver::forEachBatch(SolveBatch&& solveBatch) {
    bool any = false;
    for (int color = 0; color < kOverflow; ++color) {
        const std::size_t first = colorFirstBatch_[color];
        const std::size_t hits = pool_->parallelSum(colorFirstBatch_[color + 1] - first, kBatchGrain,
                                                    [&](std::size_t begin, std::size_t end) {
                                                        std::uint64_t count = 0;
                                                        for (std::size_t k = first + begin; k < first + end; ++k)
                                                            if (solveBatch(batches_[k])) ++count;
                                                        return count;
                                                    });
        any = any || hits > 0;
    }
    // The overflow's batches may share moving bodies: one after another.
    for (std::size_t k = colorFirstBatch_[kOverflow]; k < colorFirstBatch_[kOverflow + 1]; ++k)
        if (solveBatch(batches_[k])) any = true;
    return any;
}

void ContactSolver::warmStart(BodyStorage& bodies) {
    loadVelocities(bodies);
    float* rows = velocities_.data()->value;
    forEachBatch([&](const ManifoldBatch& c) {
        WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
        const FrictionRowsW f = frictionRows(c);
        for (int i = 0; i < c.maxPointCount; ++i) {
            const PointBatch& p = c.points[i];
            const Vec3W impulse = f.normal * p.normalImpulse;
            applyImpulse(v, impulse, cross(load(p.anchorA), impulse), cross(load(p.anchorB), impulse), c.inverseMassA,
                         c.inverseMassB, f.inverseInertiaA, f.inverseInertiaB);
        }
        if (c.anyRolling) applyAngularImpulse(v, load(c.rollingImpulse), f.inverseInertiaA, f.inverseInertiaB);
        if (c.anyFriction) applyFriction(v, f, c.tangentImpulse1, c.tangentImpulse2, c.twistImpulse);
        scatterVelocities(rows, c.storeA, c.storeB, v);
        return false;
    });
    storeVelocities(bodies);
}

bool ContactSolver::solve(BodyStorage& bodies, bool useBias) {
    loadVelocities(bodies);
    loadMotion(bodies);
    Correction correction;
    if (!useBias)
        correction.mode = Correction::Mode::None;
    else if (params_.solver.positionCorrection == PositionCorrection::SoftStep)
        correction.mode = Correction::Mode::Soft;
    else
        correction.mode = Correction::Mode::Baumgarte;
    const float inverseH = 1.0f / params_.substepDt;
    correction.inverseH = FloatW::splat(inverseH);
    correction.biasRate = FloatW::splat(soft_.biasRate);
    correction.massScale = FloatW::splat(soft_.massScale);
    correction.impulseScale = FloatW::splat(soft_.impulseScale);
    correction.maxPush = FloatW::splat(-params_.solver.maxPushVelocity);
    correction.baumgarte = FloatW::splat(params_.solver.baumgarte * inverseH);
    correction.linearSlop = FloatW::splat(params_.contact.linearSlop);
    const FloatW zero = FloatW::zero(), one = FloatW::splat(1.0f);
    // Friction is solved in the relax passes, where the normal impulses hold the bodies without the
    // push (Box3D's order); with no relax pass, in the velocity passes. Solved in the pushing passes
    // too, it carries the push between the side faces of neighbours: a pyramid of base 20 bounced
    // and toppled (1.19 m in 10 s; 4 mm without).
    const bool relaxes = params_.solver.positionCorrection == PositionCorrection::SoftStep && params_.solver.positionIterations > 0;
    const bool frictionInPass = useBias != relaxes;

    const FloatW settleTolerance = FloatW::splat(kRelaxTolerance);
    const FloatW deepOverlap = FloatW::splat(-params_.contact.linearSlop);
    float* rows = velocities_.data()->value;
    const float* motion = motion_.data()->value;
    // Whether any batch still pushes; each batch's largest excess starts afresh (the maximum over
    // all of them is above zero exactly when one batch's is).
    const bool pushLeft = forEachBatch([&](ManifoldBatch& c) {
        FloatW largestExcess = FloatW::splat(-1.0f);
        WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
        const WideBodies before = v;
        const Vec3W normal = load(c.normal);
        const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);

        const PairMotionW pairMotion = gatherMotion(motion, c.bodyA, c.bodyB);

        for (int i = 0; i < c.maxPointCount; ++i) {
            PointBatch& p = c.points[i];
            const Vec3W anchorA = load(p.anchorA), anchorB = load(p.anchorB);
            const FloatW separation =
                separationNow(pairMotion, normal, anchorA, anchorB, p.baseSeparation, c.radiusA, c.radiusB);

            const MaskW speculative = separation > zero;
            const FloatW arrive = separation * correction.inverseH;
            FloatW bias = select(speculative, arrive, zero), massScale = one, impulseScale = zero;
            if (correction.mode == Correction::Mode::Soft) {
                bias = select(speculative, arrive, simd::max(correction.biasRate * separation, correction.maxPush));
                massScale = select(speculative, one, correction.massScale);
                impulseScale = select(speculative, zero, correction.impulseScale);
            } else if (correction.mode == Correction::Mode::Baumgarte) {
                const FloatW overlap = simd::min(separation + correction.linearSlop, zero);
                bias = select(speculative, arrive, simd::max(correction.baumgarte * overlap, correction.maxPush));
            }

            const Vec3W angularA = cross(anchorA, normal), angularB = cross(anchorB, normal);
            const FloatW vn = alongAxis(v, normal, angularA, angularB);
            const FloatW lambda = -(p.normalMass * massScale * (vn + bias)) - impulseScale * p.normalImpulse;
            const FloatW accumulated = simd::max(p.normalImpulse + lambda, zero);
            const FloatW delta = accumulated - p.normalImpulse;
            p.normalImpulse = accumulated;
            applyImpulse(v, normal * delta, angularA * delta, angularB * delta, c.inverseMassA, c.inverseMassB,
                         inverseInertiaA, inverseInertiaB);
            // The velocity this row changed, beyond the tolerance (delta / normalMass, kept as a product).
            // Only where the bodies overlap beyond the slop, where the velocity passes pushed.
            const FloatW excess = simd::max(delta, -delta) - settleTolerance * p.normalMass;
            largestExcess = simd::max(largestExcess, select(separation < deepOverlap, excess, FloatW::splat(-1.0f)));
        }

        if ((c.anyFriction || c.anyRolling) && frictionInPass) {
            FloatW normalSum = zero, twistReach = zero;
            for (int i = 0; i < c.maxPointCount; ++i) {
                normalSum = normalSum + c.points[i].normalImpulse;
                twistReach = mulAdd(c.points[i].normalImpulse, c.points[i].leverArm, twistReach);
            }
            // Rolling resistance before the friction rows (Box3D solves it just before the tangent
            // block), so the friction that follows holds the contact point still at the turn
            // rolling resistance left: the whole body slows, not only its spin.
            if (c.anyRolling)
                solveRolling(v, load(c.rollingMass), inverseInertiaA, inverseInertiaB, c.rollingImpulse,
                             c.rollingLever * normalSum);
            if (c.anyFriction)
                solveFriction(v, frictionRows(c), c.tangentImpulse1, c.tangentImpulse2, c.twistImpulse,
                              c.friction * normalSum, c.friction * twistReach);
        }
        const MaskW kept = keepFiniteLanes(v, before);
        if (!simd::all(kept)) {  // and their impulses, which would overflow the next warm start
            for (int i = 0; i < c.maxPointCount; ++i) c.points[i].normalImpulse = select(kept, c.points[i].normalImpulse, zero);
            c.tangentImpulse1 = select(kept, c.tangentImpulse1, zero);
            c.tangentImpulse2 = select(kept, c.tangentImpulse2, zero);
            c.twistImpulse = select(kept, c.twistImpulse, zero);
            for (FloatW& rolling : c.rollingImpulse) rolling = select(kept, rolling, zero);
        }
        scatterVelocities(rows, c.storeA, c.storeB, v);
        return simd::any(largestExcess > zero);
    });
    storeVelocities(bodies);
    return pushLeft;
}

void ContactSolver::currentInverseInertia(const std::int32_t (&solverBodies)[kLanes], const BodyStorage& bodies,
                                          FloatW (&inverseInertia)[6]) const {
    for (int lane = 0; lane < kLanes; ++lane) {
        const BodyReference& ref = references_[solverBodies[lane]];
        setLanes(inverseInertia, lane, ref.moves ? bodies.inverseInertiaWorld[ref.denseIndex] : Mat3(0.0f));
    }
}

void ContactSolver::resolveCollisions(BodyStorage& bodies, ImpactTiming timing) {
    loadVelocities(bodies);
    loadMotion(bodies);
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
            const FloatW mass = effectiveMass(c.inverseMassA + c.inverseMassB, inverseInertiaA, inverseInertiaB, centreA,
                                              centreB, normal);
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

void ContactSolver::storeImpulses(std::vector<Contact>& contacts) const {
    for (const ManifoldBatch& c : batches_) {
        for (int lane = 0; lane < kLanes; ++lane) {
            if (c.pointCount[lane] == 0) continue;
            Contact& contact = contacts[c.contactIndex[lane]];
            const Vec3 tangent1(c.tangent1[0].lane(lane), c.tangent1[1].lane(lane), c.tangent1[2].lane(lane));
            const Vec3 tangent2(c.tangent2[0].lane(lane), c.tangent2[1].lane(lane), c.tangent2[2].lane(lane));
            for (int i = 0; i < c.pointCount[lane]; ++i) contact.impulses[i] = {c.points[i].normalImpulse.lane(lane)};
            contact.frictionImpulse = {c.tangentImpulse1.lane(lane) * tangent1 + c.tangentImpulse2.lane(lane) * tangent2,
                                       c.twistImpulse.lane(lane),
                                       Vec3(c.rollingImpulse[0].lane(lane), c.rollingImpulse[1].lane(lane),
                                            c.rollingImpulse[2].lane(lane))};
        }
    }
}

}  // namespace simcore
