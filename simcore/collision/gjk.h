#pragma once
// GJK (Gilbert-Johnson-Keerthi) distance between two convex shapes placed in the world.
//
// GJK works on C = A - B, the set of all differences a - b. The shapes are apart by the distance
// from the origin to C, and overlap when C contains the origin. A simplex of up to four points of
// C is refined towards the point of C nearest the origin; each simplex point remembers the two
// shape points it came from, so the closest points on A and B follow from the same weights.
//
// Every shape is seen as a core inflated by a radius: a sphere is its centre plus its radius, a
// capsule its segment plus its radius, and boxes, cylinders and hulls are their own core with
// radius 0. GJK runs on the cores and the radii are subtracted afterwards, so round shapes
// converge in a couple of iterations instead of crawling along a curved surface.

#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

#include <array>
#include <cstdint>

namespace simcore {

enum class GjkStatus : std::uint8_t {
    Converged,      // tolerance met, no further progress possible, or overlap found
    MaxIterations,  // iteration cap hit: the best simplex found is reported
    Degenerate,     // non-finite input or progress stalled far from the tolerance: best found so far
};

struct GjkResult {
    float distance = 0.0f;              // between the surfaces (m), >= 0; 0 when they overlap
    Vec3 pointA{0.0f};                  // closest point on A's surface (world)
    Vec3 pointB{0.0f};                  // closest point on B's surface (world)
    Vec3 normal{0.0f, 1.0f, 0.0f};      // unit, from A to B; on overlap only a guess (EPA finds the real one)
    int iterations = 0;                 // support evaluations after the first
    bool overlap = false;               // the surfaces touch or penetrate (distance 0 within tolerance)
    GjkStatus status = GjkStatus::Converged;
};

// Warm start for one pair across frames: the final simplex, as points in each shape's own frame so
// that it stays valid while the bodies move. Clear it (count = 0) when either shape changes.
struct GjkCache {
    int count = 0;
    std::array<Vec3, 4> localA{};
    std::array<Vec3, 4> localB{};
};

constexpr int kGjkMaxIterations = 64;

GjkResult gjkDistance(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                      GjkCache* cache = nullptr);

// Overlap test only: stops as soon as a separating direction is found, so it is cheaper than
// gjkDistance for pairs that are clearly apart.
bool gjkIntersect(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                  GjkCache* cache = nullptr);

// ---- Building blocks shared with EPA and the contact generator ----

// A shape placed by a transform, seen as its core plus a radius.
struct PlacedCore {
    PlacedCore(const Shape& shape, const Transform& transform);

    // Farthest core point along a local direction.
    Vec3 localSupport(const Vec3& localDirection) const;

    const Shape* shape;
    Transform transform;
    float radius;
    bool lowerDimensional;  // point or segment (sphere, capsule): the core has no volume
};

// One point of C = A - B with the core points it came from.
struct SupportPoint {
    Vec3 w{0.0f};       // a - b (world)
    Vec3 a{0.0f};       // on A's core (world)
    Vec3 b{0.0f};       // on B's core (world)
    Vec3 localA{0.0f};  // a in A's frame, for the warm-start cache
    Vec3 localB{0.0f};
};

struct CorePair {
    CorePair(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb) : a(a, ta), b(b, tb) {}

    // Farthest point of C (of the cores) along a world direction.
    SupportPoint support(const Vec3& direction) const;
    SupportPoint fromLocal(const Vec3& localA, const Vec3& localB) const;
    float radiusSum() const { return a.radius + b.radius; }

    PlacedCore a;
    PlacedCore b;
};

struct GjkSimplex {
    std::array<SupportPoint, 4> vertices{};
    std::array<float, 4> weights{};  // barycentric weights of the closest point
    int count = 0;
};

// GJK on the cores only (no radii).
struct GjkCoreResult {
    GjkSimplex simplex;           // final simplex; contains the origin (within tolerance) on overlap
    Vec3 closest{0.0f};           // point of C nearest the origin (a - b)
    Vec3 pointA{0.0f};            // on A's core (world)
    Vec3 pointB{0.0f};            // on B's core (world)
    float distance = 0.0f;        // |closest|
    float tolerance = 0.0f;       // absolute distance resolution of this query (m), from the coordinates' size
    Vec3 lastDirection{0.0f, 1.0f, 0.0f};  // unit A-to-B direction of the last non-zero estimate
    bool overlap = false;         // cores touch or overlap
    int iterations = 0;
    GjkStatus status = GjkStatus::Converged;
};

GjkCoreResult gjkCoreDistance(const CorePair& pair, GjkCache* cache = nullptr);

}  // namespace simcore
