// Scene files, format v1: strict loading with a diagnostic per problem, exact saving, atomic writes.
//
// What a file may hold - every settings key and body, shape and joint property with its accepted
// range - is simcore/settings_schema.h; the settings are read and written by loops over its table.
// The rules beyond single values (each violation is an error at the value's JSON pointer; all are
// collected, up to io_detail::kMaxDiagnostics):
//  - required: "format" ("interplay.scene"), "version" (1; newer versions are refused), "bodies",
//    each body's "shape", its "type" and the dimensions that type needs. Mass and density are
//    exclusive; rollingResistance is written only when set.
//  - orientation [w, x, y, z]: finite and not (near) zero length; a quaternion more than 1e-3
//    from unit length is normalised with a warning (smaller deviations silently).
//  - convex hulls: ConvexHull::build must succeed.
//  - what a dynamic body's values come to together (both formats): the mass a density gives
//    (density x volume) within the mass range; the smallest principal moment of inertia at least
//    1e-30 kg m^2 (its inverse must stay inside float range).
//  - size (json_reader.h, checked while parsing, so memory stays bounded).
//  - unknown keys are warnings: the scene loads, the key is reported and dropped.
//  - static and kinematic bodies may carry mass or density: the value is validated and kept (so
//    switching such a body to dynamic in the editor, or saving it, does not lose it), but the
//    world ignores it. No warning, since nothing is lost.
//  - a body without a name is called "body <index>".
//  - joints: "type", "bodyA" (a body's name) and "anchor" are required; "bodyB" is a body's name,
//    or null / absent for the world, and not bodyA; a name a joint uses must belong to exactly one
//    body. Hinges and sliders require a non-zero "axis"; limits need lower <= upper; distance
//    joints require "anchorB" at least 0.1 mm from anchor, and min <= max length once defaulted
//    (see joint.h). Keys a joint type does not take are warnings, like unknown keys.
//  - settings.preset: "fast", "balanced" or "accurate" (quality_preset.h), applied before every other
//    settings key, which then override it. Saving writes it when the settings match a preset.

#include "simcore/io/scene_io.h"

#include "simcore/io/json_reader.h"
#include "simcore/world/quality_preset.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <cstring>
#include <random>
#include <system_error>

