#pragma once
// Contact manifolds: what the narrow phase hands the solver for one touching (or nearly touching)
// pair of shapes. Up to four points share one normal; each point carries a feature id so the
// contact manager can match it with last step's point and warm-start its impulses.

#include "simcore/math/math.h"

#include <array>
#include <cstdint>

namespace simcore {

constexpr int kMaxManifoldPoints = 4;

struct ContactPoint {
    Vec3 pointA{0.0f};         // on A's surface, world frame (m)
    Vec3 pointB{0.0f};         // on B's surface, world frame (m)
    float separation = 0.0f;   // dot(pointB - pointA, normal): negative when penetrating (m)
    std::uint32_t featureId = 0;  // identifies the pair of features that made the point; stable while they touch
};

struct ContactManifold {
    Vec3 normal{0.0f, 1.0f, 0.0f};  // unit, world frame, from A towards B
    std::array<ContactPoint, kMaxManifoldPoints> points{};
    int pointCount = 0;
};

}  // namespace simcore
