#include "simcore/collision/time_of_impact.h"

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

}  // namespace

TimeOfImpact timeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
                          float tolerance) {
    if (isConvex(a.type) && isConvex(b.type)) return convexTimeOfImpact(a, sweepA, b, sweepB, target, tolerance);
    // Through the sub-shape pairs: the earliest hit of any; otherwise touching if any pair touches.
    TimeOfImpact first;
    bool touching = false;
    for (std::size_t i = 0; i < subShapeCount(a); ++i) {
        const Sweep childSweepA = subShapeSweep(a, i, sweepA);
        for (std::size_t j = 0; j < subShapeCount(b); ++j) {
            const TimeOfImpact toi = convexTimeOfImpact(subShape(a, i), childSweepA, subShape(b, j),
                                                        subShapeSweep(b, j, sweepB), target, tolerance);
            if (toi.outcome == TimeOfImpact::Outcome::Hit && (first.outcome != TimeOfImpact::Outcome::Hit ||
                                                              toi.fraction < first.fraction))
                first = toi;
            touching = touching || toi.outcome == TimeOfImpact::Outcome::InitiallyTouching;
        }
    }
    if (first.outcome != TimeOfImpact::Outcome::Hit && touching) return {TimeOfImpact::Outcome::InitiallyTouching, 0.0f};
    return first;
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
