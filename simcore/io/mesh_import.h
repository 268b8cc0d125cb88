#pragma once
// Geometry from files: OBJ, STL (ASCII and binary) and glTF 2.0 (.gltf with embedded or adjacent
// buffers, .glb) read through assimp into vertex and triangle arrays, ready for
// TriangleMesh::build or, as points, for ConvexHull::build.
//
// This is its own library, simcore_import, so that simcore itself keeps no dependency beyond GLM
// (and nlohmann-json inside its loader): the engine, its tests and the fuzzers of the scene format
// build without assimp, and only what imports files (the editor, the runner, the scene loader once
// it resolves "file" meshes) links it. assimp itself is opened on the first import
// (assimp_module.h), so a program that reads no mesh file does not carry it.
//
// Conventions: the result is in simcore's frame, +y up. A file whose up axis is +z (most CAD and
// STL files, Blender's default export without conversion) or +x is turned so that axis becomes +y,
// keeping handedness and the triangles' fronts; glTF is +y up by its specification. Then `scale`
// multiplies each axis (in simcore's frame); a scale with an odd number of negative components
// mirrors the mesh, and the triangles are rewound so their fronts stay outside. Node transforms
// of the file are applied (assimp's pre-transform step), so a glTF scene's pieces sit where its
// author placed them. Points and lines are ignored; polygons are triangulated; triangles too thin
// to have a normal (isDegenerateTriangle) are dropped and counted.
//
// Errors are plain sentences starting with the file's name: a missing or unreadable file, an
// unsupported extension, a file over maxFileBytes, a file assimp cannot parse (truncated,
// garbage), one with no triangles, or more than maxTriangles of them.

#include "simcore/io/mesh_file.h"
#include "simcore/math/math.h"
#include "simcore/shapes/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace simcore {

struct MeshImportOptions {
    Vec3 scale{1.0f};                              // per axis, after the up-axis turn; finite, non-zero
    UpAxis upAxis = UpAxis::Y;                     // the file's up axis
    std::size_t maxTriangles = kMaxMeshTriangles;  // refuse files with more
    std::uintmax_t maxFileBytes = 256u << 20;      // (bytes) refuse larger files before parsing
};

struct ImportedMesh {
    std::vector<Vec3> vertices;                      // m, simcore frame
    std::vector<TriangleMesh::Indices> triangles;    // counter-clockwise from the front
    std::size_t droppedTriangles = 0;                // degenerate triangles left out
    std::string error;                               // empty on success

    bool ok() const { return error.empty(); }
};

// Reads `file`; the format comes from its extension (.obj, .stl, .gltf, .glb, any case).
ImportedMesh importMesh(const std::filesystem::path& file, const MeshImportOptions& options = {});

// The same from bytes in memory; `format` is the extension without its dot ("obj", "stl", "gltf",
// "glb") and `name` is what messages call the data. A .gltf read this way must embed its buffers.
ImportedMesh importMeshFromMemory(const void* data, std::size_t size, std::string_view format, std::string_view name,
                                  const MeshImportOptions& options = {});

// A static mesh straight from a file: importMesh, then TriangleMesh::build, errors naming the file.
TriangleMesh::BuildResult importTriangleMesh(const std::filesystem::path& file, const MeshImportOptions& options = {});

// The scene loader's MeshFileLoader (mesh_file.h): importMesh of the reference's resolved path with
// its scale and up axis; errors name the file as the scene wrote it and as resolved.
MeshFileData importMeshFile(const MeshFileRequest& request);

// Points for a convex hull of an imported part: the extreme vertices (the hull's own), at most
// limits::kMaxHullPoints of them so a scene can store them. Fails for a flat or line-like mesh.
struct HullPoints {
    std::vector<Vec3> points;
    std::string error;  // empty on success
};
HullPoints hullPoints(const ImportedMesh& mesh);

}  // namespace simcore