namespace simcore {

using io_detail::childPath;
using io_detail::Json;
using io_detail::Reader;

namespace {

constexpr const char* kFormatTag = "interplay.scene";
constexpr int kFormatVersion = 1;

// ---- reading ----

// The first segment of a dotted settings key ("solver" of "solver.contactHertz"), and the rest.
std::pair<std::string_view, std::string_view> splitKey(std::string_view key) {
    const std::size_t dot = key.find('.');
    if (dot == std::string_view::npos) return {key, {}};
    return {key.substr(0, dot), key.substr(dot + 1)};
}

// The keys one object of the "settings" object takes: the top-level object's ("" section: preset,
// gravity, ..., solver, ...) or a section's ("solver": velocityIterations, ...).
std::vector<std::string_view> settingsKeysOf(std::string_view section) {
    std::vector<std::string_view> keys;
    if (section.empty()) keys.push_back("preset");
    for (const SettingInfo& info : settingsSchema()) {
        const auto [first, rest] = splitKey(info.key);
        const std::string_view key = section.empty() ? first : (first == section && !rest.empty() ? rest : "");
        if (!key.empty() && std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
    return keys;
}

// Reads one setting's value at `path` into `out`; reports what is wrong with it.
void readSetting(Reader& r, const SettingInfo& info, const Json& value, const std::string& path, WorldSettings& out) {
    switch (info.type) {
        case SettingType::Bool:
            if (const auto v = r.readBool(value, path)) info.set(out, *v);
            break;
        case SettingType::Int:
            if (const auto v = r.readInt(value, path, static_cast<int>(info.range.min), static_cast<int>(info.range.max)))
                info.set(out, *v);
            break;
        case SettingType::Float:
            if (const auto v = r.readFloat(value, path, info.range)) info.set(out, *v);
            break;
        case SettingType::Vec3:
            if (const auto v = r.readVec3(value, path, info.range)) info.set(out, *v);
            break;
        case SettingType::Choice:
            if (const auto text = r.readString(value, path)) {
                const auto known = std::find(info.choices.begin(), info.choices.end(), *text);
                if (known != info.choices.end()) {
                    info.set(out, static_cast<int>(known - info.choices.begin()));
                } else {
                    std::string what(info.label);  // "unknown position correction 'x'"
                    what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
                    r.error(path, "unknown " + what + " '" + *text + "' (expected " + info.choiceList() + ")");
                }
            }
            break;
    }
}

void readSettings(Reader& r, const Json& s, const std::string& path, WorldSettings& out) {
    if (!r.expectObject(s, path)) return;
    r.checkKeys(s, path, settingsKeysOf(""));
    // The preset first, so that the explicit keys read below override its values.
    if (const Json* preset = Reader::find(s, "preset")) {
        const std::string p = childPath(path, "preset");
        if (const auto name = r.readString(*preset, p)) {
            if (const auto parsed = parseQualityPreset(*name))
                applyQualityPreset(out, *parsed);
            else
                r.error(p, "unknown quality preset '" + *name + "' (expected fast, balanced or accurate)");
        }
    }
    // In schema order; a section ("solver") is checked once, when its first key comes up.
    std::string_view section;
    const Json* sectionObject = nullptr;
    for (const SettingInfo& info : settingsSchema()) {
        const auto [first, rest] = splitKey(info.key);
        if (rest.empty()) {
            if (const Json* value = Reader::find(s, first)) readSetting(r, info, *value, childPath(path, first), out);
            continue;
        }
        const std::string sectionPath = childPath(path, first);
        if (first != section) {
            section = first;
            sectionObject = Reader::find(s, first);
            if (sectionObject && !r.expectObject(*sectionObject, sectionPath)) sectionObject = nullptr;
            if (sectionObject) r.checkKeys(*sectionObject, sectionPath, settingsKeysOf(first));
        }
        if (!sectionObject) continue;
        if (const Json* value = Reader::find(*sectionObject, rest))
            readSetting(r, info, *value, childPath(sectionPath, rest), out);
    }
}

std::optional<Shape> readShape(Reader& r, const Json& j, const std::string& path) {
    if (!r.expectObject(j, path)) return std::nullopt;
    const Json* typeValue = r.require(j, path, "type");
    if (!typeValue) return std::nullopt;
    const auto type = r.readString(*typeValue, childPath(path, "type"));
    if (!type) return std::nullopt;

    auto size = [&](std::string_view key) -> std::optional<float> {
        const Json* v = r.require(j, path, key);
        return v ? r.readFloat(*v, childPath(path, key), limits::kSize) : std::nullopt;
    };

    if (*type == "box") {
        r.checkKeys(j, path, propertyKeys(PropertyOwner::Box), "for a box shape");
        const Json* v = r.require(j, path, "halfExtents");
        const auto halfExtents = v ? r.readVec3(*v, childPath(path, "halfExtents"), limits::kSize) : std::nullopt;
        if (halfExtents) return Shape::box(*halfExtents);
    } else if (*type == "sphere") {
        r.checkKeys(j, path, propertyKeys(PropertyOwner::Sphere), "for a sphere shape");
        if (const auto radius = size("radius")) return Shape::sphere(*radius);
    } else if (*type == "capsule" || *type == "cylinder") {
        const bool capsule = *type == "capsule";
        r.checkKeys(j, path, propertyKeys(capsule ? PropertyOwner::Capsule : PropertyOwner::Cylinder),
                    capsule ? "for a capsule shape" : "for a cylinder shape");
        const auto radius = size("radius");
        const auto halfHeight = size("halfHeight");
        if (radius && halfHeight)
            return capsule ? Shape::capsule(*radius, *halfHeight) : Shape::cylinder(*radius, *halfHeight);
    } else if (*type == "convexHull") {
        r.checkKeys(j, path, propertyKeys(PropertyOwner::ConvexHull), "for a convexHull shape");
        const Json* points = r.require(j, path, "points");
        const std::string p = childPath(path, "points");
        if (!points || !r.expectArray(*points, p)) return std::nullopt;
        if (points->size() > limits::kMaxHullPoints) {
            r.error(p, "a convex hull may have at most " + std::to_string(limits::kMaxHullPoints) + " points, got " +
                           std::to_string(points->size()));
            return std::nullopt;
        }
        std::vector<Vec3> cloud;
        bool ok = true;
        for (std::size_t i = 0; i < points->size() && !r.full(); ++i) {
            if (const auto point = r.readVec3((*points)[i], childPath(p, i), limits::kCoordinate))
                cloud.push_back(*point);
            else
                ok = false;
        }
        if (ok) return io_detail::hullShape(r, cloud, p);
    } else {
        r.error(childPath(path, "type"),
                "unknown shape type '" + *type + "' (expected box, sphere, capsule, cylinder or convexHull)");
    }
    return std::nullopt;
}

std::optional<Quat> readOrientation(Reader& r, const Json& v, const std::string& path) {
    if (!v.is_array()) {
        r.error(path, "expected an array of 4 numbers [w, x, y, z], got " + io_detail::typeName(v));
        return std::nullopt;
    }
    if (v.size() != 4) {
        r.error(path, "expected 4 numbers [w, x, y, z], got " + std::to_string(v.size()));
        return std::nullopt;
    }
    float c[4] = {};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto f = r.readFloat(v[i], childPath(path, i), limits::kQuaternionComponent);
        if (!f) return std::nullopt;
        c[i] = *f;
    }
    return io_detail::normalisedOrientation(r, Quat(c[0], c[1], c[2], c[3]), path);
}

std::optional<SceneBody> readBody(Reader& r, const Json& b, const std::string& path, std::size_t index) {
    if (!r.expectObject(b, path)) return std::nullopt;
    r.checkKeys(b, path, propertyKeys(PropertyOwner::Body));
    const int errorsBefore = r.errorCount();
    SceneBody out;
    BodyCreationSettings& s = out.body;

    s.name = "body " + std::to_string(index);
    if (const Json* name = Reader::find(b, "name"))
        if (auto text = r.readString(*name, childPath(path, "name"))) s.name = std::move(*text);

    if (const Json* motion = Reader::find(b, "motion")) {
        const std::string p = childPath(path, "motion");
        if (const auto text = r.readString(*motion, p)) {
            if (*text == "static") s.motion = MotionType::Static;
            else if (*text == "dynamic") s.motion = MotionType::Dynamic;
            else if (*text == "kinematic") s.motion = MotionType::Kinematic;
            else r.error(p, "unknown motion '" + *text + "' (expected static, dynamic or kinematic)");
        }
    }

    if (const Json* shape = r.require(b, path, "shape"))
        if (auto parsed = readShape(r, *shape, childPath(path, "shape"))) s.shape = std::move(*parsed);

    r.optionalVec3(b, path, "position", limits::kCoordinate, s.position);
    if (const Json* orientation = Reader::find(b, "orientation"))
        if (const auto q = readOrientation(r, *orientation, childPath(path, "orientation"))) s.orientation = *q;
    r.optionalVec3(b, path, "linearVelocity", limits::kLinearSpeed, s.linearVelocity);
    r.optionalVec3(b, path, "angularVelocity", limits::kAngularSpeed, s.angularVelocity);

    const Json* mass = Reader::find(b, "mass");
    const Json* density = Reader::find(b, "density");
    if (mass && density) {
        r.error(childPath(path, "density"), "give either mass or density, not both");
    } else if (mass) {
        if (const auto m = r.readFloat(*mass, childPath(path, "mass"), limits::kMass)) s.mass = *m;
    } else if (density) {
        if (const auto d = r.readFloat(*density, childPath(path, "density"), limits::kDensity)) s.density = *d;
    }

    r.optionalFloat(b, path, "friction", limits::kFriction, s.friction);
    r.optionalFloat(b, path, "restitution", limits::kRestitution, s.restitution);
    r.optionalFloat(b, path, "rollingResistance", limits::kRollingResistance, s.rollingResistance);
    r.optionalBool(b, path, "ccd", s.ccd);
    if (const Json* color = Reader::find(b, "color"))
        if (const auto c = r.readVec3(*color, childPath(path, "color"), limits::kColor)) out.color = *c;

    if (r.errorCount() > errorsBefore) return std::nullopt;
    return out;
}

// Reads a required number into `target`; false (and reported) when missing or invalid.
bool requiredFloat(Reader& r, const Json& object, const std::string& path, std::string_view key,
                   const io_detail::Range& range, float& target) {
    const Json* value = r.require(object, path, key);
    return value && r.optionalFloat(object, path, key, range, target);
}

const char* motorForceKey(JointType type) { return type == JointType::Hinge ? "maxTorque" : "maxForce"; }

// Whose keys a joint of `type` takes in the property schema.
PropertyOwner jointOwner(JointType type) {
    switch (type) {
        case JointType::Hinge: return PropertyOwner::Hinge;
        case JointType::Slider: return PropertyOwner::Slider;
        case JointType::Distance: return PropertyOwner::Distance;
        case JointType::Ball:
        case JointType::Fixed: break;
    }
    return PropertyOwner::Joint;
}

// Body names as the file gives them (index order, the loader's default for a nameless body), so
// joints resolve against the file even when a body failed to load.
std::vector<std::string> bodyNames(const Json& bodies) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Json* name = bodies[i].is_object() ? Reader::find(bodies[i], "name") : nullptr;
        names.push_back(name && name->is_string() ? name->get<std::string>() : "body " + std::to_string(i));
    }
    return names;
}

// The index of the one body called `name`, or an error at `path`.
std::optional<std::size_t> findBody(Reader& r, const Json& value, const std::string& path,
                                    const std::vector<std::string>& names) {
    const auto name = r.readString(value, path);
    if (!name) return std::nullopt;
    const auto count = std::count(names.begin(), names.end(), *name);
    if (count == 0) {
        r.error(path, "no body named \"" + *name + "\"");
        return std::nullopt;
    }
    if (count > 1) {
        r.error(path, std::to_string(count) + " bodies are named \"" + *name + "\"; a joint needs a unique name");
        return std::nullopt;
    }
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), *name) - names.begin());
}

