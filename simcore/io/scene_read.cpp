// Reading scene text into a Scene: format v1, strictly, with a diagnostic per problem (the thesis
// app's format is thesis_import.cpp).
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
//  - compounds: 1 to limits::kMaxCompoundChildren children, each a convex shape read (and
//    reported) like a body's, at its own path ("/bodies/3/shape/children/1/shape/radius"); a
//    compound child is refused (no nesting). A child's position defaults to 0, its orientation to
//    identity, read like a body's.
//  - meshes: inline "vertices" and "triangles" (TriangleMesh::build's checks, its message at the
//    triangles' path), or a "file" read through SceneReadOptions::loadMeshFile and held to the same
//    checks (errors at the file's path, naming it as written and as resolved); height fields: "rows" x "columns" "heights" (HeightField::build's checks).
//    Both on static and kinematic bodies only: a dynamic one is an error at its "motion".
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
//  - editor (optional): {"cameraBookmarks": [...]}, at most kMaxCameraBookmarks of them, each with
//    "name" (cameraBookmarkNameProblem), "target", "yaw", "pitch" and "distance" required and
//    "orthographic" optional (false). Kept and written back; nothing simulated reads it.
//  - settings.preset: "fast", "balanced" or "accurate" (quality_preset.h), applied before every other
//    settings key, which then override it. Saving writes it when the settings match a preset.

#include "simcore/io/scene_io.h"

#include "simcore/io/json_reader.h"
#include "simcore/io/scene_v1.h"
#include "simcore/shapes/compound_shape.h"
#include "simcore/world/quality_preset.h"
#include "simcore/world/validation.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace simcore {

using io_detail::childPath;
using io_detail::Json;
using io_detail::kFormatTag;
using io_detail::kFormatVersion;
using io_detail::motorForceKey;
using io_detail::Reader;
using io_detail::splitKey;

namespace {


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

}  // namespace

