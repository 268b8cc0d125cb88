#include "simcore/io/mesh_import.h"

#include "simcore/settings_schema.h"
#include "simcore/shapes/convex_hull.h"

#include "simcore/io/assimp_module.h"

#include <assimp/scene.h>  // the scene's structs only: assimp's code is in the module

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>

namespace simcore {

namespace {

constexpr std::string_view kSupportedFormats = "obj, stl, gltf or glb";

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

using assimp_module::isSupportedFormat;

// The module's entry points (assimp_module.h), looked up once, on the first import. Opening it
// maps assimp; SIMCORE_ASSIMP_MODULE is its path in the build tree (CMakeLists.txt).
struct AssimpModule {
    SimcoreAssimpReadFile readFile = nullptr;
    SimcoreAssimpReadMemory readMemory = nullptr;
    SimcoreAssimpScene scene = nullptr;
    SimcoreAssimpError error = nullptr;
    SimcoreAssimpRelease release = nullptr;
    std::string openError;  // why the module could not be used; empty when it can
};

const AssimpModule& assimpModule() {
    static const AssimpModule module = [] {
        AssimpModule m;
        void* library = dlopen(SIMCORE_ASSIMP_MODULE, RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            m.openError = dlerror();
            return m;
        }
        const auto lookUp = [&](auto& entry, const char* name) {
            entry = reinterpret_cast<std::remove_reference_t<decltype(entry)>>(dlsym(library, name));
            if (!entry && m.openError.empty()) m.openError = std::string(SIMCORE_ASSIMP_MODULE) + " has no " + name;
        };
        lookUp(m.readFile, assimp_module::kReadFile);
        lookUp(m.readMemory, assimp_module::kReadMemory);
        lookUp(m.scene, assimp_module::kScene);
        lookUp(m.error, assimp_module::kError);
        lookUp(m.release, assimp_module::kRelease);
        return m;
    }();
    return module;
}

// The file's up axis turned to +y: a rotation, so handedness and windings are kept.
Vec3 toYUp(const aiVector3D& v, UpAxis up) {
    switch (up) {
        case UpAxis::Z: return {v.x, v.z, -v.y};
        case UpAxis::X: return {-v.y, v.x, v.z};
        case UpAxis::Y: break;
    }
    return {v.x, v.y, v.z};
}

std::string checkOptions(const MeshImportOptions& options) {
    for (int k = 0; k < 3; ++k)
        if (!isFinite(options.scale[k]) || options.scale[k] == 0.0f)
            return "the scale must be finite and non-zero on every axis";
    return {};
}

// Copies the triangles of every mesh in the scene (node transforms already applied).
ImportedMesh collect(const aiScene& scene, std::string_view name, const MeshImportOptions& options) {
    ImportedMesh out;
    const std::string prefix = std::string(name) + ": ";
    std::size_t faces = 0, vertices = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        faces += scene.mMeshes[m]->mNumFaces;
        vertices += scene.mMeshes[m]->mNumVertices;
    }
    if (faces > options.maxTriangles) {
        out.error = prefix + "has " + std::to_string(faces) + " triangles; at most " +
                    std::to_string(options.maxTriangles) + " are allowed";
        return out;
    }
    if (vertices > kMaxMeshVertices) {
        out.error = prefix + "has " + std::to_string(vertices) + " vertices; at most " +
                    std::to_string(kMaxMeshVertices) + " are allowed";
        return out;
    }
    const bool mirrored = ((options.scale.x < 0.0f) != (options.scale.y < 0.0f)) != (options.scale.z < 0.0f);
    out.vertices.reserve(vertices);
    out.triangles.reserve(faces);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        const std::uint32_t base = std::uint32_t(out.vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const Vec3 p = toYUp(mesh.mVertices[v], options.upAxis) * options.scale;
            if (!isFinite(p) || glm::any(glm::greaterThan(glm::abs(p), Vec3(kMaxMeshCoordinate)))) {
                out.error = prefix + "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                            " is not finite or beyond " + std::to_string(int(kMaxMeshCoordinate)) + " m once scaled";
                return out;
            }
            out.vertices.push_back(p);
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines: not part of a surface
            TriangleMesh::Indices t{};
            bool inRange = true;
            for (int k = 0; k < 3; ++k) {
                inRange = inRange && face.mIndices[k] < mesh.mNumVertices;
                t[k] = base + (inRange ? face.mIndices[k] : 0u);
            }
            if (!inRange) {
                out.error = prefix + "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                            " uses a vertex the mesh does not have";
                return out;
            }
            if (mirrored) std::swap(t[1], t[2]);
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
                isDegenerateTriangle(out.vertices[t[0]], out.vertices[t[1]], out.vertices[t[2]])) {
                ++out.droppedTriangles;
                continue;
            }
            out.triangles.push_back(t);
        }
    }
    if (out.triangles.empty())
        out.error = prefix + (out.droppedTriangles > 0 ? "has only degenerate triangles" : "contains no triangles");
    return out;
}

