#include "simcore/dynamics/contact_solver.h"

#include "simcore/dynamics/contact_rows_wide.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace simcore {

using namespace contact_rows_wide;

namespace {

// The velocity of B's material at `point` relative to A's.
Vec3 relativeVelocityAt(const Vec3& point, const BodyStorage& bodies, std::size_t a, std::size_t b) {
    return bodies.linearVelocity[b] + glm::cross(bodies.angularVelocity[b], point - bodies.centerOfMass[b]) -
           bodies.linearVelocity[a] - glm::cross(bodies.angularVelocity[a], point - bodies.centerOfMass[a]);
}

// Friction tangents for a manifold with friction centre `centre`. While the bodies slip there, the
// first tangent follows the slip: with axes at an angle to it, the clamped friction pointed off the
// slip direction and came out weak (3.6 % on a box sliding down a 30-degree incline, with the rows
// solved one after the other). Without slip any continuous basis serves.
void frictionAxes(const Vec3& n, const Vec3& centre, const BodyStorage& bodies, std::size_t a, std::size_t b, Vec3& t1,
                  Vec3& t2) {
    const Vec3 relative = relativeVelocityAt(centre, bodies, a, b);
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

// (IA^-1 + IB^-1)^-1, the rolling block's mass matrix, inverted in double (a small body's inverse
// moments cubed overflow float); zero where it is singular (neither body can turn).
Mat3 rollingMass(const Mat3& inverseInertiaA, const Mat3& inverseInertiaB) {
    const glm::dmat3 k = glm::dmat3(inverseInertiaA) + glm::dmat3(inverseInertiaB);
    const double determinant = glm::determinant(k);
    if (!(determinant > 0.0) || !std::isfinite(determinant)) return Mat3(0.0f);
    return Mat3(glm::inverse(k));
}

// Records are scattered through the pool and the solver visits them in colour order: a record
// fetched only when its lane is filled (prepare) or written (storeImpulses) stalled on memory
// (pyramid20: a fifth of prepare's time). Fetched a batch ahead instead.
void prefetchSolverPart(const ManifoldRecord& record) {
    const char* first = reinterpret_cast<const char*>(&record);
    const char* last = first + offsetof(ManifoldRecord, kept) - 1;
    for (const char* byte = first; byte < last; byte += 64) __builtin_prefetch(byte);
    __builtin_prefetch(last);  // records are not aligned to lines: the part may end in one more
}

// How a solve pass turns separation into a velocity target. Speculative points (separation > 0)
// may close the gap in one substep and no more; overlapping ones are pushed out by the chosen
// position correction, or not at all in relax passes.
struct Correction {
    enum class Mode { None, Soft, Baumgarte } mode;  // Soft: each lane's spring (ManifoldBatch)
    FloatW inverseH, maxPush, baumgarte, linearSlop;
};

}  // namespace

void ContactSolver::prepare(const ContactManager& contactManager, const BodyStorage& bodies, const JointStorage& joints,
                            const Params& params, TaskPool& pool) {
    const std::vector<Contact>& contacts = contactManager.contacts();
    params_ = params;
    pool_ = &pool;
    maxPenetration_ = 0.0f;
    velocitiesHeld_ = false;
    usesFriction_ = false;
    usesRestitution_ = false;

    const float h = params.substepDt;
    const float softHertz = SoftConstraint::cappedHertz(params.solver.contactHertz, h);
    const SoftConstraint baseSpring = SoftConstraint::make(softHertz, params.solver.contactDampingRatio, h);

    const bool rolesChanged = bodyRolesChanged(bodies);  // called every step: it records the roles
    if (rolesChanged || contactManager.manifoldListVersion() != colouredManifoldList_) colourManifolds(contactManager, bodies);
    else refreshBodyReferences(bodies);

    const bool soft = params.solver.positionCorrection == PositionCorrection::SoftStep;
    jointed_.assign(joints.empty() ? 0 : bodies.size(), 0);
    for (const Joint& joint : joints.joints) {
        jointed_[static_cast<std::size_t>(bodies.denseIndex(joint.bodyA))] = 1;
        if (joint.bodyB.isValid()) jointed_[static_cast<std::size_t>(bodies.denseIndex(joint.bodyB))] = 1;
    }
    assignLanes(contacts, bodies, glm::length(params.gravity) * h, soft);

    // Each batch is filled from its own lanes' contacts, then gets its effective masses: in
    // parallel. Every solver body exists by now, so solverBody only looks them up.
    batchPenetration_.assign(batches_.size(), 0.0f);
    forEachColorSlice([&](std::size_t beginBatch, std::size_t endBatch) {
    for (std::size_t k = beginBatch; k < endBatch; ++k) {
        // Every lane writes back to its batch's scratch row (after the solver bodies' rows) unless
        // it has a moving body, set below.
        ManifoldBatch& batch = batches_[k];
        batch = ManifoldBatch{};
        const auto scratchRow = static_cast<std::int32_t>(references_.size() + k);
        std::fill(std::begin(batch.storeA), std::end(batch.storeA), scratchRow);
        std::fill(std::begin(batch.storeB), std::end(batch.storeB), scratchRow);
    }
    for (std::size_t entry = beginBatch * kLanes; entry < endBatch * kLanes; ++entry) {
        if (const std::size_t ahead = entry + kLanes; ahead < endBatch * kLanes && laneConstraint_[ahead] != kNoConstraint)
            prefetchSolverPart(contactManager.manifoldOf(contacts[order_[laneConstraint_[ahead]]]));
        if (laneConstraint_[entry] == kNoConstraint) continue;
        const std::uint32_t ci = order_[laneConstraint_[entry]];
        const float stiffening = stiffening_[laneConstraint_[entry]];
        ManifoldBatch& batch = batches_[entry / kLanes];
        const int lane = static_cast<int>(entry % kLanes);

        const Contact& contact = contacts[ci];
        const ManifoldRecord& record = contactManager.manifoldOf(contact);
        const ContactManifold& manifold = record.manifold;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.isAwakeDynamic(a);
        const bool movesB = bodies.isAwakeDynamic(b);
        batch.bodyA[lane] = solverBody(a, bodies);
        batch.bodyB[lane] = solverBody(b, bodies);
        if (movesA) batch.storeA[lane] = batch.bodyA[lane];
        if (movesB) batch.storeB[lane] = batch.bodyB[lane];
        batch.contactIndex[lane] = ci;
        batch.pointCount[lane] = static_cast<std::uint8_t>(manifold.pointCount);
        batch.maxPointCount = std::max(batch.maxPointCount, batch.pointCount[lane]);
        batch.stiff = batch.stiff || stiffening > 1.0f;

        const float inverseMassA = movesA ? bodies.inverseMass[a] : 0.0f;
        const float inverseMassB = movesB ? bodies.inverseMass[b] : 0.0f;
        const Mat3 inverseInertiaA = movesA ? bodies.inverseInertiaWorld[a] : Mat3(0.0f);
        const Mat3 inverseInertiaB = movesB ? bodies.inverseInertiaWorld[b] : Mat3(0.0f);
        batch.inverseMassA.setLane(lane, inverseMassA);
        batch.inverseMassB.setLane(lane, inverseMassB);
        const float springHertz = softHertz * std::sqrt(stiffening);
        const SoftConstraint spring =
            stiffening > 1.0f ? SoftConstraint::make(springHertz, params.solver.contactDampingRatio, h) : baseSpring;
        batch.biasRate.setLane(lane, spring.biasRate);
        if (soft && !jointedPair(a, b)) {
            batch.giveOffset.setLane(lane, record.giveOffset);
            const float omega = 2.0f * kPi * springHertz;
            batch.givePerImpulse.setLane(lane, 1.0f / (h * omega * omega));
        }
        batch.massScale.setLane(lane, spring.massScale);
        batch.impulseScale.setLane(lane, spring.impulseScale);
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
        // Rolling resistance belongs to the friction effect: off with it.
        const float rollingLever = params.friction ? contact.rollingLever : 0.0f;
        if (rollingLever > 0.0f) {
            batch.rollingLever.setLane(lane, rollingLever);
            setLanes(batch.rollingMass, lane, rollingMass(inverseInertiaA, inverseInertiaB));
            setLanes(batch.rollingImpulse, lane, record.frictionImpulse.rolling);
            batch.anyRolling = true;
        }

        setLanes(batch.centerA, lane, centre - bodies.centerOfMass[a]);
        setLanes(batch.centerB, lane, centre - bodies.centerOfMass[b]);
        if (friction > 0.0f) {
            batch.tangentImpulse1.setLane(lane, glm::dot(record.frictionImpulse.linear, tangent1));
            batch.tangentImpulse2.setLane(lane, glm::dot(record.frictionImpulse.linear, tangent2));
            batch.twistImpulse.setLane(lane, record.frictionImpulse.twist);
        }
        for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& mp = manifold.points[i];
            PointBatch& p = batch.points[i];
            // Each body's normal row acts at its own point, on its own surface: the same point for
            // both bodies when the manifold is made, and apart by how far the pair has slid since
            // while the manifold is kept (KeptManifold: under the reuse distance, 0.5 mm at the
            // defaults). Rows at the midpoint for both bodies let an awake tower of 28 cubes buckle.
            setLanes(p.anchorA, lane, mp.pointA - bodies.centerOfMass[a]);
            setLanes(p.anchorB, lane, mp.pointB - bodies.centerOfMass[b]);
            p.baseSeparation.setLane(lane, mp.separation);
            const Vec3 mid = 0.5f * (mp.pointA + mp.pointB);
            p.leverArm.setLane(lane, glm::length(mid - centre));
            p.normalImpulse.setLane(lane, record.impulses[i].normal);
            batchPenetration_[entry / kLanes] = std::max(batchPenetration_[entry / kLanes], -mp.separation);
            const float approach = -glm::dot(relativeVelocityAt(mid, bodies, a, b), normal);
            if (friction > 0.0f && approach > params.contact.restitutionThreshold) {
                batch.impacting.setLane(lane, 1.0f);
                batch.anyImpact = true;
            }
        }
    }
    for (std::size_t k = beginBatch; k < endBatch; ++k) computeEffectiveMasses(batches_[k]);
    });
    for (std::size_t k = 0; k < batches_.size(); ++k) {
        usesFriction_ = usesFriction_ || batches_[k].anyFriction || batches_[k].anyRolling;
        usesRestitution_ = usesRestitution_ || batches_[k].anyRestitution;
        maxPenetration_ = std::max(maxPenetration_, batchPenetration_[k]);
    }

