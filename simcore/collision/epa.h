#pragma once
// EPA (Expanding Polytope Algorithm): penetration depth of two overlapping convex shapes.
//
// When GJK finds that C = A - B contains the origin, EPA grows a polytope inside C, starting from
// GJK's simplex, always pushing out the face nearest the origin, until that face lies on C's
// surface. Its distance is the penetration depth and its normal the direction in which B must move
// to separate.
//
// Shapes are cores plus radii (see gjk.h). If the cores are apart, the depth is the radius sum
// minus the core distance, along GJK's normal, with no EPA at all. If the cores overlap, EPA runs
// on the cores and the radius sum is added: C of the full shapes is C of the cores inflated by the
// radius sum, so both the depth and the direction carry over exactly, while the polytope never has
// to approximate a sphere. Two round shapes (sphere, capsule) have cores without volume, and their
// overlap is resolved in closed form.

#include "simcore/collision/gjk.h"

namespace simcore {

enum class EpaStatus : std::uint8_t {
    Converged,      // tolerance met (or the depth came in closed form)
    MaxIterations,  // polytope capacity or iteration cap hit: the best direction found is reported
    Degenerate,     // the polytope could not be built or grown: the best direction found is reported
    Separated,      // the shapes do not overlap: depth 0, normal and points from GJK
};

struct EpaResult {
    float depth = 0.0f;              // (m), >= 0: moving B by depth * normal separates the shapes
    Vec3 normal{0.0f, 1.0f, 0.0f};   // unit, from A to B
    Vec3 pointA{0.0f};               // deepest point of A inside B, on A's surface (world)
    Vec3 pointB{0.0f};               // deepest point of B inside A, on B's surface (world)
    int iterations = 0;              // polytope expansions
    EpaStatus status = EpaStatus::Converged;
};

constexpr int kEpaMaxVertices = 128;
constexpr int kEpaMaxFaces = 2 * kEpaMaxVertices;  // a closed triangulated polytope has 2V - 4 faces
constexpr int kEpaMaxIterations = kEpaMaxVertices - 8;

EpaResult epaPenetration(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb);

// EPA on the cores (no radii) from the simplex of a GJK run that found the cores overlapping.
EpaResult epaCorePenetration(const CorePair& pair, const GjkSimplex& simplex);

// What the contact generator asks for a generic convex pair: the gap if the shapes are apart,
// the penetration if they are not.
struct ContactQuery {
    bool penetrating = false;        // touching counts as penetrating with depth ~0
    float distance = 0.0f;           // separated: gap between the surfaces (m), > 0
    float depth = 0.0f;              // penetrating: (m), >= 0; moving B by depth * normal separates
    Vec3 normal{0.0f, 1.0f, 0.0f};   // unit, from A to B
    Vec3 pointA{0.0f};               // closest (separated) or deepest (penetrating) point on A (world)
    Vec3 pointB{0.0f};               // same on B
    int gjkIterations = 0;
    int epaIterations = 0;
    bool epaUsed = false;
    GjkStatus gjkStatus = GjkStatus::Converged;
    EpaStatus epaStatus = EpaStatus::Converged;  // meaningful when penetrating

    float signedDistance() const { return penetrating ? -depth : distance; }
};

ContactQuery penetrationOrDistance(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                                   GjkCache* cache = nullptr);

}  // namespace simcore
