// libFuzzer target: bytes through the geometry importer as each of its formats (OBJ, STL, glTF,
// GLB), and as raw vertex and index arrays through TriangleMesh::build. Whatever is accepted must
// build into a mesh (or be refused with a message) whose queries, ray cast and contacts stay finite;
// nothing may crash, hang or leak. Seeds: tests/data/meshes/ (valid and hostile files).
#include "simcore/collision/collide_mesh.h"
#include "simcore/io/mesh_import.h"
#include "simcore/shapes/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_mesh_import: %s\n", what);
        std::abort();
    }
}

// A built mesh answers every query with finite values.
void exercise(const simcore::TriangleMesh& mesh) {
    using namespace simcore;
    const Aabb bounds = mesh.bounds();
    require(isFinite(bounds.min) && isFinite(bounds.max), "non-finite mesh bounds");
    const Vec3 centre = bounds.center();
    std::size_t visited = 0;
    mesh.forEachTriangleOverlapping(bounds, [&](std::uint32_t t) {
        require(t < mesh.triangleCount(), "query returned a triangle out of range");
        ++visited;
    });
    require(visited == mesh.triangleCount(), "the mesh's own bounds do not hold every triangle");
    const Vec3 above = centre + Vec3(0.0f, bounds.halfExtents().y + 1.0f, 0.0f);
    if (const auto hit = mesh.rayCast(above, Vec3(0.0f, -2.0f * bounds.halfExtents().y - 2.0f, 0.0f)))
        require(isFinite(hit->point) && isFinite(hit->normal) && hit->triangle < mesh.triangleCount(), "bad ray hit");
    const Shape box = Shape::box(glm::max(0.25f * bounds.halfExtents(), Vec3(1e-3f)));
    const Transform pose{centre, Quat(1, 0, 0, 0)};
    int collided = 0;
    mesh.forEachTriangleOverlapping(worldBounds(box, pose), [&](std::uint32_t t) {
        if (collided++ > 64) return;  // enough to cover the narrow phase; keeps big meshes fast
        ContactManifold m;
        if (collideTriangleConvex(mesh.triangle(t), box, pose, 0.02f, m)) {
            require(isFinite(m.normal), "non-finite contact normal");
            for (int k = 0; k < m.pointCount; ++k)
                require(isFinite(m.points[k].pointA) && isFinite(m.points[k].separation), "non-finite contact point");
        }
    });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace simcore;
    MeshImportOptions options;
    options.maxTriangles = 100000;
    options.maxFileBytes = 1u << 20;
    for (const char* format : {"obj", "stl", "gltf", "glb"}) {
        ImportedMesh imported = importMeshFromMemory(data, size, format, "input", options);
        require(imported.ok() != imported.triangles.empty(), "an import is either triangles or an error");
        if (!imported.ok()) continue;
        (void)hullPoints(imported);
        const auto built = TriangleMesh::build(std::move(imported.vertices), std::move(imported.triangles));
        require(built.mesh || !built.error.empty(), "a refused mesh must say why");
        if (built.mesh) exercise(*built.mesh);
    }
    // Raw arrays: a vertex count, floats, then index triples, as a scene's inline mesh gives them.
    if (size >= 1) {
        const std::size_t vertexCount = data[0] % 64;
        std::size_t offset = 1;
        std::vector<Vec3> vertices;
        for (std::size_t v = 0; v < vertexCount && offset + 12 <= size; ++v, offset += 12) {
            float xyz[3];
            std::memcpy(xyz, data + offset, 12);
            vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
        std::vector<TriangleMesh::Indices> triangles;
        for (; offset + 3 <= size; offset += 3)
            triangles.push_back({data[offset], data[offset + 1], data[offset + 2]});
        const auto built = TriangleMesh::build(std::move(vertices), std::move(triangles));
        require(built.mesh || !built.error.empty(), "a refused mesh must say why");
        if (built.mesh) exercise(*built.mesh);
    }
    return 0;
}