std::optional<SceneJoint> readJoint(Reader& r, const Json& j, const std::string& path, std::size_t index,
                                    const std::vector<std::string>& names) {
    if (!r.expectObject(j, path)) return std::nullopt;
    const int errorsBefore = r.errorCount();
    SceneJoint out;
    JointCreationSettings& s = out.joint;

    const Json* typeValue = r.require(j, path, "type");
    const auto type = typeValue ? r.readString(*typeValue, childPath(path, "type")) : std::nullopt;
    if (!type) return std::nullopt;
    const JointType types[] = {JointType::Ball, JointType::Hinge, JointType::Slider, JointType::Fixed, JointType::Distance};
    const auto known = std::find_if(std::begin(types), std::end(types), [&](JointType t) { return *type == jointTypeName(t); });
    if (known == std::end(types)) {
        r.error(childPath(path, "type"), "unknown joint type '" + *type + "' (expected ball, hinge, slider, fixed or distance)");
        return std::nullopt;
    }
    s.type = *known;
    const bool hingeOrSlider = s.type == JointType::Hinge || s.type == JointType::Slider;
    const bool distance = s.type == JointType::Distance;

    const PropertyOwner owner = jointOwner(s.type);
    r.checkKeys(j, path, propertyKeys(owner), "for a " + *type + " joint");

    s.name = "joint " + std::to_string(index);
    if (const Json* name = Reader::find(j, "name"))
        if (auto text = r.readString(*name, childPath(path, "name"))) s.name = std::move(*text);

    if (const Json* bodyA = r.require(j, path, "bodyA"))
        if (const auto a = findBody(r, *bodyA, childPath(path, "bodyA"), names)) out.bodyA = *a;
    if (const Json* bodyB = Reader::find(j, "bodyB"); bodyB && !bodyB->is_null()) {
        const std::string p = childPath(path, "bodyB");
        if (const auto b = findBody(r, *bodyB, p, names)) {
            out.bodyB = *b;
            if (*b == out.bodyA) r.error(p, "bodyB names the same body as bodyA (leave it out to join bodyA to the world)");
        }
    }

    if (const Json* anchor = r.require(j, path, "anchor"))
        if (const auto v = r.readVec3(*anchor, childPath(path, "anchor"), limits::kCoordinate)) s.anchor = *v;
    r.optionalBool(j, path, "collideConnected", s.collideConnected);

    if (hingeOrSlider) {
        const std::string p = childPath(path, "axis");
        if (const Json* axis = r.require(j, path, "axis")) {
            if (const auto v = r.readVec3(*axis, p, limits::kCoordinate)) {
                if (glm::length(*v) > 1e-6f) s.axis = *v;
                else r.error(p, "axis must not be zero");
            }
        }
        if (const Json* value = Reader::find(j, "limits")) {
            const std::string lp = childPath(path, "limits");
            if (r.expectObject(*value, lp)) {
                r.checkKeys(*value, lp, propertyKeys(owner, "limits"));
                JointLimits l;
                const bool lowerRead = requiredFloat(r, *value, lp, "lower", propertyRange(owner, "limits.lower"), l.lower);
                if (requiredFloat(r, *value, lp, "upper", propertyRange(owner, "limits.upper"), l.upper) && lowerRead) {
                    if (l.lower > l.upper)
                        r.error(lp, "lower (" + io_detail::formatNumber(l.lower) + ") exceeds upper (" +
                                        io_detail::formatNumber(l.upper) + ")");
                    else
                        s.limits = l;
                }
            }
        }
        if (const Json* value = Reader::find(j, "motor")) {
            const std::string mp = childPath(path, "motor");
            if (r.expectObject(*value, mp)) {
                const char* forceKey = motorForceKey(s.type);
                r.checkKeys(*value, mp, propertyKeys(owner, "motor"));
                JointMotor m;
                const bool speedRead = requiredFloat(r, *value, mp, "speed", propertyRange(owner, "motor.speed"), m.speed);
                const NumberRange& forceRange = propertyRange(owner, std::string("motor.") + forceKey);
                if (requiredFloat(r, *value, mp, forceKey, forceRange, m.maxForce) && speedRead) s.motor = m;
            }
        }
    }

    if (distance) {
        const std::string p = childPath(path, "anchorB");
        if (const Json* anchorB = r.require(j, path, "anchorB")) {
            if (const auto v = r.readVec3(*anchorB, p, limits::kCoordinate)) {
                s.anchorB = *v;
                if (glm::length(s.anchorB - s.anchor) < 1e-4f) r.error(p, "anchorB must be at least 0.1 mm from anchor");
            }
        }
        if (const Json* value = Reader::find(j, "spring")) {
            const std::string sp = childPath(path, "spring");
            if (r.expectObject(*value, sp)) {
                r.checkKeys(*value, sp, propertyKeys(owner, "spring"));
                JointSpring spring;
                const bool hertzRead = requiredFloat(r, *value, sp, "hertz", limits::kSpringHertz, spring.hertz);
                if (r.optionalFloat(*value, sp, "dampingRatio", limits::kDampingRatio, spring.dampingRatio) && hertzRead)
                    s.spring = spring;
            }
        }
        float length = 0.0f;
        if (Reader::find(j, "minLength") && r.optionalFloat(j, path, "minLength", limits::kJointLength, length)) s.minLength = length;
        if (Reader::find(j, "maxLength") && r.optionalFloat(j, path, "maxLength", limits::kJointLength, length)) s.maxLength = length;
        if (r.errorCount() == errorsBefore) {
            const DistanceLengths lengths = distanceLengths(s);
            if (lengths.min > lengths.max)
                r.error(childPath(path, s.minLength ? "minLength" : "maxLength"),
                        "minLength (" + io_detail::formatNumber(lengths.min) + ") exceeds maxLength (" +
                            io_detail::formatNumber(lengths.max) + "); unset, each is the rest length " +
                            io_detail::formatNumber(lengths.rest));
        }
    }

    if (r.errorCount() > errorsBefore) return std::nullopt;
    return out;
}