void io_detail::readSettings(Reader& r, const Json& s, const std::string& path, WorldSettings& out) {
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

namespace {

std::optional<Quat> readOrientation(Reader& r, const Json& v, const std::string& path);

// Whether a shape being read may be a compound: a body's may, a compound's child may not.
enum class Nesting { BodyShape, CompoundChild };

std::optional<Shape> readShape(Reader& r, const Json& j, const std::string& path, Nesting nesting);

// "children": each {"shape", "position", "orientation"}; the child shapes convex.
std::optional<Shape> readCompound(Reader& r, const Json& j, const std::string& path) {
    r.checkKeys(j, path, propertyKeys(PropertyOwner::Compound), "for a compound shape");
    const Json* children = r.require(j, path, "children");
    const std::string p = childPath(path, "children");
    if (!children || !r.expectArray(*children, p)) return std::nullopt;
    if (children->empty() || children->size() > limits::kMaxCompoundChildren) {
        r.error(p, "a compound has 1 to " + std::to_string(limits::kMaxCompoundChildren) + " children, got " +
                       std::to_string(children->size()));
        return std::nullopt;
    }
    std::vector<CompoundChild> parts;
    bool ok = true;
    for (std::size_t i = 0; i < children->size() && !r.full(); ++i) {
        const Json& c = (*children)[i];
        const std::string cp = childPath(p, i);
        if (!r.expectObject(c, cp)) {
            ok = false;
            continue;
        }
        r.checkKeys(c, cp, propertyKeys(PropertyOwner::CompoundChild), "for a compound's child");
        const int errorsBefore = r.errorCount();
        CompoundChild child;
        if (const Json* shape = r.require(c, cp, "shape"))
            if (auto parsed = readShape(r, *shape, childPath(cp, "shape"), Nesting::CompoundChild))
                child.shape = std::move(*parsed);
        r.optionalVec3(c, cp, "position", propertyRange(PropertyOwner::CompoundChild, "position"), child.pose.position);
        if (const Json* orientation = Reader::find(c, "orientation"))
            if (const auto q = readOrientation(r, *orientation, childPath(cp, "orientation"))) child.pose.rotation = *q;
        if (r.errorCount() > errorsBefore) ok = false;
        else parts.push_back(std::move(child));
    }
    if (!ok) return std::nullopt;
    return Shape::compoundOf(std::make_shared<const CompoundShape>(std::move(parts)));
}

// An array at `key` of at most `limit` items, each read by readItem(item, itemPath) -> optional<T>;
// nothing (and reported) when missing, too long or any item is bad.
template <class T, class ReadItem>
std::optional<std::vector<T>> readList(Reader& r, const Json& j, const std::string& path, std::string_view key,
                                       std::size_t limit, std::string_view what, ReadItem readItem) {
    const Json* list = r.require(j, path, key);
    const std::string p = childPath(path, key);
    if (!list || !r.expectArray(*list, p)) return std::nullopt;
    if (list->size() > limit) {
        r.error(p, "at most " + std::to_string(limit) + " " + std::string(what) + ", got " + std::to_string(list->size()));
        return std::nullopt;
    }
    std::vector<T> items;
    items.reserve(list->size());
    bool ok = true;
    for (std::size_t i = 0; i < list->size() && !r.full(); ++i) {
        if (auto item = readItem((*list)[i], childPath(p, i))) items.push_back(std::move(*item));
        else ok = false;
    }
    if (!ok) return std::nullopt;
    return items;
}

// "vertices" and "triangles", inline.
std::optional<Shape> readMesh(Reader& r, const Json& j, const std::string& path) {
    r.checkKeys(j, path, propertyKeys(PropertyOwner::Mesh), "for a mesh shape");
    for (const char* key : {"scale", "upAxis"})
        if (Reader::find(j, key)) r.warning(childPath(path, key), "only a mesh from a file takes this key; it is ignored");
    const auto vertices = readList<Vec3>(r, j, path, "vertices", limits::kMaxMeshVertices, "vertices",
                                         [&](const Json& v, const std::string& p) {
                                             return r.readVec3(v, p, propertyRange(PropertyOwner::Mesh, "vertices"));
                                         });
    const auto triangles = readList<TriangleMesh::Indices>(
        r, j, path, "triangles", limits::kMaxMeshTriangles, "triangles",
        [&](const Json& t, const std::string& p) -> std::optional<TriangleMesh::Indices> {
            if (!t.is_array() || t.size() != 3) {
                r.error(p, "expected 3 vertex indices [i, j, k], got " +
                               (t.is_array() ? std::to_string(t.size()) + " items" : io_detail::typeName(t)));
                return std::nullopt;
            }
            TriangleMesh::Indices indices{};
            for (std::size_t k = 0; k < 3; ++k) {
                const auto index = r.readInt(t[k], childPath(p, k), 0, int(limits::kMaxMeshVertices) - 1);
                if (!index) return std::nullopt;
                indices[k] = std::uint32_t(*index);
            }
            return indices;
        });
    if (!vertices || !triangles) return std::nullopt;
    TriangleMesh::BuildResult built = TriangleMesh::build(*vertices, *triangles);
    if (!built.mesh) {
        r.error(childPath(path, "triangles"), "cannot build the mesh: " + built.error);
        return std::nullopt;
    }
    return Shape::triangleMesh(std::move(built.mesh));
}

// "rows" x "columns" "heights", "cellSize", "heightScale".
std::optional<Shape> readHeightField(Reader& r, const Json& j, const std::string& path) {
    r.checkKeys(j, path, propertyKeys(PropertyOwner::HeightField), "for a heightField shape");
    const auto count = [&](std::string_view key) -> std::optional<int> {
        const Json* v = r.require(j, path, key);
        const NumberRange& range = propertyRange(PropertyOwner::HeightField, key);
        return v ? r.readInt(*v, childPath(path, key), int(range.min), int(range.max)) : std::nullopt;
    };
    const auto rows = count("rows");
    const auto columns = count("columns");
    float cellSize = 1.0f, heightScale = 1.0f;
    const Json* cell = r.require(j, path, "cellSize");
    const bool sized = cell && r.optionalFloat(j, path, "cellSize", propertyRange(PropertyOwner::HeightField, "cellSize"), cellSize);
    const bool scaled =
        r.optionalFloat(j, path, "heightScale", propertyRange(PropertyOwner::HeightField, "heightScale"), heightScale);
    if (!rows || !columns || !sized || !scaled) return std::nullopt;
    const std::size_t samples = std::size_t(*rows) * std::size_t(*columns);
    if (2 * std::size_t(*rows - 1) * std::size_t(*columns - 1) > limits::kMaxMeshTriangles) {
        r.error(path, "a height field may have at most " + std::to_string(limits::kMaxMeshTriangles) +
                          " triangles (2 (rows - 1)(columns - 1)), got " +
                          std::to_string(2 * std::size_t(*rows - 1) * std::size_t(*columns - 1)));
        return std::nullopt;
    }
    const auto heights = readList<float>(r, j, path, "heights", samples, "heights (rows x columns)",
                                         [&](const Json& h, const std::string& p) {
                                             return r.readFloat(h, p, propertyRange(PropertyOwner::HeightField, "heights"));
                                         });
    if (!heights) return std::nullopt;
    if (heights->size() != samples) {
        r.error(childPath(path, "heights"), "expected rows x columns = " + std::to_string(samples) + " heights, got " +
                                                std::to_string(heights->size()));
        return std::nullopt;
    }
    HeightField::BuildResult built = HeightField::build(*rows, *columns, cellSize, heightScale, *heights);
    if (!built.field) {
        r.error(path, "cannot build the height field: " + built.error);
        return std::nullopt;
    }
    return Shape::heightFieldOf(std::move(built.field));
}

// A mesh given by "file" (and "scale", "upAxis"): read through the options' loader, then held to
// the limits of an inline mesh by TriangleMesh::build. `reference` is set on success.
std::optional<Shape> readMeshFile(Reader& r, const Json& j, const std::string& path, const SceneReadOptions& options,
                                  std::optional<MeshFileReference>& reference) {
    r.checkKeys(j, path, propertyKeys(PropertyOwner::Mesh), "for a mesh shape");
    const std::string filePath = childPath(path, "file");
    if (Reader::find(j, "vertices") || Reader::find(j, "triangles")) {
        r.error(filePath, "a mesh takes either a file or vertices and triangles, not both");
        return std::nullopt;
    }
    MeshFileReference read;
    const auto file = r.readString(*Reader::find(j, "file"), filePath);
    if (!file) return std::nullopt;
    if (file->empty()) {
        r.error(filePath, "the file name is empty");
        return std::nullopt;
    }
    read.file = *file;
    const std::string scalePath = childPath(path, "scale");
    if (!r.optionalVec3(j, path, "scale", propertyRange(PropertyOwner::Mesh, "scale"), read.scale)) return std::nullopt;
    if (glm::any(glm::lessThan(glm::abs(read.scale), Vec3(float(limits::kSize.min))))) {
        r.error(scalePath, "every scale factor must be at least " + io_detail::formatNumber(limits::kSize.min) +
                               " in size (a negative one mirrors the mesh)");
        return std::nullopt;
    }
    if (const Json* up = Reader::find(j, "upAxis")) {
        const std::string upPath = childPath(path, "upAxis");
        const auto name = r.readString(*up, upPath);
        if (!name) return std::nullopt;
        const std::optional<UpAxis> axis = parseUpAxis(*name);
        if (!axis) {
            r.error(upPath, "unknown up axis '" + *name + "' (expected y, z or x)");
            return std::nullopt;
        }
        read.upAxis = *axis;
    }
    read.resolvedPath = resolveMeshFile(read.file, options.sceneFolder);
    const std::string named = "\"" + read.file + "\" (" + read.resolvedPath.string() + ")";
    if (!options.loadMeshFile) {
        r.error(filePath, "cannot read the mesh file " + named + ": this program reads scenes without the mesh importer");
        return std::nullopt;
    }
    MeshFileData data = options.loadMeshFile(MeshFileRequest{read});
    if (!data.error.empty()) {
        r.error(filePath, data.error.find(read.resolvedPath.string()) == std::string::npos
                              ? "cannot read the mesh file " + named + ": " + data.error
                              : data.error);
        return std::nullopt;
    }
    TriangleMesh::BuildResult built = TriangleMesh::build(std::move(data.vertices), std::move(data.triangles));
    if (!built.mesh) {
        r.error(filePath, "cannot build the mesh of " + named + ": " + built.error);
        return std::nullopt;
    }
    reference = std::move(read);
    return Shape::triangleMesh(std::move(built.mesh));
}

std::optional<Shape> readShape(Reader& r, const Json& j, const std::string& path, Nesting nesting) {
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
    } else if (*type == "compound") {
        if (nesting == Nesting::BodyShape) return readCompound(r, j, path);
        r.error(childPath(path, "type"), "a compound's child must be a convex shape: compounds do not nest");
    } else if (*type == "mesh" || *type == "heightField") {
        if (nesting == Nesting::BodyShape) return *type == "mesh" ? readMesh(r, j, path) : readHeightField(r, j, path);
        r.error(childPath(path, "type"), "a compound's child must be a convex shape, not a " + *type);
    } else {
        r.error(childPath(path, "type"),
                "unknown shape type '" + *type +
                    "' (expected box, sphere, capsule, cylinder, convexHull, compound, mesh or heightField)");
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

std::optional<SceneBody> readBody(Reader& r, const Json& b, const std::string& path, std::size_t index,
                                  const SceneReadOptions& options) {
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

    if (const Json* shape = r.require(b, path, "shape")) {
        const std::string shapePath = childPath(path, "shape");
        const Json* type = shape->is_object() ? Reader::find(*shape, "type") : nullptr;
        const bool meshFile = type && *type == "mesh" && Reader::find(*shape, "file");
        std::optional<Shape> parsed = meshFile ? readMeshFile(r, *shape, shapePath, options, out.meshFile)
                                               : readShape(r, *shape, shapePath, Nesting::BodyShape);
        if (parsed) s.shape = std::move(*parsed);
    }

    if (const std::string problem = validation::dynamicShapeProblem(s.shape.type);
        s.motion == MotionType::Dynamic && !problem.empty())
        r.error(childPath(path, "motion"), problem);

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

// Ranges of a camera bookmark's angles and distance: wider than the editor's camera goes (it keeps
// yaw within one turn, pitch 1 degree short of the poles, 5 cm to 5 km), which clamps on recall.
constexpr io_detail::Range kBookmarkYaw{-360.0, 360.0, false, "degrees"};
constexpr io_detail::Range kBookmarkPitch{-90.0, 90.0, false, "degrees"};
constexpr io_detail::Range kBookmarkDistance{0.0, 1e6, true, "m"};

std::optional<CameraBookmark> readCameraBookmark(Reader& r, const Json& b, const std::string& path) {
    if (!r.expectObject(b, path)) return std::nullopt;
    r.checkKeys(b, path, {"name", "target", "yaw", "pitch", "distance", "orthographic"}, "in a camera bookmark");
    const int errorsBefore = r.errorCount();
    CameraBookmark out;
    if (const Json* name = r.require(b, path, "name")) {
        const std::string p = childPath(path, "name");
        if (const auto text = r.readString(*name, p)) {
            if (const auto problem = cameraBookmarkNameProblem(*text)) r.error(p, *problem);
            out.name = *text;
        }
    }
    if (const Json* target = r.require(b, path, "target")) {
        if (const auto v = r.readVec3(*target, childPath(path, "target"), limits::kCoordinate)) out.target = *v;
    }
    requiredFloat(r, b, path, "yaw", kBookmarkYaw, out.yawDegrees);
    requiredFloat(r, b, path, "pitch", kBookmarkPitch, out.pitchDegrees);
    requiredFloat(r, b, path, "distance", kBookmarkDistance, out.distance);
    r.optionalBool(b, path, "orthographic", out.orthographic);
    if (r.errorCount() > errorsBefore) return std::nullopt;
    return out;
}

void readEditorState(Reader& r, const Json& editor, const std::string& path, EditorState& out) {
    if (!r.expectObject(editor, path)) return;
    r.checkKeys(editor, path, {"cameraBookmarks"}, "in the editor object");
    const Json* bookmarks = Reader::find(editor, "cameraBookmarks");
    const std::string p = childPath(path, "cameraBookmarks");
    if (!bookmarks || !r.expectArray(*bookmarks, p)) return;
    if (bookmarks->size() > kMaxCameraBookmarks) {
        r.error(p, "a scene may have at most " + std::to_string(kMaxCameraBookmarks) + " camera bookmarks, got " +
                       std::to_string(bookmarks->size()));
        return;
    }
    for (std::size_t i = 0; i < bookmarks->size() && !r.full(); ++i) {
        if (auto bookmark = readCameraBookmark(r, (*bookmarks)[i], childPath(p, i))) out.cameraBookmarks.push_back(std::move(*bookmark));
    }
}

std::optional<Scene> readV1(const Json& root, Reader& r, const SceneReadOptions& options) {
    r.checkKeys(root, "", {"format", "version", "settings", "bodies", "joints", "editor"});

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
            if (auto body = readBody(r, (*bodies)[i], childPath("/bodies", i), i, options)) scene.bodies.push_back(std::move(*body));
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

    if (const Json* editor = Reader::find(root, "editor")) readEditorState(r, *editor, "/editor", scene.editor);

    if (r.errorCount() > 0) return std::nullopt;
    return scene;
}

}  // namespace

SceneLoadResult parseScene(std::string_view text, std::string_view fileName, const SceneReadOptions& options) {
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
        scene = readV1(*root, reader, options);
    }
    // Limits on what the values of a body come to together (mass from density, inertia), which
    // no single value shows: the same for both formats.
    for (std::size_t i = 0; scene && i < scene->bodies.size() && !reader.full(); ++i)
        io_detail::checkMassProperties(reader, scene->bodies[i].body, childPath(bodiesPath, i));
    reader.finish();
    if (reader.errorCount() == 0 && scene) result.scene = std::move(scene);
    return result;
}

}  // namespace simcore