    velocities_.assign(references_.size() + batches_.size(), BodyRow{});
    changedInPass_.assign(references_.size(), 0);
    supportDepth_.clear();
    if (std::find(unevenBody_.begin(), unevenBody_.end(), 1) != unevenBody_.end()) findSupportDepths();
    pass_ = 1;  // no body counts as changed before the first pass
    motion_.assign(references_.size(), BodyRow{});
    motion_[0].value[7] = 1.0f;  // the immovable body's rotation: identity
    loadMotion(bodies);
    motionCount_ = 1;  // the batches' separations (separationMotion 0) are computed in their first pass
}

// Breadth first from every body that does not move, over the manifolds' lanes.
void ContactSolver::findSupportDepths() {
    const std::size_t n = references_.size();
    supportDepth_.assign(n, kUnsupported);
    neighbourStart_.assign(n + 1, 0);
    const auto forEachLane = [this](auto&& visit) {
        for (const ManifoldBatch& c : batches_)
            for (int lane = 0; lane < kLanes; ++lane)
                if (c.pointCount[lane] > 0)
                    visit(static_cast<std::size_t>(c.bodyA[lane]), c.storeA[lane] == c.bodyA[lane],
                          static_cast<std::size_t>(c.bodyB[lane]), c.storeB[lane] == c.bodyB[lane]);
    };
    // A body's list holds the moving bodies it touches: the ones its depth reaches.
    forEachLane([&](std::size_t a, bool movesA, std::size_t b, bool movesB) {
        if (movesB) ++neighbourStart_[a + 1];
        if (movesA) ++neighbourStart_[b + 1];
        if (!movesA) supportDepth_[a] = 0;
        if (!movesB) supportDepth_[b] = 0;
    });
    for (std::size_t s = 0; s < n; ++s) neighbourStart_[s + 1] += neighbourStart_[s];
    neighbours_.resize(neighbourStart_[n]);
    // Each list filled from its start, which moves the start to the next list's; then moved back.
    forEachLane([&](std::size_t a, bool movesA, std::size_t b, bool movesB) {
        if (movesB) neighbours_[neighbourStart_[a]++] = static_cast<std::uint32_t>(b);
        if (movesA) neighbours_[neighbourStart_[b]++] = static_cast<std::uint32_t>(a);
    });
    for (std::size_t s = n; s > 0; --s) neighbourStart_[s] = neighbourStart_[s - 1];
    neighbourStart_[0] = 0;
    std::vector<std::uint32_t>& queue = depthQueue_;
    queue.clear();
    for (std::size_t s = 0; s < n; ++s)
        if (supportDepth_[s] == 0) queue.push_back(static_cast<std::uint32_t>(s));
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const std::uint32_t body = queue[next];
        for (std::uint32_t k = neighbourStart_[body]; k < neighbourStart_[body + 1]; ++k) {
            const std::uint32_t neighbour = neighbours_[k];
            if (supportDepth_[neighbour] != kUnsupported) continue;
            supportDepth_[neighbour] = supportDepth_[body] + 1;
            queue.push_back(neighbour);
        }
    }
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
        const Vec3W angularA = cross(load(p.anchorA), normal), angularB = cross(load(p.anchorB), normal);
        store(p.angularA, angularA);
        store(p.angularB, angularB);
        p.normalMass =
            select(exists, effectiveMass(inverseMassSum, inverseInertiaA, inverseInertiaB, angularA, angularB), zero);
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
    const Vec3W ian = inverseInertiaA * normal, ibn = inverseInertiaB * normal;
    const FloatW k13 = dot(a1, ian) + dot(b1, ibn), k23 = dot(a2, ian) + dot(b2, ibn);
    const FloatW k33 = dot(normal, ian) + dot(normal, ibn);
    // From cofactors; where the 3x3 block is degenerate (nothing turns about the normal), the
    // twist row alone.
    const FloatW c11 = k22 * k33 - k23 * k23, c33 = k11 * k22 - k12 * k12;
    const FloatW c13 = k12 * k23 - k13 * k22, c23 = k12 * k13 - k11 * k23;
    const FloatW determinant = k11 * c11 + k12 * (k13 * k23 - k12 * k33) + k13 * c13;
    const MaskW tangents = hasFriction & (c33 > zero);
    const MaskW block = tangents & (determinant > FloatW::splat(1e-5f) * c33 * k33);
    const FloatW inverseC33 = one / simd::max(c33, tiny), inverseDeterminant = one / simd::max(determinant, tiny);
    c.tangentMass[0] = select(tangents, k22 * inverseC33, zero);
    c.tangentMass[1] = select(tangents, k11 * inverseC33, zero);
    c.tangentMass[2] = select(tangents, -(k12 * inverseC33), zero);
    c.twistMass[0] = select(block, c13 * inverseDeterminant, zero);
    c.twistMass[1] = select(block, c23 * inverseDeterminant, zero);
    c.twistMass[2] = select(block, c33 * inverseDeterminant,
                            select(hasFriction & (k33 > zero), one / simd::max(k33, tiny), zero));
}