std::optional<Scene> readV1(const Json& root, Reader& r) {
    r.checkKeys(root, "", {"format", "version", "settings", "bodies", "joints"});

    // A wrong or missing format tag means this is not a scene at all, and a newer version may give
    // keys other meanings: reporting its contents key by key would only bury the real problem.
    const Json* format = r.require(root, "", "format");
    if (!format) return std::nullopt;
    const auto tag = r.readString(*format, "/format");
    if (!tag) return std::nullopt;
    if (*tag != kFormatTag) {
        r.error("/format", "format must be \"" + std::string(kFormatTag) + "\", got \"" + *tag + "\"");
        return std::nullopt;
    }
    if (const Json* version = r.require(root, "", "version")) {
        if (!version->is_number()) {
            r.error("/version", "expected an integer, got " + io_detail::typeName(*version));
        } else if (const double v = version->get<double>(); v != std::floor(v)) {
            r.error("/version", "expected an integer, got " + io_detail::formatNumber(v));
        } else {
            if (v > kFormatVersion) {
                r.error("/version", "version " + io_detail::formatNumber(v) + " is newer than this program supports (" +
                                        std::to_string(kFormatVersion) + ")");
                return std::nullopt;
            }
            if (v != kFormatVersion)
                r.error("/version", "version " + io_detail::formatNumber(v) + " is not a valid version (this program reads version " +
                                        std::to_string(kFormatVersion) + ")");
        }
    }

    Scene scene;
    if (const Json* settings = Reader::find(root, "settings")) readSettings(r, *settings, "/settings", scene.settings);

    std::vector<std::string> names;
    if (const Json* bodies = r.require(root, "", "bodies"); bodies && r.expectArray(*bodies, "/bodies")) {
        scene.bodies.reserve(bodies->size());
        for (std::size_t i = 0; i < bodies->size() && !r.full(); ++i) {
            if (auto body = readBody(r, (*bodies)[i], childPath("/bodies", i), i)) scene.bodies.push_back(std::move(*body));
        }
        names = bodyNames(*bodies);
    }

    if (const Json* joints = Reader::find(root, "joints"); joints && r.expectArray(*joints, "/joints")) {
        scene.joints.reserve(joints->size());
        for (std::size_t i = 0; i < joints->size() && !r.full(); ++i) {
            if (auto joint = readJoint(r, (*joints)[i], childPath("/joints", i), i, names))
                scene.joints.push_back(std::move(*joint));
        }
    }

    if (r.errorCount() > 0) return std::nullopt;
    return scene;
}

