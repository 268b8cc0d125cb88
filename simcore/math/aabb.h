#pragma once

#include "simcore/math/math.h"

#include <limits>

namespace simcore {

// Axis-aligned bounding box. An empty box has min > max, so growing it by any point works.
struct Aabb {
    Vec3 min{std::numeric_limits<float>::max()};
    Vec3 max{-std::numeric_limits<float>::max()};

    static Aabb fromCenterHalfExtents(const Vec3& center, const Vec3& halfExtents) {
        return {center - halfExtents, center + halfExtents};
    }

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    Vec3 center() const { return 0.5f * (min + max); }
    Vec3 halfExtents() const { return 0.5f * (max - min); }
    float surfaceArea() const {
        const Vec3 d = max - min;
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }

    void grow(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool overlaps(const Aabb& b) const {
        return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y &&
               min.z <= b.max.z && b.min.z <= max.z;
    }
    bool contains(const Aabb& b) const {
        return min.x <= b.min.x && min.y <= b.min.y && min.z <= b.min.z && b.max.x <= max.x &&
               b.max.y <= max.y && b.max.z <= max.z;
    }
};

}  // namespace simcore
