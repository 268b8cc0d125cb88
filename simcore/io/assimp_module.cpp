// libsimcore_assimp.so: assimp behind the C entry points of assimp_module.h, opened by
// simcore_import on its first import.

#include "simcore/io/assimp_module.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <type_traits>

struct SimcoreAssimpImport {
    Assimp::Importer importer;
    const aiScene* scene = nullptr;
};

namespace {

constexpr unsigned kPostProcess = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                  aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;

void configure(Assimp::Importer& importer) {
    // Points and lines are dropped by SortByPType instead of being kept as degenerate meshes.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Only the readers of the supported formats stay: when the named reader fails, assimp tries
    // every other one on the bytes, and forty parsers are forty times the surface a hostile file
    // can reach. Unregistered readers are the caller's to delete.
    for (std::size_t i = importer.GetImporterCount(); i-- > 0;) {
        const aiImporterDesc* description = importer.GetImporterInfo(i);
        const std::string extensions = description && description->mFileExtensions ? description->mFileExtensions : "";
        bool keep = false;
        std::size_t start = 0;
        while (start < extensions.size()) {
            const std::size_t end = std::min(extensions.find(' ', start), extensions.size());
            keep = keep || simcore::assimp_module::isSupportedFormat(std::string_view(extensions).substr(start, end - start));
            start = end + 1;
        }
        if (keep) continue;
        Assimp::BaseImporter* reader = importer.GetImporter(i);
        if (importer.UnregisterLoader(reader) == aiReturn_SUCCESS) delete reader;
    }
}

SimcoreAssimpImport* finish(SimcoreAssimpImport* import, const aiScene* scene) {
    import->scene = scene && !(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) ? scene : nullptr;
    return import;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) SimcoreAssimpImport* simcoreAssimpReadFile(const char* path) {
    auto* import = new SimcoreAssimpImport;
    configure(import->importer);
    return finish(import, import->importer.ReadFile(path, kPostProcess));
}

__attribute__((visibility("default"))) SimcoreAssimpImport* simcoreAssimpReadMemory(const void* data,
                                                                                   std::size_t size,
                                                                                   const char* format) {
    auto* import = new SimcoreAssimpImport;
    configure(import->importer);
    return finish(import, import->importer.ReadFileFromMemory(data, size, kPostProcess, format));
}

__attribute__((visibility("default"))) const aiScene* simcoreAssimpScene(const SimcoreAssimpImport* import) {
    return import->scene;
}

__attribute__((visibility("default"))) const char* simcoreAssimpError(const SimcoreAssimpImport* import) {
    return import->importer.GetErrorString();
}

__attribute__((visibility("default"))) void simcoreAssimpRelease(SimcoreAssimpImport* import) { delete import; }

}  // extern "C"

// The definitions above have the types simcore_import looks them up as.
static_assert(std::is_same_v<decltype(&simcoreAssimpReadFile), SimcoreAssimpReadFile>);
static_assert(std::is_same_v<decltype(&simcoreAssimpReadMemory), SimcoreAssimpReadMemory>);
static_assert(std::is_same_v<decltype(&simcoreAssimpScene), SimcoreAssimpScene>);
static_assert(std::is_same_v<decltype(&simcoreAssimpError), SimcoreAssimpError>);
static_assert(std::is_same_v<decltype(&simcoreAssimpRelease), SimcoreAssimpRelease>);