// ---- writing ----

using OrderedJson = nlohmann::ordered_json;

// A float as the shortest decimal that reads back as the same float (0.1, not 0.100000001490116),
// handed to nlohmann as the double nearest that decimal; nlohmann prints that double's shortest
// form, which is the same decimal. from_chars, unlike strtod, ignores the C locale (Qt sets it
// from the environment, and a decimal comma would break parsing).
OrderedJson number(float value) {
    char buffer[32];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    double d = 0.0;
    const auto parsed = std::from_chars(buffer, written.ptr, d);
    if (parsed.ec != std::errc()) return OrderedJson(nullptr);  // nan/inf: written as null, refused on load
    return OrderedJson(d);
}

OrderedJson vec3(const Vec3& v) { return OrderedJson::array({number(v.x), number(v.y), number(v.z)}); }

OrderedJson settingValueJson(const SettingInfo& info, const SettingValue& value) {
    switch (info.type) {
        case SettingType::Bool: return std::get<bool>(value);
        case SettingType::Int: return std::get<int>(value);
        case SettingType::Float: return number(std::get<float>(value));
        case SettingType::Vec3: return vec3(std::get<Vec3>(value));
        case SettingType::Choice: return std::string(info.choices[static_cast<std::size_t>(std::get<int>(value))]);
    }
    return nullptr;
}