void ContactSolver::loadVelocities(const BodyStorage& bodies) {
    forEachSolverBody([&](std::size_t s) {
        const std::uint32_t i = references_[s].denseIndex;
        const Vec3& v = bodies.linearVelocity[i];
        const Vec3& w = bodies.angularVelocity[i];
        velocities_[s] = {{v.x, v.y, v.z, 0.0f, w.x, w.y, w.z, 0.0f}};
    });
}

void ContactSolver::followPositions(const BodyStorage& bodies) {
    ++motionCount_;
    loadMotion(bodies);
}

void ContactSolver::loadMotion(const BodyStorage& bodies) {
    forEachSolverBody([&](std::size_t s) {
        const BodyReference& ref = references_[s];
        const Vec3 d = bodies.centerOfMass[ref.denseIndex] - ref.centerOfMass;
        const Quat q = bodies.orientation[ref.denseIndex] * glm::conjugate(ref.orientation);
        motion_[s] = {{d.x, d.y, d.z, 0.0f, q.x, q.y, q.z, q.w}};
    });
}

void ContactSolver::startFromVelocities(const BodyStorage& bodies) {
    if (!std::exchange(velocitiesHeld_, false)) loadVelocities(bodies);
}

void ContactSolver::storeVelocities(BodyStorage& bodies) const {
    forEachSolverBody([&](std::size_t s) {
        const BodyReference& ref = references_[s];
        if (!ref.moves) return;
        const float* row = velocities_[s].value;
        bodies.linearVelocity[ref.denseIndex] = Vec3(row[0], row[1], row[2]);
        bodies.angularVelocity[ref.denseIndex] = Vec3(row[4], row[5], row[6]);
    });
}

