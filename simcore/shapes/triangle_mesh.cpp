#include "simcore/shapes/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace simcore {

namespace {

// A triangle is degenerate when its area is below this share of its longest edge squared: the
// smallest angle is then under ~1e-4 degrees and its normal is mostly round-off.
constexpr float kSliverRatio = 1e-6f;

std::string vec3Text(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
    return text;
}

}  // namespace

bool isDegenerateTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const float longest = std::max({lengthSquared(b - a), lengthSquared(c - b), lengthSquared(a - c)});
    return !(glm::length(glm::cross(b - a, c - a)) > kSliverRatio * longest);
}

Triangle Triangle::placed(const Transform& transform) const {
    return {{transform.apply(vertices[0]), transform.apply(vertices[1]), transform.apply(vertices[2])},
            glm::normalize(transform.rotate(normal)), flags};
}

bool isActiveEdge(const Vec3& normal, const Vec3& edgePoint, const Vec3& neighbourNormal, const Vec3& neighbourOpposite) {
    const bool convex = glm::dot(normal, neighbourOpposite - edgePoint) < 0.0f;
    return convex && glm::dot(normal, neighbourNormal) < std::cos(kActiveEdgeAngle);
}

TriangleFeatureFlags withVertexFlags(TriangleFeatureFlags edgeFlags) {
    TriangleFeatureFlags flags = edgeFlags & 0x7u;
    for (int v = 0; v < 3; ++v) {
        // Vertex v is where edge v (leaving it) and edge v - 1 (arriving) meet.
        if (isEdgeActive(edgeFlags, v) || isEdgeActive(edgeFlags, (v + 2) % 3)) flags |= kVertexActive0 << v;
    }
    return flags;
}

std::optional<SurfaceRayHit> rayCastTriangle(const Triangle& triangle, const Vec3& origin, const Vec3& direction,
                                             float maxFraction) {
    const Vec3 e1 = triangle.vertices[1] - triangle.vertices[0];
    const Vec3 e2 = triangle.vertices[2] - triangle.vertices[0];
    const Vec3 p = glm::cross(direction, e2);
    const float det = glm::dot(e1, p);
    if (!(std::abs(det) > 1e-20f)) return std::nullopt;  // in the triangle's plane (or NaN)
    const float inverse = 1.0f / det;
    const Vec3 s = origin - triangle.vertices[0];
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = glm::dot(e2, q) * inverse;
    if (!(t >= 0.0f && t <= maxFraction)) return std::nullopt;
    SurfaceRayHit hit;
    hit.fraction = t;
    hit.point = origin + t * direction;
    hit.frontFace = glm::dot(triangle.normal, direction) < 0.0f;
    hit.normal = hit.frontFace ? triangle.normal : -triangle.normal;
    return hit;
}

