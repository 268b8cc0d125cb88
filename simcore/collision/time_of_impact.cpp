#include "simcore/collision/time_of_impact.h"

#include "simcore/collision/collide_mesh.h"
#include "simcore/collision/gjk.h"
#include "simcore/shapes/compound_shape.h"

#include <algorithm>
#include <cmath>

namespace simcore {

Transform Sweep::at(float fraction) const {
    const Vec3 center = center0 + fraction * (center1 - center0);
    // Slerp (shorter arc) turns at a constant rate, which the advancement's speed bound assumes.
    const Quat rotation = glm::normalize(glm::slerp(rotation0, rotation1, fraction));
    return {center - rotation * localCenter, rotation};
}

float Sweep::rotationAngle() const {
    const Quat delta = rotation1 * glm::conjugate(rotation0);
    const float sine = std::min(std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z), 1.0f);
    return 2.0f * std::asin(sine);  // the shorter of the two equivalent rotations
}

namespace {

// Farthest any point of the shape lies from its centre of mass (m).
float reachFromCenter(const Shape& shape, const Vec3& localCenter) {
    const Aabb bounds = localBounds(shape);
    const Vec3 far = glm::max(glm::abs(bounds.min - localCenter), glm::abs(bounds.max - localCenter));
    return glm::length(far);
}

// The sweep of sub-shape `index` of a body on `sweep`: the same motion seen from the sub-shape's
// frame. With the child at pose (p, q) the body transform (c - R l, R) places it at
// (c - R (l - p), R q), so its centre offset is q^-1 (l - p), and slerp commutes with the fixed q.
Sweep subShapeSweep(const Shape& shape, std::size_t index, const Sweep& sweep) {
    if (shape.type != ShapeType::Compound) return sweep;
    const Transform& pose = shape.compound->children()[index].pose;
    return {pose.rotateInverse(sweep.localCenter - pose.position), sweep.center0, sweep.center1,
            sweep.rotation0 * pose.rotation, sweep.rotation1 * pose.rotation};
}

TimeOfImpact convexTimeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
                                float tolerance);

// The outcome over several sub-shape pairs: the earliest hit of any; otherwise touching if any
// pair touches.
class EarliestImpact {
public:
    void add(const TimeOfImpact& toi) {
        if (toi.outcome == TimeOfImpact::Outcome::Hit &&
            (first_.outcome != TimeOfImpact::Outcome::Hit || toi.fraction < first_.fraction))
            first_ = toi;
        touching_ = touching_ || toi.outcome == TimeOfImpact::Outcome::InitiallyTouching;
    }
    TimeOfImpact result() const {
        if (first_.outcome != TimeOfImpact::Outcome::Hit && touching_)
            return {TimeOfImpact::Outcome::InitiallyTouching, 0.0f};
        return first_;
    }

private:
    TimeOfImpact first_;
    bool touching_ = false;
};

// Conservative advancement of convex `shape` on `sweep` towards one triangle at rest (world frame).
// The distance bound is the triangle narrow phase's separation (a separating axis's, never more
// than the true distance), and no point of the shape approaches the triangle's plane faster than
// its speed plus spin times reach, so each advance stays short of the first contact. The triangle
// is one-sided as in contacts: a shape behind it is let go.
TimeOfImpact triangleTimeOfImpact(const Triangle& triangle, const Shape& shape, const Sweep& sweep, float target,
                                  float tolerance) {
    const Vec3 motion = sweep.center1 - sweep.center0;
    const float turning = sweep.rotationAngle() * reachFromCenter(shape, sweep.localCenter);
    // Farther than the whole sweep can carry the shape, a triangle cannot be met.
    const float reach = glm::length(motion) + turning + target + tolerance;
    constexpr int kMaxIterations = 64;
    float fraction = 0.0f;
    Vec3 normal(0.0f);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        ContactManifold manifold;
        if (!collideTriangleConvex(triangle, shape, sweep.at(fraction), reach, manifold)) return {};
        float separation = manifold.points[0].separation;
        for (int p = 1; p < manifold.pointCount; ++p) separation = std::min(separation, manifold.points[p].separation);
        // From the shape (A) to the triangle (B), as timeOfImpact reports when the surface is B.
        normal = -manifold.normal;
        if (separation <= target + tolerance) {
            if (fraction == 0.0f) return {TimeOfImpact::Outcome::InitiallyTouching, 0.0f};
            return {TimeOfImpact::Outcome::Hit, fraction, normal};
        }
        const float approach = glm::dot(motion, normal) + turning;
        if (approach <= 0.0f) return {};
        fraction += (separation - target) / approach;
        if (fraction >= 1.0f) return {};
    }
    return {TimeOfImpact::Outcome::Hit, fraction, normal};
}

