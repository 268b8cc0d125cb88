#pragma once
// Meshes a scene keeps in files of their own ("shape": {"type": "mesh", "file": "terrain.obj"}):
// the reference a scene body keeps, and the callback through which the loader reads such a file.
//
// The loader (simcore, no assimp) does not read OBJ, STL or glTF itself: whoever loads a scene
// passes a MeshFileLoader in SceneReadOptions, and the importer library offers one
// (simcore_import's importMeshFile). A callback, not a registry: no global state, and a program
// that links no importer (the fuzzers, the engine's own tests) still loads every other scene and
// says clearly why a file mesh cannot be read. Whatever the callback returns goes through the
// limits of an inline mesh (TriangleMesh::build: triangle and vertex counts, coordinates,
// degenerate triangles), so a loader cannot smuggle in what a file could not hold.

#include "simcore/math/math.h"
#include "simcore/shapes/triangle_mesh.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simcore {

// The axis a mesh file calls up; it is turned to simcore's +y on import.
enum class UpAxis : std::uint8_t { Y, Z, X };

// "y", "z", "x"; parseUpAxis is its inverse (nothing for anything else).
std::string_view upAxisName(UpAxis axis);
std::optional<UpAxis> parseUpAxis(std::string_view name);

// Where a body's mesh came from. The scene's shape holds the mesh as imported (scaled, turned).
struct MeshFileReference {
    std::string file;                    // as the scene file wrote it: relative to its folder, or absolute
    std::filesystem::path resolvedPath;  // absolute and normalised; what was read
    Vec3 scale{1.0f};                    // per axis, in simcore's frame after the up-axis turn
    UpAxis upAxis = UpAxis::Y;           // the file's up axis

    bool operator==(const MeshFileReference&) const = default;
};

// What the loader asks its callback for, and what the callback gives back.
struct MeshFileRequest {
    const MeshFileReference& reference;
};
struct MeshFileData {
    std::vector<Vec3> vertices;                    // m, simcore frame, scaled
    std::vector<TriangleMesh::Indices> triangles;  // counter-clockwise from the front
    std::string error;                             // why the file could not be read; empty on success
};
using MeshFileLoader = std::function<MeshFileData(const MeshFileRequest&)>;

// The absolute, normalised path `file` (as a scene writes it) names, for a scene in `sceneFolder`.
std::filesystem::path resolveMeshFile(std::string_view file, const std::filesystem::path& sceneFolder);

// How a scene saved in `sceneFolder` writes the reference: its own text when that still names the
// same file, else the path relative to the new folder (generic '/' separators), else (no relative
// path exists, e.g. another drive) the absolute path.
std::string meshFileText(const MeshFileReference& reference, const std::filesystem::path& sceneFolder);

}  // namespace simcore
