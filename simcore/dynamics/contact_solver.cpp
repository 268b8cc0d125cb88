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

SIMCORE_SIMD_INLINE void scatterVelocities(float* rows, const std::int32_t* bodyA, const std::int32_t* bodyB, const WideBodies& v) {
    const FloatW zero = FloatW::zero();
    const FloatW a[8] = {v.linearA.x, v.linearA.y, v.linearA.z, zero, v.angularA.x, v.angularA.y, v.angularA.z, zero};
    const FloatW b[8] = {v.linearB.x, v.linearB.y, v.linearB.z, zero, v.angularB.x, v.angularB.y, v.angularB.z, zero};
    // A immovable or non-moving body may sit in several lanes; its velocity is unchanged in each,
    // so the repeated stores agree.
    simd::scatterRows(rows, bodyA, a);
    simd::scatterRows(rows, bodyB, b);
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

// Coulomb: scales the tangential impulse (t1, t2) into the disc of radius `limit`.
SIMCORE_SIMD_INLINE void clampToDisc(FloatW& t1, FloatW& t2, FloatW limit) {
    const FloatW length2 = t1 * t1 + t2 * t2;
    const FloatW scale = select(length2 > limit * limit, limit / simd::sqrt(simd::max(length2, FloatW::splat(1e-30f))),
                                FloatW::splat(1.0f));
    t1 = t1 * scale;
    t2 = t2 * scale;
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

void ContactSolver::prepare(const std::vector<Contact>& contacts, const BodyStorage& bodies, const Params& params) {
    params_ = params;
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
    constexpr int kColorCount = 64;
    constexpr int kOverflow = kColorCount;
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
    std::array<std::uint32_t, kColorCount + 1> firstBatch{}, filled{};
    std::uint32_t batchCount = 0;
    colorCount_ = 0;
    for (int color = 0; color <= kColorCount; ++color) {
        firstBatch[color] = batchCount;
        const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
        batchCount += (perColor[color] + lanes - 1) / lanes;
        if (perColor[color] > 0) ++colorCount_;
    }
    batches_.assign(batchCount, ManifoldBatch{});

    for (std::size_t k = 0; k < order_.size(); ++k) {
        const std::uint32_t ci = order_[k];
        const int color = colorOf_[k];
        const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
        const std::uint32_t slot = filled[color]++;
        ManifoldBatch& batch = batches_[firstBatch[color] + slot / lanes];
        const int lane = static_cast<int>(slot % lanes);

        const Contact& contact = contacts[ci];
        const ContactManifold& manifold = contact.manifold;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.motion[a] == MotionType::Dynamic && bodies.awake[a];
        const bool movesB = bodies.motion[b] == MotionType::Dynamic && bodies.awake[b];
        batch.bodyA[lane] = solverBody(a, bodies);
        batch.bodyB[lane] = solverBody(b, bodies);
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

        const Vec3& normal = manifold.normal;
        Vec3 tangent1, tangent2;
        frictionAxes(manifold, bodies, a, b, tangent1, tangent2);
        setLanes(batch.normal, lane, normal);
        setLanes(batch.tangent1, lane, tangent1);
        setLanes(batch.tangent2, lane, tangent2);
        // With friction off (or zero for this pair) the friction rows have zero mass: no effect.
        const float friction = params.friction ? contact.friction : 0.0f;
        const float restitution = params.restitution ? contact.restitution : 0.0f;
        batch.radiusA.setLane(lane, roundingRadius(bodies.shape[a]));
        batch.radiusB.setLane(lane, roundingRadius(bodies.shape[b]));
        batch.friction.setLane(lane, friction);
        batch.restitution.setLane(lane, restitution);
        batch.anyFriction = batch.anyFriction || friction > 0.0f;
        batch.anyRestitution = batch.anyRestitution || restitution > 0.0f;
        usesFriction_ = usesFriction_ || friction > 0.0f;
        usesRestitution_ = usesRestitution_ || restitution > 0.0f;

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
            const ContactImpulse& warm = contact.impulses[i];
            p.normalImpulse.setLane(lane, warm.normal);
            if (friction > 0.0f) {
                p.tangentImpulse1.setLane(lane, glm::dot(warm.friction, tangent1));
                p.tangentImpulse2.setLane(lane, glm::dot(warm.friction, tangent2));
            }
            maxPenetration_ = std::max(maxPenetration_, -mp.separation);
        }
    }

    // Effective masses, a batch at a time; zero for the rows of absent points and of frictionless
    // lanes, so those rows do nothing.
    const FloatW zero = FloatW::zero();
    for (ManifoldBatch& c : batches_) {
        const FloatW inverseMassSum = c.inverseMassA + c.inverseMassB;
        const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);
        const Vec3W normal = load(c.normal), tangent1 = load(c.tangent1), tangent2 = load(c.tangent2);
        const MaskW hasFriction = c.friction > zero;
        FloatW pointCount = zero;
        for (int lane = 0; lane < kLanes; ++lane) pointCount.setLane(lane, c.pointCount[lane]);
        for (int i = 0; i < c.maxPointCount; ++i) {
            PointBatch& p = c.points[i];
            const MaskW exists = pointCount > FloatW::splat(static_cast<float>(i));
            const Vec3W anchorA = load(p.anchorA), anchorB = load(p.anchorB);
            auto rowMass = [&](const Vec3W& axis) {
                return effectiveMass(inverseMassSum, inverseInertiaA, inverseInertiaB, anchorA, anchorB, axis);
            };
            p.normalMass = select(exists, rowMass(normal), zero);
            if (!c.anyFriction) continue;
            p.tangentMass1 = select(exists & hasFriction, rowMass(tangent1), zero);
            p.tangentMass2 = select(exists & hasFriction, rowMass(tangent2), zero);
        }
    }

    velocities_.assign(references_.size(), BodyRow{});
    motion_.assign(references_.size(), BodyRow{});
    motion_[0].value[7] = 1.0f;  // the immovable body's rotation: identity
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

void ContactSolver::warmStart(BodyStorage& bodies) {
    loadVelocities(bodies);
    float* rows = velocities_.data()->value;
    for (const ManifoldBatch& c : batches_) {
        WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
        const Vec3W normal = load(c.normal), tangent1 = load(c.tangent1), tangent2 = load(c.tangent2);
        const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);
        for (int i = 0; i < c.maxPointCount; ++i) {
            const PointBatch& p = c.points[i];
            const Vec3W impulse =
                mulAdd(normal, p.normalImpulse, mulAdd(tangent1, p.tangentImpulse1, tangent2 * p.tangentImpulse2));
            applyImpulse(v, impulse, cross(load(p.anchorA), impulse), cross(load(p.anchorB), impulse), c.inverseMassA,
                         c.inverseMassB, inverseInertiaA, inverseInertiaB);
        }
        scatterVelocities(rows, c.bodyA, c.bodyB, v);
    }
    storeVelocities(bodies);
}

