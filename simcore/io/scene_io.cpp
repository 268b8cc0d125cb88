// Scene files: loading, atomic saving, checkScene and the runner's --set assignment. Reading the
// text is scene_read.cpp, writing it scene_write.cpp.

#include "simcore/io/scene_io.h"

#include "simcore/io/json_reader.h"
#include "simcore/io/scene_v1.h"
#include "simcore/world/quality_preset.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <random>
#include <system_error>

namespace simcore {

using io_detail::childPath;
using io_detail::Json;
using io_detail::OrderedJson;
using io_detail::Reader;
using io_detail::readSettings;
using io_detail::settingsJson;

namespace {

std::string osError(int error) { return std::system_category().message(error); }

}  // namespace

std::string_view upAxisName(UpAxis axis) {
    switch (axis) {
        case UpAxis::Z: return "z";
        case UpAxis::X: return "x";
        case UpAxis::Y: break;
    }
    return "y";
}

std::optional<UpAxis> parseUpAxis(std::string_view name) {
    for (const UpAxis axis : {UpAxis::Y, UpAxis::Z, UpAxis::X})
        if (upAxisName(axis) == name) return axis;
    return std::nullopt;
}

std::filesystem::path resolveMeshFile(std::string_view file, const std::filesystem::path& sceneFolder) {
    namespace fs = std::filesystem;
    const fs::path written(file);
    std::error_code ec;
    const fs::path folder = fs::absolute(sceneFolder.empty() ? fs::path(".") : sceneFolder, ec);
    return (written.is_absolute() ? written : folder / written).lexically_normal();
}

std::string meshFileText(const MeshFileReference& reference, const std::filesystem::path& sceneFolder) {
    namespace fs = std::filesystem;
    if (sceneFolder.empty() || reference.resolvedPath.empty() ||
        resolveMeshFile(reference.file, sceneFolder) == reference.resolvedPath)
        return reference.file;
    std::error_code ec;
    const fs::path folder = fs::absolute(sceneFolder, ec).lexically_normal();
    const fs::path relative = reference.resolvedPath.lexically_relative(folder);
    return relative.empty() ? reference.resolvedPath.generic_string() : relative.generic_string();
}

std::string Diagnostic::toString() const {
    const char* kind = severity == Severity::Error ? "error" : "warning";
    const std::string name = file.empty() ? "<scene>" : file;
    if (line > 0)
        return name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + kind + ": " + message;
    if (!path.empty()) return name + ": " + kind + " at " + path + ": " + message;
    return name + ": " + kind + ": " + message;
}

SceneLoadResult loadSceneFile(const std::filesystem::path& path, const SceneReadOptions& options) {
    SceneLoadResult result;
    const std::string name = path.string();
    auto fail = [&](std::string message) {
        Diagnostic d;
        d.file = name;
        d.message = std::move(message);
        result.diagnostics.push_back(std::move(d));
        return result;
    };

    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail("cannot read the scene: it is a directory");
    std::FILE* f = std::fopen(name.c_str(), "rb");
    if (!f) return fail("cannot open the scene: " + osError(errno));
    std::string text;
    char buffer[65536];
    bool tooLarge = false;
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, f);
        text.append(buffer, n);
        if (text.size() > kMaxSceneFileBytes) {
            tooLarge = true;
            break;
        }
        if (n < sizeof buffer) break;
    }
    const bool readError = std::ferror(f) != 0;
    const int readErrno = errno;
    std::fclose(f);
    if (tooLarge) return fail("the file is larger than " + std::to_string(kMaxSceneFileBytes >> 20) + " MiB; it is not a scene");
    if (readError) return fail("cannot read the scene: " + osError(readErrno));
    SceneReadOptions withFolder = options;
    if (withFolder.sceneFolder.empty()) withFolder.sceneFolder = path.parent_path();
    return parseScene(text, name, withFolder);
}

std::optional<std::string> saveSceneFile(const Scene& scene, const std::filesystem::path& requestedPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string text = serializeScene(scene, fs::absolute(requestedPath, ec).parent_path());
    const std::string target = requestedPath.string();
    auto failure = [&](const std::string& why) { return "cannot save '" + target + "': " + why; };

    if (requestedPath.filename().empty()) return failure("the path names no file");
    if (fs::is_directory(requestedPath, ec)) return failure(osError(EISDIR));
    // Saving through a symbolic link replaces the file it points to, not the link.
    fs::path path = requestedPath;
    if (fs::is_symlink(requestedPath, ec)) {
        const fs::path resolved = fs::canonical(requestedPath, ec);
        if (!ec) path = resolved;
    }

    // The temporary lives beside the target so the final rename stays within one file system (and
    // is therefore atomic); its name is random so concurrent saves cannot collide.
    std::random_device random;
    const fs::path temp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(random()));
    std::FILE* f = std::fopen(temp.string().c_str(), "wbx");  // x: never reuse an existing file
    if (!f) return failure(osError(errno));

    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
    int error = ok ? 0 : errno;
    if (ok && ::fsync(fileno(f)) != 0) {
        ok = false;
        error = errno;
    }
    if (std::fclose(f) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (ok) {
        // Keep the permissions of the file being replaced.
        const fs::file_status old = fs::status(path, ec);
        if (!ec && fs::exists(old)) fs::permissions(temp, old.permissions(), ec);
        fs::rename(temp, path, ec);
        if (!ec) return std::nullopt;
        const std::string why = ec.message();
        fs::remove(temp, ec);
        return failure(why);
    }
    std::error_code ignored;
    fs::remove(temp, ignored);
    return failure(osError(error == 0 ? EIO : error));
}