OrderedJson settingsJson(const WorldSettings& s) {
    OrderedJson j = OrderedJson::object();
    // Only a label: every value it sets is written below too, so loading gives the same numbers.
    if (const auto preset = matchingQualityPreset(s)) j["preset"] = std::string(qualityPresetName(*preset));
    for (const SettingInfo& info : settingsSchema()) {
        const auto [first, rest] = splitKey(info.key);
        OrderedJson value = settingValueJson(info, info.get(s));
        if (rest.empty()) j[std::string(first)] = std::move(value);
        else j[std::string(first)][std::string(rest)] = std::move(value);
    }
    return j;
}

const char* motionName(MotionType m) {
    switch (m) {
        case MotionType::Static: return "static";
        case MotionType::Kinematic: return "kinematic";
        case MotionType::Dynamic: break;
    }
    return "dynamic";
}

OrderedJson shapeJson(const Shape& shape) {
    OrderedJson j = OrderedJson::object();
    j["type"] = std::string(shapeTypeName(shape.type));
    switch (shape.type) {
        case ShapeType::Box: j["halfExtents"] = vec3(shape.halfExtents); break;
        case ShapeType::Sphere: j["radius"] = number(shape.radius); break;
        case ShapeType::Capsule:
        case ShapeType::Cylinder:
            j["radius"] = number(shape.radius);
            j["halfHeight"] = number(shape.halfHeight);
            break;
        case ShapeType::ConvexHull: {
            OrderedJson points = OrderedJson::array();
            if (shape.hull)
                for (const Vec3& p : shape.hull->sourcePoints()) points.push_back(vec3(p));
            j["points"] = std::move(points);
            break;
        }
    }
    return j;
}