void ContactSolver::solve(BodyStorage& bodies, bool useBias) {
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

    float* rows = velocities_.data()->value;
    const float* motion = motion_.data()->value;
    for (ManifoldBatch& c : batches_) {
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
        }

        if (c.anyFriction) {
            const Vec3W tangent1 = load(c.tangent1), tangent2 = load(c.tangent2);
            for (int i = 0; i < c.maxPointCount; ++i) {
                PointBatch& p = c.points[i];
                const Vec3W anchorA = load(p.anchorA), anchorB = load(p.anchorB);
                const Vec3W angularA1 = cross(anchorA, tangent1), angularB1 = cross(anchorB, tangent1);
                const Vec3W angularA2 = cross(anchorA, tangent2), angularB2 = cross(anchorB, tangent2);
                FloatW t1 = p.tangentImpulse1 - p.tangentMass1 * alongAxis(v, tangent1, angularA1, angularB1);
                FloatW t2 = p.tangentImpulse2 - p.tangentMass2 * alongAxis(v, tangent2, angularA2, angularB2);
                clampToDisc(t1, t2, c.friction * p.normalImpulse);
                const FloatW delta1 = t1 - p.tangentImpulse1, delta2 = t2 - p.tangentImpulse2;
                p.tangentImpulse1 = t1;
                p.tangentImpulse2 = t2;
                applyImpulse(v, mulAdd(tangent1, delta1, tangent2 * delta2), mulAdd(angularA1, delta1, angularA2 * delta2),
                             mulAdd(angularB1, delta1, angularB2 * delta2), c.inverseMassA, c.inverseMassB,
                             inverseInertiaA, inverseInertiaB);
            }
        }
        const MaskW kept = keepFiniteLanes(v, before);
        if (!simd::all(kept)) {  // and their impulses, which would overflow the next warm start
            for (int i = 0; i < c.maxPointCount; ++i) {
                PointBatch& p = c.points[i];
                p.normalImpulse = select(kept, p.normalImpulse, zero);
                p.tangentImpulse1 = select(kept, p.tangentImpulse1, zero);
                p.tangentImpulse2 = select(kept, p.tangentImpulse2, zero);
            }
        }
        scatterVelocities(rows, c.bodyA, c.bodyB, v);
    }
    storeVelocities(bodies);
}