void ContactSolver::warmStart(BodyStorage& bodies, AfterWarmStart after) {
    startFromVelocities(bodies);
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
    if (after == AfterWarmStart::HoldForSolve) velocitiesHeld_ = true;
    else storeVelocities(bodies);
}

bool ContactSolver::solve(BodyStorage& bodies, bool useBias, int passes) {
    startFromVelocities(bodies);
    bool unsettled = false;
    for (int pass = 0; pass < passes; ++pass) {
        // A relax pass says whether push is left; a biased one whether a stiffened manifold's rows
        // still moved, and then those manifolds' batches are solved again.
        unsettled = solvePass(useBias, PassScope::All);
        bool stiffUnsettled = useBias && unsettled;
        for (int i = 0; stiffUnsettled && i < kStiffPasses; ++i) stiffUnsettled = solvePass(true, PassScope::Stiff);
    }
    storeVelocities(bodies);
    return !useBias && unsettled;
}

bool ContactSolver::relaxWherePushing(BodyStorage& bodies, int passes) {
    startFromVelocities(bodies);
    bool pushLeft = true;
    for (int i = 0; pushLeft && i < passes; ++i) pushLeft = solvePass(false, PassScope::Pushing);
    storeVelocities(bodies);
    return pushLeft;
}

void ContactSolver::settleOnSupports(BodyStorage& bodies) {
    if (supportDepth_.empty()) return;
    startFromVelocities(bodies);
    const float inverseH = 1.0f / params_.substepDt;
    const auto jointed = [this](std::size_t s) { return jointedBody(references_[s].denseIndex); };
    for (ManifoldBatch& c : batches_) {
        for (int lane = 0; lane < kLanes; ++lane) {
            if (c.pointCount[lane] == 0 || c.restitution.lane(lane) > 0.0f) continue;
            const auto a = static_cast<std::size_t>(c.bodyA[lane]), b = static_cast<std::size_t>(c.bodyB[lane]);
            if (!unevenBody_[a] && !unevenBody_[b]) continue;
            const bool movesA = c.storeA[lane] == c.bodyA[lane], movesB = c.storeB[lane] == c.bodyB[lane];
            if ((movesA && jointed(a)) || (movesB && jointed(b))) continue;
            // The body lower than the other (fewer contacts from the ground) holds still; bodies
            // side by side, at one depth, have had the ordinary passes' answer. The upper one moves:
            // only bodies that do not move are at depth 0.
            if (supportDepth_[a] == supportDepth_[b]) continue;
            const bool freeA = supportDepth_[a] > supportDepth_[b], freeB = !freeA;
            const float inverseMassA = freeA ? c.inverseMassA.lane(lane) : 0.0f;
            const float inverseMassB = freeB ? c.inverseMassB.lane(lane) : 0.0f;
            const Mat3 inverseInertiaA = freeA ? laneOf(c.inverseInertiaA, lane) : Mat3(0.0f);
            const Mat3 inverseInertiaB = freeB ? laneOf(c.inverseInertiaB, lane) : Mat3(0.0f);
            const Vec3 normal = laneOf(c.normal, lane);
            float* rowA = velocities_[a].value;
            float* rowB = velocities_[b].value;
            Vec3 vA(rowA[0], rowA[1], rowA[2]), wA(rowA[4], rowA[5], rowA[6]);
            Vec3 vB(rowB[0], rowB[1], rowB[2]), wB(rowB[4], rowB[5], rowB[6]);
            float impulse[kMaxManifoldPoints];
            for (int i = 0; i < c.pointCount[lane]; ++i) impulse[i] = c.points[i].normalImpulse.lane(lane);
            for (int sweep = 0; sweep < kMaxNormalSweeps; ++sweep) {
                float largestChange = 0.0f;
                for (int i = 0; i < c.pointCount[lane]; ++i) {
                    const PointBatch& p = c.points[i];
                    const Vec3 anchorA = laneOf(p.anchorA, lane), anchorB = laneOf(p.anchorB, lane);
                    const Vec3 leverA = glm::cross(anchorA, normal), leverB = glm::cross(anchorB, normal);
                    const float mass = inverseMassA + inverseMassB + glm::dot(leverA, inverseInertiaA * leverA) +
                                       glm::dot(leverB, inverseInertiaB * leverB);
                    const float vn = glm::dot(vB + glm::cross(wB, anchorB) - vA - glm::cross(wA, anchorA), normal);
                    // A speculative point lets the bodies close the gap, as in the relax passes.
                    const float separation = p.separation.lane(lane);
                    const float target = separation > 0.0f ? -separation * inverseH : 0.0f;
                    const float accumulated = std::max(impulse[i] - (vn - target) / mass, 0.0f);
                    const float delta = accumulated - impulse[i];
                    impulse[i] = accumulated;
                    vA -= (inverseMassA * delta) * normal;
                    wA -= inverseInertiaA * (leverA * delta);
                    vB += (inverseMassB * delta) * normal;
                    wB += inverseInertiaB * (leverB * delta);
                    largestChange = std::max(largestChange, std::abs(delta) * mass);
                }
                if (largestChange <= kSweepTolerance) break;
            }
            if (freeA) velocities_[a] = {{vA.x, vA.y, vA.z, 0.0f, wA.x, wA.y, wA.z, 0.0f}};
            if (freeB) velocities_[b] = {{vB.x, vB.y, vB.z, 0.0f, wB.x, wB.y, wB.z, 0.0f}};
        }
    }
    storeVelocities(bodies);
}