// Reads through the module and collects the triangles; `read` starts the import.
template <typename Read>
ImportedMesh readThroughAssimp(std::string_view name, const std::string& format, const MeshImportOptions& options,
                               Read read) {
    const AssimpModule& assimp = assimpModule();
    if (!assimp.openError.empty()) {
        ImportedMesh out;
        out.error = std::string(name) + ": cannot be read: the mesh importer is missing (" + assimp.openError + ")";
        return out;
    }
    const std::unique_ptr<SimcoreAssimpImport, SimcoreAssimpRelease> import(read(assimp), assimp.release);
    const aiScene* scene = assimp.scene(import.get());
    if (!scene) {
        ImportedMesh out;
        const std::string why = assimp.error(import.get());
        out.error = std::string(name) + ": cannot be read as " + format + (why.empty() ? "" : " (" + why + ")");
        return out;
    }
    return collect(*scene, name, options);
}

// A binary glTF states its own length and each chunk's: assimp 5.2 believes them and allocates
// what they say (a 100-byte file whose JSON chunk claimed 4 GB ran the fuzzer out of memory), so
// they are checked against the bytes there are first. Empty when the data is no binary glTF or
// its lengths fit; else what is wrong.
std::string binaryGltfProblem(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    if (size < 4 || std::memcmp(bytes, "glTF", 4) != 0) return {};
    const auto word = [bytes](std::size_t at) {  // little-endian, as the format stores it
        return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 | std::uint32_t(bytes[at + 2]) << 16 |
               std::uint32_t(bytes[at + 3]) << 24;
    };
    const std::size_t headerBytes = size >= 8 && word(4) == 1 ? 20 : 12;  // glTF 1.0's header is longer
    if (size < headerBytes)
        return "is a binary glTF cut off in its " + std::to_string(headerBytes) + "-byte header";
    const std::uint32_t length = word(8);
    if (length > size || length < headerBytes)
        return "is a binary glTF whose header says " + std::to_string(length) + " bytes, but it has " +
               std::to_string(size);
    if (headerBytes == 20) {
        const std::uint32_t content = word(12);
        if (content > length - headerBytes)
            return "is a binary glTF whose scene is said to be " + std::to_string(content) + " bytes, but " +
                   std::to_string(length - headerBytes) + " follow the header";
        return {};
    }
    for (std::size_t at = headerBytes; at < length;) {
        if (length - at < 8) return "is a binary glTF with a chunk header cut off at byte " + std::to_string(at);
        const std::uint32_t chunk = word(at);
        if (chunk > length - at - 8)
            return "is a binary glTF whose chunk at byte " + std::to_string(at) + " says " + std::to_string(chunk) +
                   " bytes, but " + std::to_string(length - at - 8) + " follow";
        at += 8 + std::size_t(chunk);
    }
    return {};
}

}  // namespace