void ContactSolver::resolveCollisions(BodyStorage& bodies) {
    loadVelocities(bodies);
    loadMotion(bodies);
    const FloatW zero = FloatW::zero();
    const FloatW threshold = FloatW::splat(-params_.contact.restitutionThreshold);
    const FloatW h = FloatW::splat(params_.substepDt);
    float* rows = velocities_.data()->value;
    const float* motion = motion_.data()->value;
    for (int pass = 0; pass < kMaxCollisionPasses; ++pass) {
        bool collided = false;
        for (ManifoldBatch& c : batches_) {
            if (!c.anyRestitution) continue;
            WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
            const WideBodies before = v;
            const PairMotionW pairMotion = gatherMotion(motion, c.bodyA, c.bodyB);
            const Vec3W normal = load(c.normal), tangent1 = load(c.tangent1), tangent2 = load(c.tangent2);
            const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);
            const FloatW bounce = FloatW::splat(1.0f) + c.restitution;
            for (int i = 0; i < c.maxPointCount; ++i) {
                const PointBatch& p = c.points[i];
                const Vec3W anchorA = load(p.anchorA), anchorB = load(p.anchorB);
                const Vec3W angularA = cross(anchorA, normal), angularB = cross(anchorB, normal);
                const FloatW vn = alongAxis(v, normal, angularA, angularB);
                const FloatW separation =
                    separationNow(pairMotion, normal, anchorA, anchorB, p.baseSeparation, c.radiusA, c.radiusB);
                // A collision: closing faster than the threshold, and touching within this substep.
                const MaskW collides = (vn < threshold) & (mulAdd(vn, h, separation) < zero) &
                                       (c.restitution > zero) & (p.normalMass > zero);
                if (!simd::any(collides)) continue;
                collided = true;
                const FloatW normalImpulse = select(collides, -(bounce * p.normalMass * vn), zero);
                applyImpulse(v, normal * normalImpulse, angularA * normalImpulse, angularB * normalImpulse,
                             c.inverseMassA, c.inverseMassB, inverseInertiaA, inverseInertiaB);
                if (!c.anyFriction) continue;
                // Friction during the impact, bounded by the impact's own normal impulse.
                const Vec3W angularA1 = cross(anchorA, tangent1), angularB1 = cross(anchorB, tangent1);
                const Vec3W angularA2 = cross(anchorA, tangent2), angularB2 = cross(anchorB, tangent2);
                FloatW t1 = -(p.tangentMass1 * alongAxis(v, tangent1, angularA1, angularB1));
                FloatW t2 = -(p.tangentMass2 * alongAxis(v, tangent2, angularA2, angularB2));
                clampToDisc(t1, t2, c.friction * normalImpulse);
                applyImpulse(v, mulAdd(tangent1, t1, tangent2 * t2), mulAdd(angularA1, t1, angularA2 * t2),
                             mulAdd(angularB1, t1, angularB2 * t2), c.inverseMassA, c.inverseMassB, inverseInertiaA,
                             inverseInertiaB);
            }
            keepFiniteLanes(v, before);
            scatterVelocities(rows, c.bodyA, c.bodyB, v);
        }
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
            for (int i = 0; i < c.pointCount[lane]; ++i) {
                const PointBatch& p = c.points[i];
                contact.impulses[i] = {p.normalImpulse.lane(lane),
                                       p.tangentImpulse1.lane(lane) * tangent1 + p.tangentImpulse2.lane(lane) * tangent2};
            }
        }
    }
}

}  // namespace simcore
