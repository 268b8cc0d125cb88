#pragma once
// Static triangle surfaces: an immutable triangle mesh with a BVH over its triangles. The height
// field (height_field.h) offers the same surface interface (triangle(), forEachTriangleOverlapping(),
// rayCast()), so the collision code (collision/collide_mesh.h) serves both.
//
// Conventions:
//   - A triangle's front is the side from which its vertices run counter-clockwise; its normal
//     points out of the front. Surfaces are one-sided for collision: a shape whose centre is behind
//     a triangle's plane gets no contact from it (see collide_mesh.h), so a body found inside a
//     closed mesh or under a terrain is not shot through it, and a wall can be entered from behind.
//     Ray casts are two-sided (picking a terrain from below still finds it).
//   - Edge i of a triangle runs from vertex i to vertex i + 1 (mod 3). An edge is "active" when a
//     contact on it may take the edge's own normal: a boundary edge, an edge shared by more than
//     two triangles, or a convex crease sharper than kActiveEdgeAngle. Flat and concave seams are
//     inactive, so a contact there takes the face normal and a body sliding over them does not
//     bump. A vertex is active when either of the triangle's edges meeting at it is active.

#include "simcore/math/aabb.h"
#include "simcore/math/math.h"
#include "simcore/settings_schema.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace simcore {

// A convex crease flatter than this keeps inactive edges: a gently curved terrain tessellated into
// triangles behaves as a smooth surface (Jolt uses 5 degrees as well).
constexpr float kActiveEdgeAngle = 5.0f * kPi / 180.0f;  // rad

// Limits a mesh is built within, so a hostile file cannot exhaust memory or break float precision.
constexpr std::size_t kMaxMeshTriangles = limits::kMaxMeshTriangles;  // settings_schema.h: the loader's too
constexpr std::size_t kMaxMeshVertices = limits::kMaxMeshVertices;
constexpr float kMaxMeshCoordinate = 1e6f;  // m, the range of positions elsewhere in a scene

// Per-triangle feature flags: bit i (0..2) = edge i active, bit 3 + i = vertex i active.
using TriangleFeatureFlags = std::uint8_t;
constexpr TriangleFeatureFlags kEdgeActive0 = 1u << 0;
constexpr TriangleFeatureFlags kVertexActive0 = 1u << 3;
constexpr TriangleFeatureFlags kAllFeaturesActive = 0x3f;

inline bool isEdgeActive(TriangleFeatureFlags flags, int edge) { return (flags >> edge) & 1u; }
inline bool isVertexActive(TriangleFeatureFlags flags, int vertex) { return (flags >> (3 + vertex)) & 1u; }

// One triangle of a surface, with what collision needs to know about it.
struct Triangle {
    std::array<Vec3, 3> vertices{};       // counter-clockwise seen from the front
    Vec3 normal{0.0f, 1.0f, 0.0f};        // unit, out of the front
    TriangleFeatureFlags flags = kAllFeaturesActive;

    Triangle placed(const Transform& transform) const;  // the same triangle in another frame
};

// Whether triangle abc is too thin to have a trustworthy normal (zero area, or a sliver whose
// area is below a millionth of its longest edge squared). TriangleMesh::build refuses such
// triangles; importers drop them.
bool isDegenerateTriangle(const Vec3& a, const Vec3& b, const Vec3& c);

// Whether an edge at vertex `edgePoint` of a triangle with unit normal `normal` is active, given the
// neighbouring triangle across it: its unit normal and its vertex off the edge (see above).
bool isActiveEdge(const Vec3& normal, const Vec3& edgePoint, const Vec3& neighbourNormal, const Vec3& neighbourOpposite);

// Vertex flags that follow from the edge flags (bits 0..2 in, all six bits out).
TriangleFeatureFlags withVertexFlags(TriangleFeatureFlags edgeFlags);

// Nearest hit of a ray on a surface.
struct SurfaceRayHit {
    float fraction = 0.0f;          // t of the hit on origin + t * direction
    Vec3 point{0.0f};
    Vec3 normal{0.0f};              // unit, facing the ray (dot(normal, direction) <= 0)
    std::uint32_t triangle = 0;     // index of the triangle hit
    bool frontFace = true;          // the ray came from the triangle's front
};