OrderedJson bodyJson(const SceneBody& sb) {
    const BodyCreationSettings& b = sb.body;
    OrderedJson j = OrderedJson::object();
    j["name"] = b.name;
    j["motion"] = motionName(b.motion);
    j["shape"] = shapeJson(b.shape);
    j["position"] = vec3(b.position);
    const Quat& q = b.orientation;
    j["orientation"] = OrderedJson::array({number(q.w), number(q.x), number(q.y), number(q.z)});
    j["linearVelocity"] = vec3(b.linearVelocity);
    j["angularVelocity"] = vec3(b.angularVelocity);
    if (b.mass) j["mass"] = number(*b.mass);
    else j["density"] = number(b.density);
    j["friction"] = number(b.friction);
    j["restitution"] = number(b.restitution);
    // Only when set, so files of scenes without it stay as they were (-0 is kept: it reads back
    // as itself, and saving gives back every value bit for bit).
    if (b.rollingResistance != 0.0f || std::signbit(b.rollingResistance)) j["rollingResistance"] = number(b.rollingResistance);
    j["ccd"] = b.ccd;
    if (sb.color) j["color"] = vec3(*sb.color);
    return j;
}

OrderedJson jointJson(const SceneJoint& sj, const std::vector<SceneBody>& bodies) {
    const JointCreationSettings& s = sj.joint;
    OrderedJson j = OrderedJson::object();
    j["name"] = s.name;
    j["type"] = std::string(jointTypeName(s.type));
    j["bodyA"] = bodies[sj.bodyA].body.name;
    j["bodyB"] = sj.bodyB ? OrderedJson(bodies[*sj.bodyB].body.name) : OrderedJson(nullptr);
    j["anchor"] = vec3(s.anchor);
    if (s.type == JointType::Distance) j["anchorB"] = vec3(s.anchorB);
    if (s.type == JointType::Hinge || s.type == JointType::Slider) {
        j["axis"] = vec3(s.axis);
        if (s.limits) j["limits"] = {{"lower", number(s.limits->lower)}, {"upper", number(s.limits->upper)}};
        if (s.motor) j["motor"] = {{"speed", number(s.motor->speed)}, {motorForceKey(s.type), number(s.motor->maxForce)}};
    }
    if (s.type == JointType::Distance) {
        if (s.spring) j["spring"] = {{"hertz", number(s.spring->hertz)}, {"dampingRatio", number(s.spring->dampingRatio)}};
        if (s.minLength) j["minLength"] = number(*s.minLength);
        if (s.maxLength) j["maxLength"] = number(*s.maxLength);
    }
    j["collideConnected"] = s.collideConnected;
    return j;
}