// A convex shape or compound on `sweep` against a surface resting at `surfacePose`: each sub-shape
// against each triangle its swept box meets (queried in the surface's frame). Normal from the
// swept shape to the surface.
TimeOfImpact surfaceTimeOfImpact(const Shape& moving, const Sweep& sweep, const Shape& surface,
                                 const Transform& surfacePose, float target, float tolerance) {
    EarliestImpact earliest;
    for (std::size_t i = 0; i < subShapeCount(moving); ++i) {
        const Shape& part = subShape(moving, i);
        const Sweep partSweep = subShapeSweep(moving, i, sweep);
        Aabb swept = worldBounds(part, partSweep.at(0.0f));
        swept.grow(worldBounds(part, partSweep.at(1.0f)));
        swept.min -= Vec3(target + tolerance);
        swept.max += Vec3(target + tolerance);
        visitSurface(surface, [&](const auto& triangles) {
            triangles.forEachTriangleOverlapping(boundsInFrame(swept, surfacePose), [&](std::uint32_t index) {
                earliest.add(triangleTimeOfImpact(triangles.triangle(index).placed(surfacePose), part, partSweep,
                                                  target, tolerance));
            });
        });
    }
    return earliest.result();
}

}  // namespace

TimeOfImpact timeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
                          float tolerance) {
    if (isConvex(a.type) && isConvex(b.type)) return convexTimeOfImpact(a, sweepA, b, sweepB, target, tolerance);
    if (isSurface(b.type)) return surfaceTimeOfImpact(a, sweepA, b, sweepB.at(0.0f), target, tolerance);
    if (isSurface(a.type)) {
        TimeOfImpact toi = surfaceTimeOfImpact(b, sweepB, a, sweepA.at(0.0f), target, tolerance);
        toi.normal = -toi.normal;
        return toi;
    }
    // Through the sub-shape pairs.
    EarliestImpact earliest;
    for (std::size_t i = 0; i < subShapeCount(a); ++i) {
        const Sweep childSweepA = subShapeSweep(a, i, sweepA);
        for (std::size_t j = 0; j < subShapeCount(b); ++j)
            earliest.add(convexTimeOfImpact(subShape(a, i), childSweepA, subShape(b, j), subShapeSweep(b, j, sweepB),
                                            target, tolerance));
    }
    return earliest.result();
}

namespace {

TimeOfImpact convexTimeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
                                float tolerance) {
    // Bound on how fast any point of A approaches any point of B along a unit direction n, per unit
    // of sweep fraction: the centres' relative motion along n plus each body's turn times its reach.
    const Vec3 relativeMotion = (sweepB.center1 - sweepB.center0) - (sweepA.center1 - sweepA.center0);
    const float turning = sweepA.rotationAngle() * reachFromCenter(a, sweepA.localCenter) +
                          sweepB.rotationAngle() * reachFromCenter(b, sweepB.localCenter);

    constexpr int kMaxIterations = 64;
    GjkCache cache;
    float fraction = 0.0f;
    Vec3 normal(0.0f);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const GjkResult gjk = gjkDistance(a, sweepA.at(fraction), b, sweepB.at(fraction), &cache);
        if (!isFinite(gjk.distance) || !isFinite(gjk.normal)) return {};  // degenerate input: leave it to contacts
        if (gjk.overlap || gjk.distance <= target + tolerance) {
            if (fraction == 0.0f) return {TimeOfImpact::Outcome::InitiallyTouching, 0.0f};
            return {TimeOfImpact::Outcome::Hit, fraction, gjk.normal};
        }
        normal = gjk.normal;
        const float approach = -glm::dot(relativeMotion, gjk.normal) + turning;
        if (approach <= 0.0f) return {};  // moving apart along the separating direction
        fraction += (gjk.distance - target) / approach;
        if (fraction >= 1.0f) return {};
    }
    // Converging this slowly means grazing contact: report where the advance got to, which is
    // still before the first contact.
    return {TimeOfImpact::Outcome::Hit, fraction, normal};
}

}  // namespace

}  // namespace simcore
