#pragma once
// Internal to simcore/io (not part of the public API): what reading v1 scenes (scene_read.cpp),
// writing them (scene_write.cpp) and the entry points of scene_io.cpp share.

#include "simcore/io/json_reader.h"
#include "simcore/io/scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <utility>

namespace simcore::io_detail {

inline constexpr const char* kFormatTag = "interplay.scene";
inline constexpr int kFormatVersion = 1;

// The first segment of a dotted settings key ("solver" of "solver.contactHertz"), and the rest.
inline std::pair<std::string_view, std::string_view> splitKey(std::string_view key) {
    const std::size_t dot = key.find('.');
    if (dot == std::string_view::npos) return {key, {}};
    return {key.substr(0, dot), key.substr(dot + 1)};
}

// The key of a motor's force limit: a hinge's motor limits torque.
inline const char* motorForceKey(JointType type) { return type == JointType::Hinge ? "maxTorque" : "maxForce"; }

// Reads the "settings" object `s` at `path` into `out`: the preset first, then the schema's keys
// over it. Reports every problem. (scene_read.cpp)
void readSettings(Reader& r, const Json& s, const std::string& path, WorldSettings& out);

using OrderedJson = nlohmann::ordered_json;

// The "settings" object a saved file holds: every schema key, and the preset when the settings
// match one. (scene_write.cpp)
OrderedJson settingsJson(const WorldSettings& s);

}  // namespace simcore::io_detail
