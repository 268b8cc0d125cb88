#pragma once
// Small geometric helpers shared by the collision tests: placing shapes, building hulls, and
// measuring placed shapes through their support functions.

#include "simcore/math/math.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/shape.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace test_support {

using namespace simcore;

inline Quat rotation(float degrees, const Vec3& axis) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// Rotation taking direction `from` onto direction `to` (not opposite).
inline Quat rotationBetween(const Vec3& from, const Vec3& to) {
    const Vec3 f = glm::normalize(from);
    const Vec3 t = glm::normalize(to);
    return glm::angleAxis(std::acos(std::clamp(glm::dot(f, t), -1.0f, 1.0f)), glm::normalize(glm::cross(f, t)));
}

inline Transform place(const Vec3& position, const Quat& orientation = Quat(1.0f, 0.0f, 0.0f, 0.0f)) {
    Transform t;
    t.position = position;
    t.rotation = orientation;
    return t;
}

// Applies `outer` after `inner`.
inline Transform compose(const Transform& outer, const Transform& inner) {
    return place(outer.apply(inner.position), glm::normalize(outer.rotation * inner.rotation));
}

// Farthest extent of the placed shape along a world direction.
inline float extentAlong(const Shape& shape, const Transform& t, const Vec3& direction) {
    return glm::dot(direction, t.apply(support(shape, t.rotateInverse(direction))));
}

// Diagonal of the local bounds: the shape's scale, for relative tolerances.
inline float sizeOf(const Shape& shape) {
    const Aabb bounds = localBounds(shape);
    return glm::length(bounds.max - bounds.min);
}

// Signed distance from a point in the shape's local frame to its surface: negative inside. Exact
// for every primitive; for hulls the largest face-plane distance, exact inside and on faces and
// never more than the true distance outside.
inline float signedDistance(const Shape& shape, const Vec3& p) {
    switch (shape.type) {
        case ShapeType::Sphere: return glm::length(p) - shape.radius;
        case ShapeType::Box: {
            const Vec3 q = glm::abs(p) - shape.halfExtents;
            return glm::length(glm::max(q, Vec3(0.0f))) + std::min(std::max({q.x, q.y, q.z}), 0.0f);
        }
        case ShapeType::Capsule: {
            const float y = std::clamp(p.y, -shape.halfHeight, shape.halfHeight);
            return glm::length(p - Vec3(0.0f, y, 0.0f)) - shape.radius;
        }
        case ShapeType::Cylinder: {
            const glm::vec2 d(std::sqrt(p.x * p.x + p.z * p.z) - shape.radius, std::abs(p.y) - shape.halfHeight);
            return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, glm::vec2(0.0f)));
        }
        case ShapeType::ConvexHull: {
            float distance = -std::numeric_limits<float>::max();
            for (const HullFace& f : shape.hull->faces()) distance = std::max(distance, glm::dot(f.normal, p) - f.offset);
            return distance;
        }
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // not convex: callers pass convex shapes only
    }
    return 0.0f;
}

// The same for a placed shape and a world point.
inline float outsideBy(const Shape& shape, const Transform& t, const Vec3& world) {
    return signedDistance(shape, t.applyInverse(world));
}

// A hull the test needs; failing to build one is a broken test, not a result.
inline std::shared_ptr<const ConvexHull> buildHull(const std::vector<Vec3>& points) {
    auto result = ConvexHull::build(points);
    if (!result.hull) qFatal("hull build failed: %s", result.error.c_str());
    return result.hull;
}

inline Shape octahedron(float r) {
    return Shape::convexHull(buildHull({{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}}));
}

// A box with the given half extents, as a convex hull of its eight corners.
inline Shape boxHull(const Vec3& h) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i) corners.emplace_back((i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z);
    return Shape::convexHull(buildHull(corners));
}

}  // namespace test_support
