#pragma once
// Small geometric helpers shared by the collision tests: placing shapes, building hulls, and
// measuring placed shapes through their support functions.

#include "simcore/math/math.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/shape.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
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
