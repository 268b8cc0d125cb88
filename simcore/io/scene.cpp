#include "simcore/io/scene.h"

#include <stdexcept>
#include <string>

namespace simcore {

std::optional<std::string> cameraBookmarkNameProblem(std::string_view name) {
    if (name.empty()) return "a bookmark needs a name";
    if (name.size() > kMaxCameraBookmarkName)
        return "a bookmark's name may have at most " + std::to_string(kMaxCameraBookmarkName) + " bytes, got " +
               std::to_string(name.size());
    return std::nullopt;
}

BuiltWorld buildWorld(const Scene& scene) {
    BuiltWorld built{World(scene.settings), {}, {}};
    built.bodyIds.reserve(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyCreationSettings& body = scene.bodies[i].body;
        try {
            built.bodyIds.push_back(built.world.createBody(body));
        } catch (const std::invalid_argument& e) {
            // Name the body: the world's message only names the field.
            throw std::invalid_argument("body " + std::to_string(i) + " ('" + body.name + "'): " + e.what());
        }
    }
    built.jointIds.reserve(scene.joints.size());
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        const SceneJoint& joint = scene.joints[i];
        JointCreationSettings settings = joint.joint;
        try {
            if (joint.bodyA >= built.bodyIds.size() || (joint.bodyB && *joint.bodyB >= built.bodyIds.size()))
                throw std::invalid_argument("a body index is out of range");
            settings.bodyA = built.bodyIds[joint.bodyA];
            settings.bodyB = joint.bodyB ? built.bodyIds[*joint.bodyB] : BodyId{};
            built.jointIds.push_back(built.world.createJoint(settings));
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("joint " + std::to_string(i) + " ('" + settings.name + "'): " + e.what());
        }
    }
    return built;
}

namespace {

SceneBody makeBody(std::string name, Shape shape, const Vec3& position, const Vec3& color,
                   const Quat& orientation = Quat(1.0f, 0.0f, 0.0f, 0.0f)) {
    SceneBody b;
    b.body.name = std::move(name);
    b.body.shape = std::move(shape);
    b.body.position = position;
    b.body.orientation = orientation;
    b.color = color;
    return b;
}

// A small irregular rock: few enough faces to read as a hull, irregular enough not to look like
// any primitive.
Shape rockShape() {
    const std::vector<Vec3> points{
        {-0.50f, -0.35f, -0.40f}, {0.55f, -0.30f, -0.35f}, {0.10f, -0.40f, 0.55f}, {-0.45f, -0.25f, 0.40f},
        {0.45f, -0.20f, 0.40f},   {0.00f, 0.45f, 0.05f},   {-0.30f, 0.30f, -0.20f}, {0.35f, 0.25f, -0.25f},
        {0.15f, 0.35f, 0.30f},    {-0.55f, 0.05f, 0.00f},  {0.60f, 0.00f, 0.05f},
    };
    ConvexHull::BuildResult built = ConvexHull::build(points);
    if (!built.hull) throw std::logic_error("default scene rock: " + built.error);
    return Shape::convexHull(std::move(built.hull));
}

}  // namespace

Scene defaultScene() {
    Scene scene;
    SceneBody ground = makeBody("ground", Shape::box(Vec3(20.0f, 0.5f, 20.0f)), Vec3(0.0f, -0.5f, 0.0f),
                                Vec3(0.55f, 0.57f, 0.60f));
    ground.body.motion = MotionType::Static;
    scene.bodies.push_back(std::move(ground));

    // One dynamic body of each shape, in a row a little above the ground, so each falls, lands and
    // settles in view of the default camera.
    const Vec3 axisY(0.0f, 1.0f, 0.0f), axisZ(0.0f, 0.0f, 1.0f);
    scene.bodies.push_back(makeBody("box", Shape::box(Vec3(0.5f)), Vec3(-4.0f, 1.5f, 0.0f), Vec3(0.91f, 0.45f, 0.32f),
                                    glm::angleAxis(0.35f, axisY)));
    scene.bodies.push_back(makeBody("sphere", Shape::sphere(0.5f), Vec3(-2.0f, 2.0f, 0.0f), Vec3(0.20f, 0.65f, 0.70f)));
    // Lying down: a capsule stood on end would only topple.
    scene.bodies.push_back(makeBody("capsule", Shape::capsule(0.3f, 0.4f), Vec3(0.0f, 1.5f, 0.0f),
                                    Vec3(0.95f, 0.75f, 0.25f), glm::angleAxis(0.5f * kPi, axisZ)));
    scene.bodies.push_back(makeBody("cylinder", Shape::cylinder(0.45f, 0.4f), Vec3(2.0f, 1.5f, 0.0f),
                                    Vec3(0.55f, 0.45f, 0.85f)));
    scene.bodies.push_back(makeBody("rock", rockShape(), Vec3(4.0f, 1.5f, 0.0f), Vec3(0.45f, 0.70f, 0.40f),
                                    glm::angleAxis(0.6f, axisY)));
    return scene;
}

}  // namespace simcore