// Two-space indentation like dump(2), but arrays of plain values stay on one line, so vectors
// read as [0, -9.81, 0] and a hull is one point per line.
void writeJson(std::string& out, const OrderedJson& v, int indent) {
    auto scalar = [](const OrderedJson& s) {
        return s.dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
    };
    const bool isContainer = v.is_object() || v.is_array();
    if (!isContainer) {
        out += scalar(v);
        return;
    }
    if (v.empty()) {
        out += v.is_object() ? "{}" : "[]";
        return;
    }
    if (v.is_array()) {
        bool flat = true;
        for (const auto& e : v) flat = flat && !e.is_object() && !e.is_array();
        if (flat) {
            out += '[';
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (i > 0) out += ", ";
                out += scalar(v[i]);
            }
            out += ']';
            return;
        }
    }
    out += v.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (!first) out += ",\n";
        first = false;
        out.append(static_cast<std::size_t>(indent + 2), ' ');
        if (v.is_object()) {
            out += scalar(OrderedJson(it.key()));
            out += ": ";
        }
        writeJson(out, *it, indent + 2);
    }
    out += '\n';
    out.append(static_cast<std::size_t>(indent), ' ');
    out += v.is_object() ? '}' : ']';
}

std::string osError(int error) { return std::system_category().message(error); }

}  // namespace

// ---- public API ----

std::string Diagnostic::toString() const {
    const char* kind = severity == Severity::Error ? "error" : "warning";
    const std::string name = file.empty() ? "<scene>" : file;
    if (line > 0)
        return name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + kind + ": " + message;
    if (!path.empty()) return name + ": " + kind + " at " + path + ": " + message;
    return name + ": " + kind + ": " + message;
}

SceneLoadResult parseScene(std::string_view text, std::string_view fileName) {
    SceneLoadResult result;
    const std::string file(fileName);
    std::optional<Json> root = io_detail::parseJson(text, file, result.diagnostics);
    if (!root) return result;

    Reader reader(file, result.diagnostics);
    std::optional<Scene> scene;
    std::string bodiesPath = "/bodies";
    if (!root->is_object()) {
        reader.error("", "expected a JSON object at the top level, got " + io_detail::typeName(*root));
    } else if (!Reader::find(*root, "format") && Reader::find(*root, "objects")) {
        // The thesis app's files have no format tag; their "objects" list identifies them.
        scene = io_detail::importThesisScene(*root, reader);
        bodiesPath = "/objects";
    } else {
        scene = readV1(*root, reader);
    }
    // Limits on what the values of a body come to together (mass from density, inertia), which
    // no single value shows: the same for both formats.
    for (std::size_t i = 0; scene && i < scene->bodies.size() && !reader.full(); ++i)
        io_detail::checkMassProperties(reader, scene->bodies[i].body, childPath(bodiesPath, i));
    reader.finish();
    if (reader.errorCount() == 0 && scene) result.scene = std::move(scene);
    return result;
}

SceneLoadResult loadSceneFile(const std::filesystem::path& path) {
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
    return parseScene(text, name);
}

std::string serializeScene(const Scene& scene) {
    OrderedJson root = OrderedJson::object();
    root["format"] = kFormatTag;
    root["version"] = kFormatVersion;
    root["settings"] = settingsJson(scene.settings);
    OrderedJson bodies = OrderedJson::array();
    for (const SceneBody& b : scene.bodies) bodies.push_back(bodyJson(b));
    root["bodies"] = std::move(bodies);
    OrderedJson joints = OrderedJson::array();
    for (const SceneJoint& j : scene.joints) joints.push_back(jointJson(j, scene.bodies));
    root["joints"] = std::move(joints);
    std::string out;
    writeJson(out, root, 0);
    out += '\n';
    return out;
}

std::optional<std::string> saveSceneFile(const Scene& scene, const std::filesystem::path& requestedPath) {
    namespace fs = std::filesystem;
    const std::string text = serializeScene(scene);
    const std::string target = requestedPath.string();
    auto failure = [&](const std::string& why) { return "cannot save '" + target + "': " + why; };

    if (requestedPath.filename().empty()) return failure("the path names no file");
    std::error_code ec;
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
    // The loader's own rules, by the loader: no second copy of them to drift apart.
    return parseScene(serializeScene(scene), "").diagnostics;
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