bool ContactSolver::touchesChange(const ManifoldBatch& c) const {
    for (int lane = 0; lane < kLanes; ++lane) {
        if (changedInPass_[static_cast<std::size_t>(c.bodyA[lane])] + 1 >= pass_) return true;
        if (changedInPass_[static_cast<std::size_t>(c.bodyB[lane])] + 1 >= pass_) return true;
    }
    return false;
}

bool ContactSolver::solvePass(bool useBias, PassScope scope) {
    ++pass_;
    extraRelaxPasses_ = scope == PassScope::Pushing ? extraRelaxPasses_ + 1 : 0;
    const bool unevenOnly = extraRelaxPasses_ > kEvenExtraRelaxPasses;
    Correction correction;
    if (!useBias)
        correction.mode = Correction::Mode::None;
    else if (params_.solver.positionCorrection == PositionCorrection::SoftStep)
        correction.mode = Correction::Mode::Soft;
    else
        correction.mode = Correction::Mode::Baumgarte;
    const float inverseH = 1.0f / params_.substepDt;
    correction.inverseH = FloatW::splat(inverseH);
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
    const bool impactFrictionPass = useBias && !frictionInPass;  // for the manifolds that impact

    const FloatW settleTolerance = FloatW::splat(useBias ? kStiffTolerance : kRelaxTolerance), sweepTolerance = FloatW::splat(kSweepTolerance);
    const FloatW deepOverlap = FloatW::splat(-params_.contact.linearSlop);
    float* rows = velocities_.data()->value;
    const float* motion = motion_.data()->value;
    // Whether any batch still pushes; each batch's largest excess starts afresh (the maximum over
    // all of them is above zero exactly when one batch's is).
    const auto solveBatch = [&](ManifoldBatch& c) {
        FloatW largestExcess = FloatW::splat(-1.0f);
        WideBodies v = gatherVelocities(rows, c.bodyA, c.bodyB);
        const WideBodies before = v;
        const Vec3W normal = load(c.normal);
        const SymMat3W inverseInertiaA = load(c.inverseInertiaA), inverseInertiaB = load(c.inverseInertiaB);

        // Each point's velocity target for this pass: positions do not move within it.
        struct NormalRow {
            FloatW bias, massScale, impulseScale, impulseAtStart;
            MaskW deep;
        };
        NormalRow normalRows[kMaxManifoldPoints];
        if (c.separationMotion != motionCount_) {
            const PairMotionW pairMotion = gatherMotion(motion, c.bodyA, c.bodyB);
            for (int i = 0; i < c.maxPointCount; ++i) {
                PointBatch& p = c.points[i];
                p.separation = separationNow(pairMotion, normal, load(p.anchorA), load(p.anchorB), p.baseSeparation,
                                             c.radiusA, c.radiusB);
            }
            c.separationMotion = motionCount_;
        }
        for (int i = 0; i < c.maxPointCount; ++i) {
            const PointBatch& p = c.points[i];
            const FloatW separation = p.separation - c.giveOffset;

            const MaskW speculative = separation > zero;
            const FloatW arrive = separation * correction.inverseH;
            FloatW bias = select(speculative, arrive, zero), massScale = one, impulseScale = zero;
            if (correction.mode == Correction::Mode::Soft) {
                bias = select(speculative, arrive, simd::max(c.biasRate * separation, correction.maxPush));
                massScale = select(speculative, one, c.massScale);
                impulseScale = select(speculative, zero, c.impulseScale);
            } else if (correction.mode == Correction::Mode::Baumgarte) {
                const FloatW overlap = simd::min(separation + correction.linearSlop, zero);
                bias = select(speculative, arrive, simd::max(correction.baumgarte * overlap, correction.maxPush));
            }
            normalRows[i] = {bias, massScale, impulseScale, p.normalImpulse, separation < deepOverlap};
        }

        // One point alone is solved exactly in one sweep; more are swept while they still move each other.
        const int sweeps = c.maxPointCount > 1 ? kMaxNormalSweeps : 1;
        for (int sweep = 0; sweep < sweeps; ++sweep) {
            FloatW sweepExcess = FloatW::splat(-1.0f);
            for (int i = 0; i < c.maxPointCount; ++i) {
                PointBatch& p = c.points[i];
                const NormalRow& r = normalRows[i];
                const Vec3W angularA = load(p.angularA), angularB = load(p.angularB);
                const FloatW vn = alongAxis(v, normal, angularA, angularB);
                const FloatW lambda = -(p.normalMass * r.massScale * (vn + r.bias)) - r.impulseScale * p.normalImpulse;
                const FloatW accumulated = simd::max(p.normalImpulse + lambda, zero);
                const FloatW delta = accumulated - p.normalImpulse;
                p.normalImpulse = accumulated;
                applyImpulse(v, normal * delta, angularA * delta, angularB * delta, c.inverseMassA, c.inverseMassB,
                             inverseInertiaA, inverseInertiaB);
                // The velocity this row changed beyond the tolerance (delta / normalMass, kept as a product).
                sweepExcess = simd::max(sweepExcess, simd::max(delta, -delta) - sweepTolerance * p.normalMass);
            }
            if (!simd::any(sweepExcess > zero)) break;
        }
        // The velocity each row changed over the pass, beyond the pass's tolerance: in a velocity
        // pass every row of a stiffened manifold's batch; in a relax pass only where the bodies
        // overlap beyond the slop, where the velocity passes pushed.
        for (int i = 0; i < c.maxPointCount && (!useBias || c.stiff); ++i) {
            const FloatW change = c.points[i].normalImpulse - normalRows[i].impulseAtStart;
            const FloatW excess = simd::max(change, -change) - settleTolerance * c.points[i].normalMass;
            largestExcess = simd::max(largestExcess, useBias ? excess : select(normalRows[i].deep, excess, FloatW::splat(-1.0f)));
        }

        const bool impactFriction = impactFrictionPass && c.anyImpact;
        if ((c.anyFriction || c.anyRolling) && (frictionInPass || impactFriction)) {
            FloatW normalSum = zero, twistReach = zero;
            for (int i = 0; i < c.maxPointCount; ++i) {
                normalSum = normalSum + c.points[i].normalImpulse;
                twistReach = mulAdd(c.points[i].normalImpulse, c.points[i].leverArm, twistReach);
            }
            // Rolling resistance before the friction rows (Box3D solves it just before the tangent
            // block), so the friction that follows holds the contact point still at the turn
            // rolling resistance left: the whole body slows, not only its spin.
            if (c.anyRolling && frictionInPass)
                solveRolling(v, load(c.rollingMass), inverseInertiaA, inverseInertiaB, c.rollingImpulse,
                             c.rollingLever * normalSum);
            if (c.anyFriction) {
                const WideBodies beforeFriction = v;
                const FloatW impulse1 = c.tangentImpulse1, impulse2 = c.tangentImpulse2, twist = c.twistImpulse;
                solveFriction(v, frictionRows(c), c.tangentImpulse1, c.tangentImpulse2, c.twistImpulse,
                              c.friction * normalSum, c.friction * twistReach);
                if (impactFriction) {  // only the impacting lanes: the others wait for the relax passes
                    const MaskW impacting = c.impacting > zero;
                    v = selectLanes(impacting, v, beforeFriction);
                    c.tangentImpulse1 = select(impacting, c.tangentImpulse1, impulse1);
                    c.tangentImpulse2 = select(impacting, c.tangentImpulse2, impulse2);
                    c.twistImpulse = select(impacting, c.twistImpulse, twist);
                }
            }
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
        // The lanes still changing mark their moving bodies: in a velocity pass, stiffened
        // manifolds' lanes; in a relax pass, those still pushing.
        if (useBias && !c.stiff) return false;
        bool changing = false;
        for (int lane = 0; lane < kLanes; ++lane) {
            if (largestExcess.lane(lane) <= 0.0f) continue;
            if (!useBias && unevenOnly && !unevenBody_[static_cast<std::size_t>(c.bodyA[lane])] &&
                !unevenBody_[static_cast<std::size_t>(c.bodyB[lane])])
                continue;
            changing = true;
            if (c.storeA[lane] == c.bodyA[lane]) changedInPass_[static_cast<std::size_t>(c.bodyA[lane])] = pass_;
            if (c.storeB[lane] == c.bodyB[lane]) changedInPass_[static_cast<std::size_t>(c.bodyB[lane])] = pass_;
        }
        return changing;
    };
    if (scope == PassScope::All) return forEachBatch(solveBatch);
    if (scope == PassScope::Stiff)
        return forEachBatch([&](ManifoldBatch& c) { return touchesChange(c) && solveBatch(c); }, true);
    // Few batches still push: one after another (colour by colour, as batches_ is ordered).
    bool pushLeft = false;
    for (ManifoldBatch& c : batches_)
        if (touchesChange(c) && solveBatch(c)) pushLeft = true;
    return pushLeft;
}

// Each lane writes its own manifold's record: batches may run side by side in any order.
void ContactSolver::storeImpulses(ContactManager& contactManager) const {
    forEachColorSlice([&](std::size_t beginBatch, std::size_t endBatch) {
    for (std::size_t k = beginBatch; k < endBatch; ++k) {
        const ManifoldBatch& c = batches_[k];
        if (k + 1 < endBatch)
            for (int lane = 0; lane < kLanes; ++lane)
                if (batches_[k + 1].pointCount[lane] > 0)
                    prefetchSolverPart(contactManager.manifoldOf(contactManager.contacts()[batches_[k + 1].contactIndex[lane]]));
        for (int lane = 0; lane < kLanes; ++lane) {
            if (c.pointCount[lane] == 0) continue;
            Contact& contact = contactManager.contacts()[c.contactIndex[lane]];
            ManifoldRecord& record = contactManager.manifoldOf(contact);
            const Vec3 tangent1 = laneOf(c.tangent1, lane), tangent2 = laneOf(c.tangent2, lane);
            contact.normalImpulse = 0.0f;
            float meanSeparation = 0.0f, give = 0.0f;
            const int pointCount = c.pointCount[lane];
            const auto points = static_cast<float>(pointCount);
            for (int i = 0; i < pointCount; ++i) {
                const PointBatch& p = c.points[i];
                const float impulse = p.normalImpulse.lane(lane);
                record.impulses[i] = {impulse};
                contact.normalImpulse += impulse;
                meanSeparation += p.separation.lane(lane) / points;
                if (const float mass = p.normalMass.lane(lane); mass > 0.0f) give += impulse * c.givePerImpulse.lane(lane) / (mass * points);
            }
            const float towardsRest = kGiveOffsetRate * params_.timeStep * (meanSeparation + kRestingGive * give);
            record.giveOffset = std::clamp(c.giveOffset.lane(lane) - towardsRest, 0.0f, kMaxGiveOffset * give);
            record.frictionImpulse = {c.tangentImpulse1.lane(lane) * tangent1 + c.tangentImpulse2.lane(lane) * tangent2,
                                       c.twistImpulse.lane(lane),
                                       laneOf(c.rollingImpulse, lane)};
        }
    }
    });
}

}  // namespace simcore
