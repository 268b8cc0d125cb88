#pragma once
// Contact manifolds: what the narrow phase hands the solver for one touching (or nearly touching)
// pair of shapes. Up to four points share one normal; each point carries a feature id so the
// contact manager can match it with last step's point and warm-start its impulses.

#include "simcore/math/math.h"

#include <array>
#include <cstdint>

namespace simcore {

constexpr int kMaxManifoldPoints = 4;
// The narrow phase's scale for depth differences that do not matter (m): its choices between
// features and points are made against fractions of it, so round-off does not flip them. It is
// fixed, not the solver's settings.contact.linearSlop (also 5 mm by default), so the manifolds do
// not change with that setting.
constexpr float kLinearSlop = 0.005f;

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

// A contact point before reduction, as ContactPoint. Plain data without initialisers: the narrow
// phase's buffers of them (up to 64 points) are written before they are read, so making one costs
// nothing.
struct ContactCandidate {
    Vec3 pointA, pointB;
    float separation;
    std::uint32_t featureId;
};

// Makes `out` the manifold of `count` candidates sharing `normal`: at most kMaxManifoldPoints of
// them, spanning the largest area in the plane of the normal.
void reduceToManifold(const ContactCandidate* candidates, int count, const Vec3& normal, ContactManifold& out);

}  // namespace simcore
