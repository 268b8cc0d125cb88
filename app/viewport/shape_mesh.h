#pragma once
// Triangle meshes for drawing simcore shapes. Each mesh is in the shape's local frame (the body
// origin), with counter-clockwise triangles seen from outside and outward unit normals: smooth on
// curved surfaces, flat on faces (box faces, cylinder caps, hull faces).

#include "simcore/shapes/shape.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace interplay {

struct MeshVertex {
    glm::vec3 position{0.0f};  // m, shape local frame
    glm::vec3 normal{0.0f};    // outward unit normal
};

struct ShapeMesh {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;  // three per triangle

    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct MeshDetail {
    int slices = 40;  // segments around the local Y axis (spheres, capsules, cylinders)
    int stacks = 20;  // latitude bands from pole to pole (spheres); half as many per capsule cap
};

// Convex shapes and surfaces (a mesh's or height field's triangles, each with its face normal, so
// the terrain is drawn faceted with the same look as hulls). A compound is drawn as its children's
// meshes (body_batches.h), so equal children share one; it gets an empty mesh here.
ShapeMesh buildShapeMesh(const simcore::Shape& shape, const MeshDetail& detail = {});

}  // namespace interplay