std::vector<Diagnostic> checkScene(const Scene& scene) {
    // The one thing a file cannot say wrong (it names bodies), so the text below could not show it.
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const SceneJoint& joint = scene.joints[i];
        if (joint.bodyA < scene.bodies.size() && (!joint.bodyB || *joint.bodyB < scene.bodies.size())) continue;
        Diagnostic missing;
        missing.path = childPath("/joints", i);
        missing.message = "a body of the joint is missing";
        return {missing};
    }
    // The loader's own rules, by the loader: no second copy of them to drift apart. A file mesh is
    // the one the scene holds (already within the limits when it was read), not the file again.
    SceneReadOptions options;
    options.loadMeshFile = [&scene](const MeshFileRequest& request) {
        MeshFileData held;
        for (const SceneBody& body : scene.bodies) {
            // Matched on what the text says: it was serialised without a folder, so it resolves elsewhere.
            const std::optional<MeshFileReference>& reference = body.meshFile;
            if (!reference || reference->file != request.reference.file || reference->scale != request.reference.scale ||
                reference->upAxis != request.reference.upAxis || !body.body.shape.mesh)
                continue;
            held.vertices = body.body.shape.mesh->vertices();
            held.triangles = body.body.shape.mesh->triangleIndices();
            return held;
        }
        held.error = "the mesh of \"" + request.reference.file + "\" is not in the scene";
        return held;
    };
    return parseScene(serializeScene(scene), "", options).diagnostics;
}

std::vector<std::string> writtenSettingsKeys(const WorldSettings& settings) {
    std::vector<std::string> keys;
    const OrderedJson written = settingsJson(settings);
    for (const auto& [key, value] : written.items()) {
        if (!value.is_object()) keys.push_back(key);
        else
            for (const auto& [inner, unused] : value.items()) keys.push_back(key + "." + inner);
    }
    return keys;
}

std::optional<std::string> applySettingOverride(Scene& scene, std::string_view assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0)
        return "expected key=value (for example solver.velocityIterations=20), got '" + std::string(assignment) + "'";
    const std::string key(assignment.substr(0, eq));
    const std::string valueText(assignment.substr(eq + 1));
    if (key == "preset") {
        // Applied now, over the current values, like the key in a file; later overrides win.
        const Json quoted = Json::parse(valueText, nullptr, /*allow_exceptions=*/false);
        const std::string name = quoted.is_string() ? quoted.get<std::string>() : valueText;
        const std::optional<QualityPreset> preset = parseQualityPreset(name);
        if (!preset)
            return "invalid value for setting 'preset': unknown quality preset '" + name +
                   "' (expected fast, balanced or accurate)";
        applyQualityPreset(scene.settings, *preset);
        return std::nullopt;
    }

    // Work on the settings as they would be saved (every schema key, written by the schema's loop),
    // so exactly the schema's keys, their sections and vector components can be set, and the new
    // value goes through the validation a file would.
    Json settings = Json::parse(settingsJson(scene.settings).dump());
    Json* node = &settings;
    std::size_t start = 0;
    while (start <= key.size()) {
        const std::size_t dot = std::min(key.find('.', start), key.size());
        const std::string segment = key.substr(start, dot - start);
        if (node->is_object() && node->contains(segment)) {
            node = &(*node)[segment];
        } else if (node->is_array() && !segment.empty() && segment.size() < 4 &&
                   segment.find_first_not_of("0123456789") == std::string::npos &&
                   std::stoul(segment) < node->size()) {
            node = &(*node)[std::stoul(segment)];  // gravity.1=-1.62
        } else {
            return "unknown setting '" + key + "'";
        }
        start = dot + 1;
    }

    Json value = Json::parse(valueText, nullptr, /*allow_exceptions=*/false);
    if (value.is_discarded()) {
        // Not JSON: a bare word is taken as a string; something meant as a number gets a clear word.
        const bool looksNumeric = !valueText.empty() && std::string_view("0123456789+-.").find(valueText.front()) != std::string_view::npos;
        if (looksNumeric)
            return "invalid value for setting '" + key + "': '" + valueText + "' is not a valid finite number";
        value = valueText;
    }
    *node = std::move(value);

    std::vector<Diagnostic> diagnostics;
    Reader reader("--set", diagnostics);
    WorldSettings updated;
    readSettings(reader, settings, "", updated);
    reader.finish();
    if (!diagnostics.empty())
        return "invalid value for setting '" + key + "': " + diagnostics.front().message;
    scene.settings = updated;
    return std::nullopt;
}

}  // namespace simcore
