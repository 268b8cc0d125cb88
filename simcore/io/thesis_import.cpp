// Import of the 2018 thesis app's scene files (see the brief, "Thesis scenes").
//
// Mapping, and the reasoning behind each choice:
//  - settings.gravity {x,y,z} -> gravity.
//  - settings.damping {linear, angular}: per-second velocity retention factors d (v <- v d^dt, as
//    in Millington's Cyclone, which the thesis follows), d in (0, 1]. Our damping is a decay rate
//    (v <- v exp(-rate dt)), so rate = -ln d.
//  - settings.collisionResolution.velMaxIterations -> solver.velocityIterations,
//    penMaxIterations -> solver.positionIterations. Its other keys (restitution threshold,
//    angular movement limit, persistence threshold, interpolation alpha) tune the thesis's own
//    solver and have no counterpart; they are accepted silently.
//  - settings.rigidBodies: defaultMass / defaultFrictionCoef / defaultRestitutionCoef apply to
//    objects that lack the key (without them our v1 defaults apply: density 1000, friction 0.5,
//    restitution 0). sleepMotionThreshold bounds Cyclone's "motion", a running average of
//    |v|^2 + |w|^2, so its square root is the speed below which a body sleeps; it becomes both
//    sleep.linearVelocity and sleep.angularVelocity.
//  - settings.timeScale: a playback speed of the thesis's editor, not physics; a value other than
//    1 is reported as ignored. settings.rendering, gjkepa, forceMultipliers: editor/tuning
//    options with no counterpart, accepted silently.
//  - objects[].type is a unit shape scaled by `scale` (default 1, 1, 1):
//      box, longbox, wall -> box with halfExtents = scale / 2 (the unit cube has side 1). A wall
//        is such a box made thin in one axis, e.g. scale (40, 40, 1); pitch 90 turns its thin z
//        axis onto world y, laying it down as a floor. Walls are always static (the thesis spawns
//        them with spawnWallStatic, which takes no mass); a mass on a wall is ignored with a warning.
//      sphere -> radius 0.5 scale.x (a non-uniform scale is reported: a sphere stays a sphere).
//      cylinder -> radius 0.5 scale.x, halfHeight 0.5 scale.y (unit cylinder: diameter 1, height 1).
//      capsule -> radius 0.5 scale.x, halfHeight 0.5 scale.y: the unit capsule is taken to have
//        radius 0.5 and a straight part of length 1 (total height 2, the usual unit capsule that
//        fills a 1 x 2 x 1 box); scaling y stretches the straight part, the caps stay round.
//      For cylinders and capsules a scale.z different from scale.x is reported and ignored.
//  - objects[].orientation {pitch, yaw, roll} in degrees: pitch about X, yaw about Y, roll about
//    Z, composed as q = yaw * pitch * roll (roll applied first, yaw last: the usual camera-style
//    order, in which yaw turns about the world vertical).
//  - objects[].mass: -1 means static; otherwise a positive mass in kg.
//  - Positions are the centres of the unit shapes, which is where our body origins are.

#include "simcore/io/json_reader.h"

#include <cmath>