ImportedMesh importMeshFromMemory(const void* data, std::size_t size, std::string_view format, std::string_view name,
                                  const MeshImportOptions& options) {
    ImportedMesh out;
    const std::string prefix = std::string(name) + ": ";
    const std::string fmt = lowercase(format);
    if (!isSupportedFormat(fmt)) {
        out.error = prefix + "unsupported format \"" + fmt + "\" (use " + std::string(kSupportedFormats) + ")";
        return out;
    }
    if (std::string problem = checkOptions(options); !problem.empty()) {
        out.error = prefix + problem;
        return out;
    }
    if (size == 0) {
        out.error = prefix + "is empty";
        return out;
    }
    if (size > options.maxFileBytes) {
        out.error = prefix + "is " + std::to_string(size) + " bytes; at most " + std::to_string(options.maxFileBytes) +
                    " are read";
        return out;
    }
    if (std::string problem = binaryGltfProblem(data, size); !problem.empty()) {
        out.error = prefix + problem;
        return out;
    }
    return readThroughAssimp(name, fmt, options, [&](const AssimpModule& assimp) {
        return assimp.readMemory(data, size, fmt.c_str());
    });
}

ImportedMesh importMesh(const std::filesystem::path& file, const MeshImportOptions& options) {
    ImportedMesh out;
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        out.error = name + ": no such file";
        return out;
    }
    if (!std::filesystem::is_regular_file(file, ec)) {
        out.error = name + ": not a regular file";
        return out;
    }
    const std::string format = lowercase(file.extension().string().substr(file.extension().empty() ? 0 : 1));
    if (!isSupportedFormat(format)) {
        out.error = name + ": unsupported format \"" + file.extension().string() + "\" (use " +
                    std::string(kSupportedFormats) + ")";
        return out;
    }
    if (std::string problem = checkOptions(options); !problem.empty()) {
        out.error = name + ": " + problem;
        return out;
    }
    const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
    if (ec) {
        out.error = name + ": cannot be read (" + ec.message() + ")";
        return out;
    }
    if (bytes == 0) {
        out.error = name + ": is empty";
        return out;
    }
    if (bytes > options.maxFileBytes) {
        out.error = name + ": is " + std::to_string(bytes) + " bytes; at most " + std::to_string(options.maxFileBytes) +
                    " are read";
        return out;
    }
    if (std::ifstream in(file, std::ios::binary); in) {  // a GLB's lengths, checked as in memory
        char magic[4] = {};
        if (in.read(magic, 4) && std::memcmp(magic, "glTF", 4) == 0) {
            std::string whole(static_cast<std::size_t>(bytes), '\0');
            in.seekg(0);
            in.read(whole.data(), static_cast<std::streamsize>(whole.size()));
            if (std::string problem = binaryGltfProblem(whole.data(), static_cast<std::size_t>(in.gcount()));
                !problem.empty()) {
                out.error = name + ": " + problem;
                return out;
            }
        }
    }
    // Through assimp's file system, so a .gltf can name buffers beside it.
    return readThroughAssimp(name, format, options,
                             [&](const AssimpModule& assimp) { return assimp.readFile(name.c_str()); });
}

TriangleMesh::BuildResult importTriangleMesh(const std::filesystem::path& file, const MeshImportOptions& options) {
    ImportedMesh imported = importMesh(file, options);
    if (!imported.ok()) return {nullptr, imported.error};
    TriangleMesh::BuildResult built = TriangleMesh::build(std::move(imported.vertices), std::move(imported.triangles));
    if (!built.mesh) built.error = file.string() + ": " + built.error;
    return built;
}

MeshFileData importMeshFile(const MeshFileRequest& request) {
    const MeshFileReference& reference = request.reference;
    MeshImportOptions options;
    options.scale = reference.scale;
    options.upAxis = reference.upAxis;
    ImportedMesh imported = importMesh(reference.resolvedPath, options);
    MeshFileData out;
    if (!imported.ok()) {
        // importMesh's messages start with the resolved path; say what the scene wrote as well.
        out.error = "cannot read the mesh file \"" + reference.file + "\": " + imported.error;
        return out;
    }
    out.vertices = std::move(imported.vertices);
    out.triangles = std::move(imported.triangles);
    return out;
}

HullPoints hullPoints(const ImportedMesh& mesh) {
    const auto built = ConvexHull::build(mesh.vertices);
    if (!built.hull) return {{}, "no convex hull: " + built.error};
    if (built.hull->vertices().size() > limits::kMaxHullPoints)
        return {{}, "the convex hull has " + std::to_string(built.hull->vertices().size()) + " corners; at most " +
                        std::to_string(limits::kMaxHullPoints) + " are allowed"};
    return {built.hull->vertices(), {}};
}

}  // namespace simcore
