#pragma once
// A scene as authored: world settings, bodies (with editor-only extras such as colour) and joints.
// This is what files hold, what the editor edits, and what a World is built from.

#include "simcore/dynamics/body.h"
#include "simcore/world/world.h"
#include "simcore/world/world_settings.h"

#include <optional>
#include <vector>

namespace simcore {

struct SceneBody {
    BodyCreationSettings body;
    std::optional<Vec3> color;  // linear RGB in [0, 1]; the viewer picks one when unset
};

struct Scene {
    WorldSettings settings;
    std::vector<SceneBody> bodies;
};

// Creates every body of the scene in a new world (ids in scene order).
struct BuiltWorld {
    World world;
    std::vector<BodyId> bodyIds;  // bodyIds[i] is scene.bodies[i]
};
BuiltWorld buildWorld(const Scene& scene);

// The built-in scene the editor opens with no file: a ground, and one body of every shape type.
Scene defaultScene();

}  // namespace simcore