TriangleMesh::BuildResult TriangleMesh::build(std::vector<Vec3> vertices, std::vector<Indices> triangles) {
    if (triangles.empty()) return {nullptr, "the mesh has no triangles"};
    if (triangles.size() > kMaxMeshTriangles)
        return {nullptr, "the mesh has " + std::to_string(triangles.size()) + " triangles; at most " +
                             std::to_string(kMaxMeshTriangles) + " are allowed"};
    if (vertices.size() > kMaxMeshVertices)
        return {nullptr, "the mesh has " + std::to_string(vertices.size()) + " vertices; at most " +
                             std::to_string(kMaxMeshVertices) + " are allowed"};
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec3& v = vertices[i];
        if (!isFinite(v)) return {nullptr, "vertex " + std::to_string(i) + " is not finite"};
        if (glm::any(glm::greaterThan(glm::abs(v), Vec3(kMaxMeshCoordinate))))
            return {nullptr, "vertex " + std::to_string(i) + " " + vec3Text(v) + " is beyond " +
                                 std::to_string(int(kMaxMeshCoordinate)) + " m from the origin"};
    }

    std::shared_ptr<TriangleMesh> mesh(new TriangleMesh());
    mesh->normals_.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Indices& index = triangles[t];
        const std::string name = "triangle " + std::to_string(t);
        for (int k = 0; k < 3; ++k) {
            if (index[k] >= vertices.size())
                return {nullptr, name + " uses vertex " + std::to_string(index[k]) + ", but the mesh has " +
                                     std::to_string(vertices.size()) + " vertices"};
        }
        if (index[0] == index[1] || index[1] == index[2] || index[2] == index[0])
            return {nullptr, name + " uses a vertex twice (" + std::to_string(index[0]) + ", " +
                                 std::to_string(index[1]) + ", " + std::to_string(index[2]) + ")"};
        const Vec3& a = vertices[index[0]];
        const Vec3& b = vertices[index[1]];
        const Vec3& c = vertices[index[2]];
        const Vec3 n = glm::cross(b - a, c - a);
        const float doubleArea = glm::length(n);
        if (isDegenerateTriangle(a, b, c))
            return {nullptr, name + " is degenerate: vertices " + std::to_string(index[0]) + ", " +
                                 std::to_string(index[1]) + " and " + std::to_string(index[2]) +
                                 " are coincident or in a line (area " + std::to_string(0.5f * doubleArea) + " m^2)"};
        mesh->normals_.push_back(n / doubleArea);
    }

    mesh->vertices_ = std::move(vertices);
    mesh->triangles_ = std::move(triangles);
    mesh->buildAdjacency();
    mesh->buildBvh();
    return {std::move(mesh), {}};
}

void TriangleMesh::buildAdjacency() {
    // Weld by exact position, so files that repeat a vertex per triangle (STL) still get seams.
    std::vector<std::uint32_t> order(vertices_.size());
    std::iota(order.begin(), order.end(), 0u);
    auto lexicographic = [&](std::uint32_t l, std::uint32_t r) {
        const Vec3& a = vertices_[l];
        const Vec3& b = vertices_[r];
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        if (a.z != b.z) return a.z < b.z;
        return l < r;
    };
    std::sort(order.begin(), order.end(), lexicographic);
    std::vector<std::uint32_t> welded(vertices_.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        welded[order[i]] = (i > 0 && vertices_[order[i]] == vertices_[order[i - 1]]) ? welded[order[i - 1]] : order[i];

    struct EdgeRecord {
        std::uint64_t key;  // the welded vertex pair, smaller first
        std::uint32_t triangle;
        std::uint32_t edge;
    };
    std::vector<EdgeRecord> edges;
    edges.reserve(3 * triangles_.size());
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
        for (std::uint32_t e = 0; e < 3; ++e) {
            const std::uint32_t a = welded[triangles_[t][e]];
            const std::uint32_t b = welded[triangles_[t][(e + 1) % 3]];
            edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), t, e});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const EdgeRecord& l, const EdgeRecord& r) {
        return l.key != r.key ? l.key < r.key : l.triangle != r.triangle ? l.triangle < r.triangle : l.edge < r.edge;
    });

    neighbours_.assign(triangles_.size(), {kNoNeighbour, kNoNeighbour, kNoNeighbour});
    std::vector<TriangleFeatureFlags> edgeFlags(triangles_.size(), 0x7u);  // boundary and non-manifold: active
    for (std::size_t first = 0; first < edges.size();) {
        std::size_t last = first + 1;
        while (last < edges.size() && edges[last].key == edges[first].key) ++last;
        if (last - first == 2) {
            const EdgeRecord& l = edges[first];
            const EdgeRecord& r = edges[first + 1];
            neighbours_[l.triangle][l.edge] = r.triangle;
            neighbours_[r.triangle][r.edge] = l.triangle;
            auto settle = [&](const EdgeRecord& self, const EdgeRecord& other) {
                const Vec3& onEdge = vertices_[triangles_[self.triangle][self.edge]];
                const Vec3& opposite = vertices_[triangles_[other.triangle][(other.edge + 2) % 3]];
                if (!isActiveEdge(normals_[self.triangle], onEdge, normals_[other.triangle], opposite))
                    edgeFlags[self.triangle] &= TriangleFeatureFlags(~(kEdgeActive0 << self.edge));
            };
            settle(l, r);
            settle(r, l);
        }
        first = last;
    }
    flags_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) flags_[t] = withVertexFlags(edgeFlags[t]);
}

