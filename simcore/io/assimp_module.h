#pragma once
// The seam between simcore_import and assimp. assimp is a 10 MB library whose loading alone adds
// about 6 MB to a process's resident memory, so it lives in a module of its own
// (libsimcore_assimp.so, assimp_module.cpp) that simcore_import opens with dlopen the first time a
// file is imported: a runner, editor or sweep that never reads a mesh file never maps it.
//
// The module's entry points are C functions, looked up by these names; both sides include this
// header, so a change to a signature breaks the build of both. An import is an opaque handle that
// owns assimp's importer and the scene it read; the scene is read in place (aiScene is a plain C
// struct) and the handle released when done.

#include <cstddef>
#include <string_view>

struct aiScene;

extern "C" {

struct SimcoreAssimpImport;

// Reads a file through assimp's file system (a .gltf finds the buffers beside it), or bytes in
// memory whose format is an extension without its dot. Never null; the scene may be.
using SimcoreAssimpReadFile = SimcoreAssimpImport* (*)(const char* path);
using SimcoreAssimpReadMemory = SimcoreAssimpImport* (*)(const void* data, std::size_t size, const char* format);
// The scene read, node transforms applied and polygons triangulated; null when assimp failed or
// the scene is incomplete.
using SimcoreAssimpScene = const aiScene* (*)(const SimcoreAssimpImport* import);
// assimp's reason for a failure ("" when it gave none).
using SimcoreAssimpError = const char* (*)(const SimcoreAssimpImport* import);
using SimcoreAssimpRelease = void (*)(SimcoreAssimpImport* import);

}  // extern "C"

namespace simcore::assimp_module {

inline constexpr const char* kReadFile = "simcoreAssimpReadFile";
inline constexpr const char* kReadMemory = "simcoreAssimpReadMemory";
inline constexpr const char* kScene = "simcoreAssimpScene";
inline constexpr const char* kError = "simcoreAssimpError";
inline constexpr const char* kRelease = "simcoreAssimpRelease";

// The formats read, as lowercase extensions without the dot: assimp keeps only their readers.
inline bool isSupportedFormat(std::string_view extension) {
    return extension == "obj" || extension == "stl" || extension == "gltf" || extension == "glb";
}

}  // namespace simcore::assimp_module