// Ray against one triangle, two-sided (Moller-Trumbore); nothing for a ray in its plane.
std::optional<SurfaceRayHit> rayCastTriangle(const Triangle& triangle, const Vec3& origin, const Vec3& direction,
                                             float maxFraction);

class TriangleMesh {
public:
    using Indices = std::array<std::uint32_t, 3>;

    struct BuildResult {
        std::shared_ptr<const TriangleMesh> mesh;  // null on failure
        std::string error;                         // why it failed, naming the triangle or vertex
    };

    // Validates and builds. Fails on: no triangles, more than kMaxMeshTriangles (or vertices), a
    // non-finite vertex or one beyond kMaxMeshCoordinate, an index out of range, a triangle using a
    // vertex twice, or a degenerate (zero-area or sliver) triangle. Vertices no triangle uses are
    // allowed (an imported file may carry them).
    static BuildResult build(std::vector<Vec3> vertices, std::vector<Indices> triangles);

    std::size_t triangleCount() const { return triangles_.size(); }
    const std::vector<Vec3>& vertices() const { return vertices_; }
    const std::vector<Indices>& triangleIndices() const { return triangles_; }
    Triangle triangle(std::uint32_t index) const {
        const Indices& t = triangles_[index];
        return {{vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]}, normals_[index], flags_[index]};
    }
    // The triangle across edge `edge` of triangle `index` (vertices welded by exact position), or
    // kNoNeighbour on a boundary edge or one shared by more than two triangles.
    static constexpr std::uint32_t kNoNeighbour = 0xffffffffu;
    std::uint32_t neighbour(std::uint32_t index, int edge) const { return neighbours_[index][edge]; }
    const Aabb& bounds() const { return nodes_.front().bounds; }
    int bvhDepth() const { return depth_; }

    // Calls visit(triangleIndex) for every triangle whose bounding box overlaps `box` (each once,
    // in BVH order). Allocates nothing.
    template <class Visit>
    void forEachTriangleOverlapping(const Aabb& box, Visit&& visit) const;

    // Nearest hit along origin + t * direction, t in [0, maxFraction]; two-sided.
    std::optional<SurfaceRayHit> rayCast(const Vec3& origin, const Vec3& direction, float maxFraction = 1.0f) const;

    // A BVH node: an inner node's children are the next node and `first`; a leaf holds `count`
    // triangles from leafTriangles_[first].
    struct Node {
        Aabb bounds;
        std::uint32_t first = 0;
        std::uint32_t count = 0;  // 0: inner node
    };
    static constexpr int kMaxLeafTriangles = 4;
    static constexpr int kMaxDepth = 48;  // median splits: depth <= log2(kMaxMeshTriangles) + 2

private:
    TriangleMesh() = default;
    void buildAdjacency();
    void buildBvh();
    std::uint32_t buildNode(std::uint32_t first, std::uint32_t count, int depth);

    std::vector<Vec3> vertices_;
    std::vector<Indices> triangles_;
    std::vector<Vec3> normals_;
    std::vector<TriangleFeatureFlags> flags_;
    std::vector<Indices> neighbours_;
    std::vector<Aabb> triangleBounds_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> leafTriangles_;
    int depth_ = 0;
};

template <class Visit>
void TriangleMesh::forEachTriangleOverlapping(const Aabb& box, Visit&& visit) const {
    std::uint32_t stack[kMaxDepth + 1];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint32_t index = stack[--top];
        const Node& node = nodes_[index];
        if (!node.bounds.overlaps(box)) continue;
        if (node.count > 0) {
            for (std::uint32_t k = 0; k < node.count; ++k) {
                const std::uint32_t t = leafTriangles_[node.first + k];
                if (triangleBounds_[t].overlaps(box)) visit(t);
            }
        } else {
            stack[top++] = node.first;
            stack[top++] = index + 1;
        }
    }
}

}  // namespace simcore
