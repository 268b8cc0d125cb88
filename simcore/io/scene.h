#pragma once
// A scene as authored: world settings, bodies (with editor-only extras such as colour) and joints.
// This is what files hold, what the editor edits, and what a World is built from.

#include "simcore/dynamics/body.h"
#include "simcore/dynamics/joint.h"
#include "simcore/io/mesh_file.h"
#include "simcore/world/world.h"
#include "simcore/world_settings.h"

#include <optional>
#include <vector>

namespace simcore {

struct SceneBody {
    BodyCreationSettings body;
    std::optional<Vec3> color;  // linear RGB in [0, 1]; the viewer picks one when unset
    // Set when the body's mesh shape was read from a file: saving writes the reference, not the
    // triangles. Ignored unless the shape is a mesh.
    std::optional<MeshFileReference> meshFile;
};

// A joint refers to its bodies by index into Scene::bodies (files name them).
struct SceneJoint {
    JointCreationSettings joint;       // its bodyA and bodyB are set when the world is built
    std::size_t bodyA = 0;
    std::optional<std::size_t> bodyB;  // unset: the joint holds bodyA to the world
};

struct Scene {
    WorldSettings settings;
    std::vector<SceneBody> bodies;
    std::vector<SceneJoint> joints;
};

// Creates every body, then every joint, of the scene in a new world (ids in scene order).
struct BuiltWorld {
    World world;
    std::vector<BodyId> bodyIds;    // bodyIds[i] is scene.bodies[i]
    std::vector<JointId> jointIds;  // jointIds[i] is scene.joints[i]
};
BuiltWorld buildWorld(const Scene& scene);

// The built-in scene the editor opens with no file: a ground, and one body of every shape type.
Scene defaultScene();

}  // namespace simcore