void TriangleMesh::buildBvh() {
    triangleBounds_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
        Aabb box;
        for (std::uint32_t v : triangles_[t]) box.grow(vertices_[v]);
        triangleBounds_[t] = box;
    }
    leafTriangles_.resize(triangles_.size());
    std::iota(leafTriangles_.begin(), leafTriangles_.end(), 0u);
    nodes_.reserve(2 * (triangles_.size() / kMaxLeafTriangles + 1));
    buildNode(0, std::uint32_t(triangles_.size()), 1);
}

// Top-down, split at the median of the centroids along the longest axis of their bounds: balanced,
// so the depth stays logarithmic whatever the triangles' sizes.
std::uint32_t TriangleMesh::buildNode(std::uint32_t first, std::uint32_t count, int depth) {
    depth_ = std::max(depth_, depth);
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    Aabb bounds, centroids;
    for (std::uint32_t k = first; k < first + count; ++k) {
        bounds.grow(triangleBounds_[leafTriangles_[k]]);
        centroids.grow(triangleBounds_[leafTriangles_[k]].center());
    }
    nodes_[index].bounds = bounds;
    if (count <= std::uint32_t(kMaxLeafTriangles)) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    const Vec3 size = centroids.max - centroids.min;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    std::nth_element(leafTriangles_.begin() + first, leafTriangles_.begin() + first + half,
                     leafTriangles_.begin() + first + count, [&](std::uint32_t l, std::uint32_t r) {
                         const float cl = triangleBounds_[l].center()[axis];
                         const float cr = triangleBounds_[r].center()[axis];
                         return cl != cr ? cl < cr : l < r;
                     });
    buildNode(first, half, depth + 1);  // the left child is the next node
    const std::uint32_t right = buildNode(first + half, count - half, depth + 1);
    nodes_[index].first = right;
    return index;
}

std::optional<SurfaceRayHit> TriangleMesh::rayCast(const Vec3& origin, const Vec3& direction, float maxFraction) const {
    if (!isFinite(origin) || !isFinite(direction) || !(maxFraction >= 0.0f) || lengthSquared(direction) == 0.0f)
        return std::nullopt;
    const Vec3 inverse = 1.0f / direction;  // infinities for zero components are what the slab test needs
    std::optional<SurfaceRayHit> best;
    float limit = maxFraction;
    // Entry fraction of the ray into `box`, or nothing when it misses within [0, limit].
    auto enter = [&](const Aabb& box) -> std::optional<float> {
        float near = 0.0f, far = limit;
        for (int k = 0; k < 3; ++k) {
            if (direction[k] == 0.0f) {
                if (origin[k] < box.min[k] || origin[k] > box.max[k]) return std::nullopt;
                continue;
            }
            float t0 = (box.min[k] - origin[k]) * inverse[k];
            float t1 = (box.max[k] - origin[k]) * inverse[k];
            if (t0 > t1) std::swap(t0, t1);
            near = std::max(near, t0);
            far = std::min(far, t1);
            if (near > far) return std::nullopt;
        }
        return near;
    };
    std::uint32_t stack[kMaxDepth + 1];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint32_t index = stack[--top];
        const Node& node = nodes_[index];
        if (!enter(node.bounds)) continue;
        if (node.count > 0) {
            for (std::uint32_t k = 0; k < node.count; ++k) {
                const std::uint32_t t = leafTriangles_[node.first + k];
                if (auto hit = rayCastTriangle(triangle(t), origin, direction, limit)) {
                    if (!best || hit->fraction < best->fraction ||
                        (hit->fraction == best->fraction && t < best->triangle)) {
                        hit->triangle = t;
                        best = hit;
                        limit = hit->fraction;
                    }
                }
            }
        } else {
            stack[top++] = node.first;
            stack[top++] = index + 1;
        }
    }
    return best;
}

}  // namespace simcore
