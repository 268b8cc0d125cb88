#pragma once
// Ray casts against a single placed shape, solved analytically per shape type. This is the narrow
// phase of picking: the broad phase (DynamicAabbTree::rayCast) proposes candidates, this finds
// where the ray really enters each one.
//
// Conventions:
//   - The ray is the segment origin + t * direction, t in [0, maxFraction]; the hit is reported as
//     that t (a fraction of `direction`, not a distance), so a ray from A with direction B - A
//     reports the share of the way from A to B.
//   - A compound reports its nearest child's entry; a ray from inside one child can still hit
//     another.
//   - A ray whose origin lies inside the shape reports no hit: picking from inside a body is not
//     meaningful, and the editor casts from the camera, which is outside. An origin exactly on the
//     surface hits at fraction 0 when the ray heads in, and misses when it heads out.
//   - Grazing rays (tangent to a curved side, running along a face or an edge) count as hits.
//   - Zero-length or non-finite directions, non-finite origins and a negative or NaN maxFraction
//     report no hit. An infinite maxFraction is allowed (an unbounded ray). Nothing returns NaN.

#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

#include <cstdint>
#include <optional>

namespace simcore {

struct RayCastInput {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f};
    float maxFraction = 1.0f;  // points origin + t * direction, t in [0, maxFraction]
};

struct RayCastHit {
    float fraction = 0.0f;  // t of the entry point, in [0, maxFraction]
    Vec3 point{0.0f};       // world frame, origin + fraction * direction
    Vec3 normal{0.0f};      // world frame, unit, outward at the hit (dot(normal, direction) <= 0)
    std::uint32_t subShape = 0;  // the sub-shape hit (shape.h): a compound's child, a surface's triangle, 0 for a convex shape
};

// First point where the ray enters `shape` placed by `transform`, or nothing.
std::optional<RayCastHit> rayCastShape(const Shape& shape, const Transform& transform, const RayCastInput& ray);

}  // namespace simcore
