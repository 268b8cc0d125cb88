#pragma once
// A scene as authored: world settings, bodies (with editor-only extras such as colour) and joints.
// This is what files hold, what the editor edits, and what a World is built from.

#include "simcore/dynamics/body.h"
#include "simcore/dynamics/joint.h"
#include "simcore/io/mesh_file.h"
#include "simcore/world/world.h"
#include "simcore/world_settings.h"

#include <optional>
#include <string>
#include <string_view>
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

// A named view of the editor's orbit camera, kept with the scene so that a reopened file can be
// seen as its author looked at it. Nothing the engine simulates reads it.
struct CameraBookmark {
    std::string name;
    Vec3 target{0.0f};          // the point the camera orbits and looks at (m)
    float yawDegrees = 0.0f;    // about world Y; 0 looks along -Z
    float pitchDegrees = 0.0f;  // how far above the horizon the eye sits
    float distance = 10.0f;     // from the eye to the target (m)
    bool orthographic = false;

    bool operator==(const CameraBookmark&) const = default;
};

// A file holds at most this many bookmarks, each named with 1 to kMaxCameraBookmarkName bytes.
inline constexpr std::size_t kMaxCameraBookmarks = 100;
inline constexpr std::size_t kMaxCameraBookmarkName = 200;
// Why `name` cannot name a bookmark (empty, or too long), or nothing: the loader's and the
// editor's rule.
std::optional<std::string> cameraBookmarkNameProblem(std::string_view name);

// What the editor keeps in a scene file besides the scene (the file's optional "editor" object):
// loaded, kept and saved again by the engine, ignored by the runner.
struct EditorState {
    std::vector<CameraBookmark> cameraBookmarks;

    bool operator==(const EditorState&) const = default;
};

struct Scene {
    WorldSettings settings;
    std::vector<SceneBody> bodies;
    std::vector<SceneJoint> joints;
    EditorState editor;
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
