#include "simcore/collision/time_of_impact.h"

#include "simcore/collision/gjk.h"

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

}  // namespace

TimeOfImpact timeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
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

}  // namespace simcore