namespace simcore::io_detail {

namespace {

struct ThesisDefaults {
    std::optional<float> mass;
    float friction = BodyCreationSettings{}.friction;
    float restitution = BodyCreationSettings{}.restitution;
};

constexpr Range kRetention{0.0, 1.0, true};           // per-second velocity retention factor
constexpr Range kTimeScale{0.0, 1e3, true};
constexpr Range kSleepThreshold{0.0, 1e6, false};     // squared speed: sqrt(1e6) is the v1 sleep speeds' maximum
constexpr Range kScale{2e-4, 2e5, false};             // unit shapes halved give limits::kSize
constexpr Range kAngleDegrees{-1e5, 1e5, false};

Quat eulerDegrees(double pitch, double yaw, double roll) {
    const double toRadians = 3.14159265358979323846 / 180.0;
    const glm::dquat qPitch = glm::angleAxis(pitch * toRadians, glm::dvec3(1.0, 0.0, 0.0));
    const glm::dquat qYaw = glm::angleAxis(yaw * toRadians, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dquat qRoll = glm::angleAxis(roll * toRadians, glm::dvec3(0.0, 0.0, 1.0));
    const glm::dquat q = glm::normalize(qYaw * qPitch * qRoll);
    return Quat(static_cast<float>(q.w), static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z));
}

void readSettings(Reader& r, const Json& s, WorldSettings& out, ThesisDefaults& defaults) {
    const std::string path = "/settings";
    if (!r.expectObject(s, path)) return;
    r.checkKeys(s, path,
                {"damping", "gravity", "timeScale", "collisionResolution", "rigidBodies", "rendering", "gjkepa",
                 "forceMultipliers"});

    if (const Json* damping = Reader::find(s, "damping")) {
        const std::string p = childPath(path, "damping");
        if (r.expectObject(*damping, p)) {
            r.checkKeys(*damping, p, {"linear", "angular"});
            float linear = 1.0f, angular = 1.0f;
            if (r.optionalFloat(*damping, p, "linear", kRetention, linear))
                out.damping.linear = static_cast<float>(0.0 - std::log(double(linear)));  // 0 - x: +0 for d = 1
            if (r.optionalFloat(*damping, p, "angular", kRetention, angular))
                out.damping.angular = static_cast<float>(0.0 - std::log(double(angular)));
            // -ln(1e-38) is about 87: always inside the v1 limit, so the result saves and reloads.
        }
    }
    if (const Json* gravity = Reader::find(s, "gravity"))
        if (const auto g = r.readXyz(*gravity, childPath(path, "gravity"), findSetting("gravity")->range)) out.gravity = *g;

    if (const Json* timeScale = Reader::find(s, "timeScale")) {
        const std::string p = childPath(path, "timeScale");
        if (const auto t = r.readFloat(*timeScale, p, kTimeScale); t && *t != 1.0f)
            r.warning(p, "timeScale " + formatNumber(*t) +
                             " is a playback speed of the thesis app's editor, not physics; it is ignored");
    }

    if (const Json* resolution = Reader::find(s, "collisionResolution")) {
        const std::string p = childPath(path, "collisionResolution");
        if (r.expectObject(*resolution, p)) {
            r.checkKeys(*resolution, p,
                        {"penMaxIterations", "velMaxIterations", "minVelocityForRestitution",
                         "angularMovementLimitFactor", "persistentContactDistanceThreshold", "coefInterpAlpha"});
            // The v1 ranges of what they become, so an imported scene saves and reloads.
            const NumberRange& velocity = findSetting("solver.velocityIterations")->range;
            const NumberRange& position = findSetting("solver.positionIterations")->range;
            r.optionalInt(*resolution, p, "velMaxIterations", static_cast<int>(velocity.min),
                          static_cast<int>(velocity.max), out.solver.velocityIterations);
            r.optionalInt(*resolution, p, "penMaxIterations", static_cast<int>(position.min),
                          static_cast<int>(position.max), out.solver.positionIterations);
        }
    }

    if (const Json* bodies = Reader::find(s, "rigidBodies")) {
        const std::string p = childPath(path, "rigidBodies");
        if (r.expectObject(*bodies, p)) {
            r.checkKeys(*bodies, p, {"defaultMass", "defaultRestitutionCoef", "defaultFrictionCoef", "sleepMotionThreshold"});
            if (const Json* mass = Reader::find(*bodies, "defaultMass"))
                defaults.mass = r.readFloat(*mass, childPath(p, "defaultMass"), limits::kMass);
            r.optionalFloat(*bodies, p, "defaultRestitutionCoef", limits::kRestitution, defaults.restitution);
            r.optionalFloat(*bodies, p, "defaultFrictionCoef", limits::kFriction, defaults.friction);
            float threshold = 0.0f;
            if (Reader::find(*bodies, "sleepMotionThreshold") &&
                r.optionalFloat(*bodies, p, "sleepMotionThreshold", kSleepThreshold, threshold)) {
                const float speed = std::sqrt(threshold);
                out.sleep.linearVelocity = speed;
                out.sleep.angularVelocity = speed;
            }
        }
    }
    // rendering, gjkepa, forceMultipliers: accepted as they are (see the top of the file).
}

std::optional<SceneBody> readObject(Reader& r, const Json& o, const std::string& path, std::size_t index,
                                    const ThesisDefaults& defaults) {
    if (!r.expectObject(o, path)) return std::nullopt;
    r.checkKeys(o, path,
                {"type", "name", "position", "scale", "orientation", "frictionCoef", "restitutionCoef", "mass"});
    const int errorsBefore = r.errorCount();

    const Json* typeValue = r.require(o, path, "type");
    std::optional<std::string> type = typeValue ? r.readString(*typeValue, childPath(path, "type")) : std::nullopt;
    if (type && *type != "wall" && *type != "box" && *type != "longbox" && *type != "sphere" && *type != "cylinder" &&
        *type != "capsule") {
        r.error(childPath(path, "type"),
                "unknown object type '" + *type + "' (expected wall, box, longbox, sphere, cylinder or capsule)");
        type.reset();
    }

    SceneBody out;
    BodyCreationSettings& b = out.body;
    b.name = (type ? *type : std::string("object")) + " " + std::to_string(index);
    if (const Json* name = Reader::find(o, "name"))
        if (auto text = r.readString(*name, childPath(path, "name"))) b.name = std::move(*text);

    if (const Json* position = Reader::find(o, "position"))
        if (const auto p = r.readXyz(*position, childPath(path, "position"), limits::kCoordinate)) b.position = *p;

    Vec3 scale{1.0f};
    if (const Json* s = Reader::find(o, "scale"))
        if (const auto v = r.readXyz(*s, childPath(path, "scale"), kScale)) scale = *v;

    if (const Json* orientation = Reader::find(o, "orientation")) {
        const std::string p = childPath(path, "orientation");
        if (r.expectObject(*orientation, p)) {
            r.checkKeys(*orientation, p, {"pitch", "yaw", "roll"});
            float pitch = 0.0f, yaw = 0.0f, roll = 0.0f;
            // Each read on its own line so that every bad angle is reported, not just the first.
            const bool pitchOk = r.optionalFloat(*orientation, p, "pitch", kAngleDegrees, pitch);
            const bool yawOk = r.optionalFloat(*orientation, p, "yaw", kAngleDegrees, yaw);
            const bool rollOk = r.optionalFloat(*orientation, p, "roll", kAngleDegrees, roll);
            if (pitchOk && yawOk && rollOk) b.orientation = eulerDegrees(pitch, yaw, roll);
        }
    }

    b.friction = defaults.friction;
    b.restitution = defaults.restitution;
    r.optionalFloat(o, path, "frictionCoef", limits::kFriction, b.friction);
    r.optionalFloat(o, path, "restitutionCoef", limits::kRestitution, b.restitution);

    const bool isWall = type && *type == "wall";
    b.motion = MotionType::Dynamic;
    b.mass = defaults.mass;
    if (const Json* mass = Reader::find(o, "mass")) {
        const std::string p = childPath(path, "mass");
        if (!mass->is_number()) {
            r.error(p, "expected a number, got " + typeName(*mass));
        } else if (mass->get<double>() == -1.0) {
            b.motion = MotionType::Static;
        } else if (isWall) {
            r.warning(p, "a wall is always static in the thesis app; its mass is ignored");
        } else if (mass->get<double>() < 0.0) {
            r.error(p, "mass must be positive, or -1 for a static object, got " + formatNumber(mass->get<double>()));
        } else if (const auto m = r.readFloat(*mass, p, limits::kMass)) {
            b.mass = *m;
        }
    }
    if (isWall) b.motion = MotionType::Static;

    if (type) {
        auto nonUniform = [&](bool differs, const std::string& what) {
            if (differs) r.warning(childPath(path, "scale"), what);
        };
        const float radius = 0.5f * scale.x;
        if (*type == "wall" || *type == "box" || *type == "longbox") {
            b.shape = Shape::box(0.5f * scale);
        } else if (*type == "sphere") {
            nonUniform(scale.y != scale.x || scale.z != scale.x,
                       "a sphere cannot be scaled non-uniformly; it is imported with radius 0.5 * scale.x = " +
                           formatNumber(radius));
            b.shape = Shape::sphere(radius);
        } else {
            nonUniform(scale.z != scale.x, "a " + *type + " is round about its y axis; scale.z is ignored and scale.x used");
            b.shape = *type == "capsule" ? Shape::capsule(radius, 0.5f * scale.y) : Shape::cylinder(radius, 0.5f * scale.y);
        }
    }

    if (r.errorCount() > errorsBefore) return std::nullopt;
    return out;
}

}  // namespace

std::optional<Scene> importThesisScene(const Json& root, Reader& r) {
    r.checkKeys(root, "", {"settings", "objects"});
    Scene scene;
    ThesisDefaults defaults;
    if (const Json* settings = Reader::find(root, "settings")) readSettings(r, *settings, scene.settings, defaults);

    const Json& objects = *Reader::find(root, "objects");
    if (r.expectArray(objects, "/objects")) {
        scene.bodies.reserve(objects.size());
        for (std::size_t i = 0; i < objects.size() && !r.full(); ++i)
            if (auto body = readObject(r, objects[i], childPath("/objects", i), i, defaults))
                scene.bodies.push_back(std::move(*body));
    }
    if (r.errorCount() > 0) return std::nullopt;
    return scene;
}

}  // namespace simcore::io_detail
