// Writing a Scene as v1 JSON text: every value, each number exact, laid out for reading and diffs.

#include "simcore/io/scene_io.h"

#include "simcore/io/scene_v1.h"
#include "simcore/shapes/compound_shape.h"
#include "simcore/world/quality_preset.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace simcore {

using io_detail::kFormatTag;
using io_detail::kFormatVersion;
using io_detail::motorForceKey;
using io_detail::OrderedJson;
using io_detail::settingsJson;
using io_detail::splitKey;

namespace {

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

}  // namespace

OrderedJson io_detail::settingsJson(const WorldSettings& s) {
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

namespace {

const char* motionName(MotionType m) {
    switch (m) {
        case MotionType::Static: return "static";
        case MotionType::Kinematic: return "kinematic";
        case MotionType::Dynamic: break;
    }
    return "dynamic";
}

OrderedJson quaternion(const Quat& q) { return OrderedJson::array({number(q.w), number(q.x), number(q.y), number(q.z)}); }

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
        case ShapeType::Compound: {
            OrderedJson children = OrderedJson::array();
            if (shape.compound)
                for (const CompoundChild& child : shape.compound->children()) {
                    OrderedJson c = OrderedJson::object();
                    c["shape"] = shapeJson(child.shape);
                    c["position"] = vec3(child.pose.position);
                    c["orientation"] = quaternion(child.pose.rotation);
                    children.push_back(std::move(c));
                }
            j["children"] = std::move(children);
            break;
        }
        case ShapeType::Mesh: {
            OrderedJson vertices = OrderedJson::array();
            OrderedJson triangles = OrderedJson::array();
            if (shape.mesh) {
                for (const Vec3& v : shape.mesh->vertices()) vertices.push_back(vec3(v));
                for (const TriangleMesh::Indices& t : shape.mesh->triangleIndices())
                    triangles.push_back(OrderedJson::array({t[0], t[1], t[2]}));
            }
            j["vertices"] = std::move(vertices);
            j["triangles"] = std::move(triangles);
            break;
        }
        case ShapeType::HeightField: {
            if (!shape.heightField) break;
            const HeightField& field = *shape.heightField;
            j["rows"] = field.rows();
            j["columns"] = field.columns();
            j["cellSize"] = number(field.cellSize());
            j["heightScale"] = number(field.heightScale());
            OrderedJson heights = OrderedJson::array();
            for (float h : field.heights()) heights.push_back(number(h));
            j["heights"] = std::move(heights);
            break;
        }
    }
    return j;
}

// A mesh read from a file, as its reference: the triangles stay in the file.
OrderedJson meshFileJson(const MeshFileReference& reference, const std::filesystem::path& sceneFolder) {
    OrderedJson j = OrderedJson::object();
    j["type"] = "mesh";
    j["file"] = meshFileText(reference, sceneFolder);
    j["scale"] = vec3(reference.scale);
    j["upAxis"] = std::string(upAxisName(reference.upAxis));
    return j;
}

OrderedJson bodyJson(const SceneBody& sb, const std::filesystem::path& sceneFolder) {
    const BodyCreationSettings& b = sb.body;
    OrderedJson j = OrderedJson::object();
    j["name"] = b.name;
    j["motion"] = motionName(b.motion);
    const bool fromFile = sb.meshFile && b.shape.type == ShapeType::Mesh;
    j["shape"] = fromFile ? meshFileJson(*sb.meshFile, sceneFolder) : shapeJson(b.shape);
    j["position"] = vec3(b.position);
    j["orientation"] = quaternion(b.orientation);
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

}  // namespace

std::string serializeScene(const Scene& scene, const std::filesystem::path& sceneFolder) {
    OrderedJson root = OrderedJson::object();
    root["format"] = kFormatTag;
    root["version"] = kFormatVersion;
    root["settings"] = settingsJson(scene.settings);
    OrderedJson bodies = OrderedJson::array();
    for (const SceneBody& b : scene.bodies) bodies.push_back(bodyJson(b, sceneFolder));
    root["bodies"] = std::move(bodies);
    OrderedJson joints = OrderedJson::array();
    for (const SceneJoint& j : scene.joints) joints.push_back(jointJson(j, scene.bodies));
    root["joints"] = std::move(joints);
    // Only when there is something to keep: a scene without bookmarks saves as it always did.
    if (!scene.editor.cameraBookmarks.empty()) {
        OrderedJson bookmarks = OrderedJson::array();
        for (const CameraBookmark& b : scene.editor.cameraBookmarks) {
            OrderedJson bookmark = OrderedJson::object();
            bookmark["name"] = b.name;
            bookmark["target"] = vec3(b.target);
            bookmark["yaw"] = number(b.yawDegrees);
            bookmark["pitch"] = number(b.pitchDegrees);
            bookmark["distance"] = number(b.distance);
            bookmark["orthographic"] = b.orthographic;
            bookmarks.push_back(std::move(bookmark));
        }
        root["editor"] = OrderedJson{{"cameraBookmarks", std::move(bookmarks)}};
    }
    std::string out;
    writeJson(out, root, 0);
    out += '\n';
    return out;
}

}  // namespace simcore
