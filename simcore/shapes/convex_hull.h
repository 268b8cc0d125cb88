#pragma once
// Convex polyhedron built from a point cloud by Quickhull. Faces are planar polygons (coplanar
// triangles merged) with outward normals and counter-clockwise vertex order seen from outside;
// edges are stored once each. This is the form face clipping and SAT need later.

#include "simcore/math/math.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace simcore {

struct HullFace {
    Vec3 normal{0.0f};            // outward unit normal
    float offset = 0.0f;          // plane: dot(normal, p) == offset for points p on the face
    std::uint32_t firstIndex = 0; // into ConvexHull::faceVertexIndices
    std::uint32_t vertexCount = 0;
};

struct HullEdge {
    std::uint32_t a = 0, b = 0;        // vertex indices
    std::uint32_t faceA = 0, faceB = 0; // the two faces sharing the edge
};

class ConvexHull {
public:
    struct BuildResult {
        std::shared_ptr<const ConvexHull> hull;  // null on failure
        std::string error;                       // why it failed, in a plain sentence
    };

    // Builds the hull of `points`. Fails (with a reason) on fewer than 4 points, non-finite
    // coordinates, or point sets with no volume: all coincident, collinear or coplanar (relative
    // to the cloud's size). Duplicate and interior points are dropped.
    static BuildResult build(const std::vector<Vec3>& points);

    const std::vector<Vec3>& vertices() const { return vertices_; }
    const std::vector<HullFace>& faces() const { return faces_; }
    const std::vector<std::uint32_t>& faceVertexIndices() const { return faceVertexIndices_; }
    const std::vector<HullEdge>& edges() const { return edges_; }

    // The points the hull was built from, kept so a scene saves exactly what it loaded.
    const std::vector<Vec3>& sourcePoints() const { return sourcePoints_; }

    Vec3 support(const Vec3& direction) const;

private:
    std::vector<Vec3> vertices_;
    std::vector<HullFace> faces_;
    std::vector<std::uint32_t> faceVertexIndices_;
    std::vector<HullEdge> edges_;
    std::vector<Vec3> sourcePoints_;
};

}  // namespace simcore
