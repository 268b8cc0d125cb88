#pragma once
// Scene files: the v1 format (load, save, validate) and import of the thesis app's format.
// Every problem found is a Diagnostic naming the file, the JSON path and the reason.

#include "simcore/io/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simcore {

struct Diagnostic {
    enum class Severity { Warning, Error };
    Severity severity = Severity::Error;
    std::string file;     // as given by the caller
    std::string path;     // JSON pointer, e.g. "/bodies/3/shape/radius"; empty for the whole file
    int line = 0;         // 1-based, for syntax errors; 0 when unknown
    int column = 0;       // 1-based, for syntax errors
    std::string message;  // plain sentence: what is wrong

    // "file:line:column: error: message" or "file: error at /path: message".
    std::string toString() const;
};

struct SceneLoadResult {
    std::optional<Scene> scene;            // set when there is no error
    std::vector<Diagnostic> diagnostics;   // errors and warnings, in document order
    bool ok() const { return scene.has_value(); }
};

enum class SceneFormat { V1, Thesis };

// Scene text longer than this is refused (far beyond any real scene; it bounds memory).
inline constexpr std::uintmax_t kMaxSceneFileBytes = 64u * 1024u * 1024u;

// What reading a scene needs beyond its text: where relative mesh files are, and how to read them
// (mesh_file.h; simcore_import's importMeshFile). Without a loader a file mesh is an error saying
// so; every other scene loads the same.
struct SceneReadOptions {
    std::filesystem::path sceneFolder;  // relative "file" paths start here; empty: the working directory
    MeshFileLoader loadMeshFile;        // unset: file meshes cannot be read
};

// Parses scene text; the format is detected ("format": "interplay.scene" is v1, an "objects" array
// is the thesis format). `fileName` is used in diagnostics only.
SceneLoadResult parseScene(std::string_view text, std::string_view fileName, const SceneReadOptions& options = {});
// The same from a file; an empty options.sceneFolder becomes the file's own folder.
SceneLoadResult loadSceneFile(const std::filesystem::path& path, const SceneReadOptions& options = {});

// v1 JSON text. Every number is written so that parsing it gives back the identical float. Mesh
// file references are written as references (meshFileText): relative to `sceneFolder` when it is
// given, else as they were read.
std::string serializeScene(const Scene& scene, const std::filesystem::path& sceneFolder = {});

// Writes atomically: to a temporary file beside the target, then renamed over it, so a failure
// never leaves a half-written file; mesh file references are rewritten relative to the target's
// folder. Returns an error message, or nothing on success.
std::optional<std::string> saveSceneFile(const Scene& scene, const std::filesystem::path& path);

// What the loader would report about `scene` if it were saved and opened again: every edit the
// editor makes is checked with this, so it never holds a scene it could not reopen. Diagnostics
// carry the JSON path of the value (as in the file the scene would save to) and no file name.
// Meshes read from files are checked as they are in the scene, without reading the files again.
std::vector<Diagnostic> checkScene(const Scene& scene);

// The keys of the "settings" object a saved file would hold for `settings`, dotted as in
// settingsSchema() ("solver.contactHertz"), plus "preset" when the settings match one.
std::vector<std::string> writtenSettingsKeys(const WorldSettings& settings);

// Sets one settings value from text, as the runner's `--set key.path=value` does, e.g.
// "solver.velocityIterations=20", "gravity=[0,-1.62,0]", "effects.friction=false". The value is
// JSON (bare words that are not JSON are taken as strings). Returns an error naming the key.
std::optional<std::string> applySettingOverride(Scene& scene, std::string_view assignment);

}  // namespace simcore
