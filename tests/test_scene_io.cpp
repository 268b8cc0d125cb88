// Scene file v1: exact round trips, the brief's example, warnings for unknown keys, atomic saves,
// settings overrides, building worlds from scenes, the default scene, and the editor's camera
// bookmarks (kept, written back, checked).

#include "simcore/io/scene.h"
#include "simcore/io/scene_io.h"
#include "simcore/shapes/compound_shape.h"

#include <QtTest>

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

using namespace simcore;

namespace {

bool sameBits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool sameBits(const Vec3& a, const Vec3& b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }
bool sameBits(const Quat& a, const Quat& b) {
    return sameBits(a.w, b.w) && sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

std::string describe(const std::vector<Diagnostic>& diagnostics) {
    std::string s;
    for (const Diagnostic& d : diagnostics) s += d.toString() + "\n";
    return s;
}

// Compares every number bit for bit (so -0 differs from 0), and every other field exactly.
void compareScenes(const Scene& a, const Scene& b) {
    const WorldSettings& sa = a.settings;
    const WorldSettings& sb = b.settings;
    QVERIFY(sameBits(sa.gravity, sb.gravity));
    QVERIFY(sameBits(sa.timeStep, sb.timeStep));
    QCOMPARE(sa.substeps, sb.substeps);
    QCOMPARE(sa.solver.velocityIterations, sb.solver.velocityIterations);
    QCOMPARE(sa.solver.positionIterations, sb.solver.positionIterations);
    QVERIFY(sa.solver == sb.solver);
    QVERIFY(sa.contact == sb.contact);
    QVERIFY(sameBits(sa.damping.linear, sb.damping.linear));
    QVERIFY(sameBits(sa.damping.angular, sb.damping.angular));
    QCOMPARE(sa.sleep.enabled, sb.sleep.enabled);
    QVERIFY(sameBits(sa.sleep.linearVelocity, sb.sleep.linearVelocity));
    QVERIFY(sameBits(sa.sleep.angularVelocity, sb.sleep.angularVelocity));
    QVERIFY(sameBits(sa.sleep.timeToSleep, sb.sleep.timeToSleep));
    QVERIFY(sa.effects == sb.effects);

    QCOMPARE(a.bodies.size(), b.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        const BodyCreationSettings& x = a.bodies[i].body;
        const BodyCreationSettings& y = b.bodies[i].body;
        QCOMPARE(x.name, y.name);
        QVERIFY(x.motion == y.motion);
        QVERIFY(x.shape.type == y.shape.type);
        switch (x.shape.type) {
            case ShapeType::Box: QVERIFY(sameBits(x.shape.halfExtents, y.shape.halfExtents)); break;
            case ShapeType::Sphere: QVERIFY(sameBits(x.shape.radius, y.shape.radius)); break;
            case ShapeType::Capsule:
            case ShapeType::Cylinder:
                QVERIFY(sameBits(x.shape.radius, y.shape.radius));
                QVERIFY(sameBits(x.shape.halfHeight, y.shape.halfHeight));
                break;
            case ShapeType::ConvexHull: {
                QVERIFY(x.shape.hull && y.shape.hull);
                const auto& px = x.shape.hull->sourcePoints();
                const auto& py = y.shape.hull->sourcePoints();
                QCOMPARE(px.size(), py.size());
                for (std::size_t k = 0; k < px.size(); ++k) QVERIFY(sameBits(px[k], py[k]));
                break;
            }
            case ShapeType::Compound: {
                QVERIFY(x.shape.compound && y.shape.compound);
                QCOMPARE(x.shape.compound->size(), y.shape.compound->size());
                break;
            }
            case ShapeType::Mesh: {
                QVERIFY(x.shape.mesh && y.shape.mesh);
                const auto& vx = x.shape.mesh->vertices();
                const auto& vy = y.shape.mesh->vertices();
                QCOMPARE(vx.size(), vy.size());
                for (std::size_t k = 0; k < vx.size(); ++k) QVERIFY(sameBits(vx[k], vy[k]));
                QVERIFY(x.shape.mesh->triangleIndices() == y.shape.mesh->triangleIndices());
                break;
            }
            case ShapeType::HeightField: {
                QVERIFY(x.shape.heightField && y.shape.heightField);
                QCOMPARE(x.shape.heightField->rows(), y.shape.heightField->rows());
                QCOMPARE(x.shape.heightField->columns(), y.shape.heightField->columns());
                QVERIFY(sameBits(x.shape.heightField->cellSize(), y.shape.heightField->cellSize()));
                QVERIFY(sameBits(x.shape.heightField->heightScale(), y.shape.heightField->heightScale()));
                const auto& hx = x.shape.heightField->heights();
                const auto& hy = y.shape.heightField->heights();
                QCOMPARE(hx.size(), hy.size());
                for (std::size_t k = 0; k < hx.size(); ++k) QVERIFY(sameBits(hx[k], hy[k]));
                break;
            }
        }
        QVERIFY(sameBits(x.position, y.position));
        QVERIFY(sameBits(x.orientation, y.orientation));
        QVERIFY(sameBits(x.linearVelocity, y.linearVelocity));
        QVERIFY(sameBits(x.angularVelocity, y.angularVelocity));
        QCOMPARE(x.mass.has_value(), y.mass.has_value());
        if (x.mass) QVERIFY(sameBits(*x.mass, *y.mass));
        else QVERIFY(sameBits(x.density, y.density));
        QVERIFY(sameBits(x.friction, y.friction));
        QVERIFY(sameBits(x.restitution, y.restitution));
        QVERIFY(sameBits(x.rollingResistance, y.rollingResistance));
        QCOMPARE(x.ccd, y.ccd);
        QCOMPARE(a.bodies[i].color.has_value(), b.bodies[i].color.has_value());
        if (a.bodies[i].color) QVERIFY(sameBits(*a.bodies[i].color, *b.bodies[i].color));
    }
}

SceneBody body(std::string name, Shape shape) {
    SceneBody b;
    b.body.name = std::move(name);
    b.body.shape = std::move(shape);
    return b;
}

// Every shape type, every motion type and floats that do not print nicely: 0.1, 1/3, 1e-7,
// 123456.789, negative zero, the smallest normal and denormal floats.
Scene awkwardScene() {
    Scene s;
    s.settings.gravity = Vec3(0.1f, -1.0f / 3.0f, 1e-7f);
    s.settings.timeStep = 1.0f / 60.0f;
    s.settings.substeps = 3;
    s.settings.integrator = Integrator::VelocityVerlet;
    s.settings.solver.velocityIterations = 17;
    s.settings.solver.positionIterations = 0;
    s.settings.solver.positionCorrection = PositionCorrection::Baumgarte;
    s.settings.solver.contactHertz = 45.5f;
    s.settings.solver.contactDampingRatio = 0.7f;
    s.settings.solver.maxPushVelocity = 1.0f / 3.0f;
    s.settings.solver.baumgarte = 0.15f;
    s.settings.contact.speculativeDistance = 0.035f;
    s.settings.contact.linearSlop = 1e-3f;
    s.settings.contact.restitutionThreshold = 0.25f;
    s.settings.damping.linear = 0.1f;
    s.settings.damping.angular = 1e-7f;
    s.settings.sleep.enabled = false;
    s.settings.sleep.linearVelocity = 0.0123f;
    s.settings.sleep.angularVelocity = 1.0f / 3.0f;
    s.settings.sleep.timeToSleep = 0.7f;
    s.settings.effects[Effect::Friction] = false;
    s.settings.effects[Effect::Ccd] = false;

    SceneBody box = body("box \"quoted\" / ünïcode", Shape::box(Vec3(0.1f, 1.0f / 3.0f, 12345.6789f)));
    box.body.position = Vec3(123456.789f, -0.0f, 1e-7f);
    box.body.orientation = glm::normalize(Quat(1.0f, 2.0f, 3.0f, 4.0f));
    box.body.density = 1234.5678f;
    box.body.friction = 0.1f;
    box.body.restitution = 1.0f / 3.0f;
    box.body.linearVelocity = Vec3(-0.0f, std::numeric_limits<float>::min(), std::numeric_limits<float>::denorm_min());
    box.body.angularVelocity = Vec3(1e-38f, -1e-40f, 3400.5f);
    box.color = Vec3(0.1f, 1.0f / 3.0f, 1.0f);
    s.bodies.push_back(box);

    SceneBody sphere = body("sphere", Shape::sphere(1.0f / 3.0f));
    sphere.body.mass = 1.0f / 3.0f;
    sphere.body.position = Vec3(0.1f, 0.2f, 0.3f);
    sphere.body.rollingResistance = 1.0f / 3.0f;
    s.bodies.push_back(sphere);

    SceneBody capsule = body("capsule", Shape::capsule(1e-4f, 0.30000001f));
    capsule.body.motion = MotionType::Kinematic;
    capsule.body.mass = 123456.789f;
    capsule.body.ccd = true;
    capsule.body.linearVelocity = Vec3(1e-7f, -2.5f, 0.0f);
    capsule.body.rollingResistance = std::numeric_limits<float>::denorm_min();
    s.bodies.push_back(capsule);

    SceneBody cylinder = body("cylinder", Shape::cylinder(99999.99f, 1e-3f));
    cylinder.body.motion = MotionType::Static;
    cylinder.body.orientation = glm::angleAxis(0.1f, glm::normalize(Vec3(1.0f, 1.0f, 0.0f)));
    cylinder.body.rollingResistance = -0.0f;  // zero, but its sign must survive the round trip too
    s.bodies.push_back(cylinder);

    const std::vector<Vec3> points{{0.0f, 0.0f, 0.0f},       {1.0f / 3.0f, -0.0f, 0.0f}, {0.0f, 0.1f, 1e-7f},
                                   {0.0f, 0.0f, 0.7f},       {0.05f, 0.02f, 0.1f},      {123.456f, 0.01f, 0.02f},
                                   {-1e-40f, 0.05f, 0.05f}};
    const ConvexHull::BuildResult hull = ConvexHull::build(points);
    if (hull.hull) {
        SceneBody rock = body("rock", Shape::convexHull(hull.hull));
        rock.body.friction = 0.0f;
        rock.body.restitution = 1.0f;
        rock.body.rollingResistance = 100.0f;  // the largest the format takes
        rock.color = Vec3(0.0f, 0.5f, 1e-7f);
        s.bodies.push_back(rock);
    }
    return s;
}

// The example of the brief's "Scene format v1 (normative)" section, verbatim.
const char* kBriefExample = R"json({
  "format": "interplay.scene", "version": 1,
  "settings": {
    "gravity": [0, -9.81, 0],
    "timeStep": 0.016666667,
    "substeps": 1,
    "solver": { "velocityIterations": 8, "positionIterations": 3 },
    "damping": { "linear": 0.0, "angular": 0.0 },
    "sleep": { "enabled": true },
    "effects": { "gravity": true, "contacts": true, "friction": true,
                 "restitution": true, "damping": true, "gyroscopic": true,
                 "joints": true, "ccd": true, "sleeping": true }
  },
  "bodies": [
    { "name": "ground", "motion": "static",
      "shape": { "type": "box", "halfExtents": [50, 0.5, 50] },
      "position": [0, -0.5, 0], "orientation": [1, 0, 0, 0],
      "friction": 0.6, "restitution": 0.0 },
    { "name": "ball", "motion": "dynamic",
      "shape": { "type": "sphere", "radius": 0.5 },
      "position": [0, 5, 0], "mass": 1.0,
      "linearVelocity": [0, 0, 0], "angularVelocity": [0, 0, 0] }
  ],
  "joints": []
})json";

std::string readFile(const QString& path) {
    std::ifstream in(path.toStdString(), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

}  // namespace

class TestSceneIo : public QObject {
    Q_OBJECT

private slots:
    // checkScene: what the loader would say about a scene in memory, at the path it would have.
    void checkSceneReportsWhatTheLoaderWould() {
        Scene scene = defaultScene();
        QVERIFY(checkScene(scene).empty());
        scene.settings.gravity.y = 1e9f;
        scene.bodies[1].body.friction = -1.0f;
        const std::vector<Diagnostic> found = checkScene(scene);
        QCOMPARE(found.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(found[0].path), QString("/settings/gravity/1"));
        QCOMPARE(QString::fromStdString(found[0].message),
                 QString("gravity[1] must be between -10000 and 10000 m/s^2, got 1e+09"));
        QCOMPARE(QString::fromStdString(found[1].path), QString("/bodies/1/friction"));
        QCOMPARE(found[1].severity, Diagnostic::Severity::Error);
        // The same scene saved and opened gives the same diagnostics.
        const SceneLoadResult loaded = parseScene(serializeScene(scene), "");
        QCOMPARE(loaded.diagnostics.size(), found.size());
        QCOMPARE(loaded.diagnostics[0].message, found[0].message);

        // A joint whose body is gone cannot be written at all: said so, not crashed on.
        Scene broken = defaultScene();
        SceneJoint joint;
        joint.bodyA = broken.bodies.size();
        broken.joints.push_back(joint);
        const std::vector<Diagnostic> missing = checkScene(broken);
        QCOMPARE(missing.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(missing[0].path), QString("/joints/0"));
    }

    void awkwardSceneHasEveryShape() {
        const Scene s = awkwardScene();
        QCOMPARE(s.bodies.size(), std::size_t(kShapeTypeCount));
    }

    void roundTripIsBitExact() {
        const Scene original = awkwardScene();
        const std::string text = serializeScene(original);
        const SceneLoadResult loaded = parseScene(text, "awkward.json");
        QVERIFY2(loaded.ok(), describe(loaded.diagnostics).c_str());
        QVERIFY2(loaded.diagnostics.empty(), describe(loaded.diagnostics).c_str());
        compareScenes(original, *loaded.scene);
        QCOMPARE(serializeScene(*loaded.scene), text);
    }

    // A compound's children keep every bit of their sizes and poses through save and load, and a
    // second save is byte-identical.
    void compoundRoundTripIsBitExact() {
        const Quat turned = glm::normalize(Quat(0.9f, 0.1f, -1.0f / 3.0f, 0.2f));
        std::vector<CompoundChild> children{
            {Shape::box(Vec3(0.1f, 1.0f / 3.0f, 2.5e-3f)), Transform{Vec3(1e-7f, -0.3f, 12345.679f), turned}},
            {Shape::cylinder(0.7f, 1.0f / 7.0f), Transform{Vec3(0.0f, 0.1f, 0.0f), Quat(1.0f, 0.0f, 0.0f, 0.0f)}}};
        Scene scene;
        SceneBody body;
        body.body.name = "compound";
        body.body.shape = Shape::compoundOf(std::make_shared<const CompoundShape>(children));
        scene.bodies.push_back(body);
        const std::string text = serializeScene(scene);
        const SceneLoadResult loaded = parseScene(text, "compound.json");
        QVERIFY2(loaded.ok() && loaded.diagnostics.empty(), describe(loaded.diagnostics).c_str());
        const Shape& shape = loaded.scene->bodies.front().body.shape;
        QVERIFY(shape.type == ShapeType::Compound && shape.compound);
        QCOMPARE(shape.compound->size(), children.size());
        for (std::size_t i = 0; i < children.size(); ++i) {
            const CompoundChild& child = shape.compound->children()[i];
            QVERIFY(child.shape.type == children[i].shape.type);
            QVERIFY(sameBits(child.shape.halfExtents, children[i].shape.halfExtents));
            QVERIFY(sameBits(child.shape.radius, children[i].shape.radius));
            QVERIFY(sameBits(child.shape.halfHeight, children[i].shape.halfHeight));
            QVERIFY(sameBits(child.pose.position, children[i].pose.position));
            QVERIFY(sameBits(child.pose.rotation, children[i].pose.rotation));
        }
        QCOMPARE(serializeScene(*loaded.scene), text);
    }

    void numbersAreWrittenShortest() {
        const std::string text = serializeScene(awkwardScene());
        QVERIFY(text.find("\"friction\": 0.1,") != std::string::npos);
        QVERIFY(text.find("\"gravity\": [0.1, -0.33333334, 1e-07]") != std::string::npos);
        QVERIFY(text.find("123456.79") != std::string::npos);  // the float nearest 123456.789
        QVERIFY(text.find("0.10000000149") == std::string::npos);
        QVERIFY(text.find("-0.0") != std::string::npos);
    }

    // Written only when set, so scenes without rolling resistance save exactly as they did before
    // the key existed; next to restitution when it is.
    void rollingResistanceIsWrittenWhenSet() {
        QVERIFY(serializeScene(defaultScene()).find("rollingResistance") == std::string::npos);
        const std::string text = serializeScene(awkwardScene());
        QVERIFY(text.find("\"restitution\": 0.0,\n      \"rollingResistance\": 0.33333334,") != std::string::npos);
        QVERIFY(text.find("\"rollingResistance\": -0.0") != std::string::npos);
        QVERIFY(text.find("\"rollingResistance\": 1e-45") != std::string::npos);
        QVERIFY(text.find("\"rollingResistance\": 100") != std::string::npos);
        const SceneLoadResult loaded = parseScene(
            R"({"format": "interplay.scene", "version": 1, "bodies": [
                {"shape": {"type": "sphere", "radius": 0.25}, "rollingResistance": 0.05}]})",
            "rolling.json");
        QVERIFY2(loaded.ok(), describe(loaded.diagnostics).c_str());
        QCOMPARE(loaded.scene->bodies[0].body.rollingResistance, 0.05f);
        // And the world takes it: a rolling ball's lever is C r.
        BuiltWorld built = buildWorld(*loaded.scene);
        QCOMPARE(built.world.rollingResistance(built.bodyIds[0]), 0.05f);
    }

    void keyOrderIsStable() {
        const std::string text = serializeScene(defaultScene());
        // Top-level keys are the ones indented by two spaces.
        const auto at = [&](const char* key) { return text.find("\n  \"" + std::string(key) + "\": "); };
        QVERIFY(at("format") < at("version"));
        QVERIFY(at("version") < at("settings"));
        QVERIFY(at("settings") < at("bodies"));
        QVERIFY(at("bodies") < at("joints"));
        QVERIFY(at("joints") != std::string::npos);
        QVERIFY(text.starts_with("{\n  \"format\": \"interplay.scene\",\n  \"version\": 1,\n"));
        QVERIFY(text.ends_with("\"joints\": []\n}\n"));
        // Every settings key is written.
        for (const char* key : {"gravity", "timeStep", "substeps", "velocityIterations", "positionIterations", "linear",
                                "angular", "enabled", "linearVelocity", "angularVelocity", "timeToSleep", "gyroscopic",
                                "sleeping", "ccd"})
            QVERIFY2(text.find("\"" + std::string(key) + "\"") != std::string::npos, key);
    }

    void saveLoadSaveIsByteIdentical() {
        for (const Scene& scene : {awkwardScene(), defaultScene(), Scene{}}) {
            const std::string first = serializeScene(scene);
            const SceneLoadResult loaded = parseScene(first, "s.json");
            QVERIFY2(loaded.ok(), describe(loaded.diagnostics).c_str());
            QCOMPARE(serializeScene(*loaded.scene), first);
        }
    }

    void briefExampleLoads() {
        const SceneLoadResult r = parseScene(kBriefExample, "brief.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY2(r.diagnostics.empty(), describe(r.diagnostics).c_str());
        const Scene& s = *r.scene;
        QVERIFY(s.settings.gravity == Vec3(0.0f, -9.81f, 0.0f));
        QCOMPARE(s.settings.timeStep, 0.016666667f);
        QCOMPARE(s.settings.substeps, 1);
        QCOMPARE(s.settings.solver.velocityIterations, 8);
        QCOMPARE(s.settings.solver.positionIterations, 3);
        QCOMPARE(s.settings.damping.linear, 0.0f);
        QCOMPARE(s.settings.damping.angular, 0.0f);
        QCOMPARE(s.settings.sleep.enabled, true);
        QVERIFY(s.settings.sleep == SleepSettings{});  // unspecified keys keep their defaults
        for (int i = 0; i < kEffectCount; ++i) QVERIFY(s.settings.effects.enabled[i]);

        QCOMPARE(s.bodies.size(), std::size_t(2));
        const BodyCreationSettings& ground = s.bodies[0].body;
        QCOMPARE(ground.name, std::string("ground"));
        QVERIFY(ground.motion == MotionType::Static);
        QVERIFY(ground.shape.type == ShapeType::Box);
        QVERIFY(ground.shape.halfExtents == Vec3(50.0f, 0.5f, 50.0f));
        QVERIFY(ground.position == Vec3(0.0f, -0.5f, 0.0f));
        QVERIFY(ground.orientation == Quat(1.0f, 0.0f, 0.0f, 0.0f));
        QCOMPARE(ground.friction, 0.6f);
        QCOMPARE(ground.restitution, 0.0f);
        QVERIFY(!ground.mass);
        QVERIFY(!s.bodies[0].color);

        const BodyCreationSettings& ball = s.bodies[1].body;
        QCOMPARE(ball.name, std::string("ball"));
        QVERIFY(ball.motion == MotionType::Dynamic);
        QVERIFY(ball.shape.type == ShapeType::Sphere);
        QCOMPARE(ball.shape.radius, 0.5f);
        QVERIFY(ball.position == Vec3(0.0f, 5.0f, 0.0f));
        QVERIFY(ball.mass && *ball.mass == 1.0f);
        QVERIFY(ball.linearVelocity == Vec3(0.0f));
        QVERIFY(ball.angularVelocity == Vec3(0.0f));
        QCOMPARE(ball.friction, 0.5f);    // default
        QCOMPARE(ball.restitution, 0.0f); // default
        QVERIFY(!ball.ccd);
    }

    void defaultsAndOptionalKeys() {
        const SceneLoadResult r = parseScene(
            R"({"format": "interplay.scene", "version": 1, "bodies": [
                {"shape": {"type": "capsule", "radius": 0.25, "halfHeight": 0.5}},
                {"motion": "kinematic", "shape": {"type": "cylinder", "radius": 1, "halfHeight": 2},
                 "density": 500, "ccd": true, "color": [1, 0.5, 0]}]})",
            "min.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY(r.diagnostics.empty());
        const Scene& s = *r.scene;
        QVERIFY(s.settings == WorldSettings{});
        QCOMPARE(s.bodies[0].body.name, std::string("body 0"));
        QCOMPARE(s.bodies[1].body.name, std::string("body 1"));
        QVERIFY(s.bodies[0].body.motion == MotionType::Dynamic);
        QCOMPARE(s.bodies[0].body.density, 1000.0f);
        QCOMPARE(s.bodies[0].body.rollingResistance, 0.0f);  // default
        QVERIFY(s.bodies[1].body.motion == MotionType::Kinematic);
        QCOMPARE(s.bodies[1].body.density, 500.0f);
        QVERIFY(s.bodies[1].body.ccd);
        QVERIFY(s.bodies[1].color && *s.bodies[1].color == Vec3(1.0f, 0.5f, 0.0f));
    }

    void nonUnitOrientationIsNormalised() {
        const SceneLoadResult r = parseScene(
            R"({"format": "interplay.scene", "version": 1, "bodies": [
                {"shape": {"type": "sphere", "radius": 1}, "orientation": [2, 0, 0, 0]},
                {"shape": {"type": "sphere", "radius": 1}, "orientation": [1.0000001, 0, 0, 0]}]})",
            "q.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));  // the small deviation is silent
        QVERIFY(r.diagnostics[0].severity == Diagnostic::Severity::Warning);
        QCOMPARE(r.diagnostics[0].path, std::string("/bodies/0/orientation"));
        QVERIFY(r.scene->bodies[0].body.orientation == Quat(1.0f, 0.0f, 0.0f, 0.0f));
    }

    // The editor's bookmarks come back bit for bit and in order; a scene without any writes no
    // "editor" object, so existing files save as they did.
    void cameraBookmarksRoundTrip() {
        Scene scene = defaultScene();
        QVERIFY(serializeScene(scene).find("\"editor\"") == std::string::npos);
        scene.editor.cameraBookmarks.push_back({"Top view", Vec3(0.1f, -1.0f / 3.0f, 2e6f / 3.0f), -359.5f, 89.0f, 1e-3f, true});
        scene.editor.cameraBookmarks.push_back({"ünïcode \"quoted\"", Vec3(0.0f), 35.0f, -22.0f, 12.0f, false});
        const std::string text = serializeScene(scene);
        const SceneLoadResult loaded = parseScene(text, "bookmarks.json");
        QVERIFY2(loaded.ok() && loaded.diagnostics.empty(), describe(loaded.diagnostics).c_str());
        const auto& read = loaded.scene->editor.cameraBookmarks;
        QCOMPARE(read.size(), std::size_t(2));
        for (std::size_t i = 0; i < read.size(); ++i) {
            const CameraBookmark& a = scene.editor.cameraBookmarks[i];
            QCOMPARE(read[i].name, a.name);
            QVERIFY(sameBits(read[i].target, a.target));
            QVERIFY(sameBits(read[i].yawDegrees, a.yawDegrees));
            QVERIFY(sameBits(read[i].pitchDegrees, a.pitchDegrees));
            QVERIFY(sameBits(read[i].distance, a.distance));
            QCOMPARE(read[i].orthographic, a.orthographic);
        }
        QCOMPARE(serializeScene(*loaded.scene), text);
        // What the engine simulates is the same with or without them.
        QVERIFY(checkScene(scene).empty());
    }

    void badCameraBookmarksAreErrorsAtTheirPath_data() {
        // QTest checks each value against its column type: the literals go in as QStrings.
        const auto row = [](const char* name, const QString& editor, const char* path, const char* message) {
            QTest::newRow(name) << editor << QString(path) << QString(message);
        };
        QTest::addColumn<QString>("editor");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("message");
        const QString good = R"("target": [0, 1, 0], "yaw": 30, "pitch": 20, "distance": 8)";
        row("not an object", QString(R"([])"), "/editor", "expected an object");
        row("list not an array", QString(R"({"cameraBookmarks": {}})"), "/editor/cameraBookmarks", "expected an array");
        row("no name", QString("{\"cameraBookmarks\": [{" + good + "}]}"), "/editor/cameraBookmarks/0/name", "missing");
        row("empty name", QString("{\"cameraBookmarks\": [{\"name\": \"\", " + good + "}]}"), "/editor/cameraBookmarks/0/name", "a bookmark needs a name");
        row("long name", QString("{\"cameraBookmarks\": [{\"name\": \"" + QString(201, 'x') + "\", " + good + "}]}"), "/editor/cameraBookmarks/0/name", "at most 200 bytes, got 201");
        row("pitch past the pole", QString(R"({"cameraBookmarks": [{"name": "a", "target": [0, 1, 0], "yaw": 30, "pitch": 90.5, "distance": 8}]})"), "/editor/cameraBookmarks/0/pitch", "between -90 and 90 degrees, got 90.5");
        row("zero distance", QString(R"({"cameraBookmarks": [{"name": "a", "target": [0, 1, 0], "yaw": 30, "pitch": 20, "distance": 0}]})"), "/editor/cameraBookmarks/0/distance", "got 0");
        row("no target", QString(R"({"cameraBookmarks": [{"name": "a", "yaw": 30, "pitch": 20, "distance": 8}]})"), "/editor/cameraBookmarks/0/target", "missing");
        row("orthographic not a bool", QString("{\"cameraBookmarks\": [{\"name\": \"a\", \"orthographic\": 1, " + good + "}]}"), "/editor/cameraBookmarks/0/orthographic", "expected");
        QString many = "{\"cameraBookmarks\": [";
        for (int i = 0; i <= int(kMaxCameraBookmarks); ++i) many += QString(i ? ", " : "") + "{\"name\": \"a\", " + good + "}";
        row("too many", QString(many + "]}"), "/editor/cameraBookmarks", "at most 100 camera bookmarks, got 101");
    }

    void badCameraBookmarksAreErrorsAtTheirPath() {
        QFETCH(QString, editor);
        QFETCH(QString, path);
        QFETCH(QString, message);
        const std::string text = R"({"format": "interplay.scene", "version": 1, "bodies": [], "editor": )" +
                                 editor.toStdString() + "}";
        const SceneLoadResult r = parseScene(text, "bad.json");
        QVERIFY(!r.ok());
        QVERIFY2(!r.diagnostics.empty(), text.c_str());
        const Diagnostic& d = r.diagnostics.front();
        QCOMPARE(d.severity, Diagnostic::Severity::Error);
        QCOMPARE(QString::fromStdString(d.path), path);
        QVERIFY2(QString::fromStdString(d.message).contains(message), d.toString().c_str());
    }

    void unknownKeysAreWarnings() {
        const SceneLoadResult r = parseScene(
            R"({"format": "interplay.scene", "version": 1, "extra": 1,
                "settings": {"solver": {"velocityIterations": 4, "foo": 2}, "effects": {"magic": true}},
                "bodies": [{"shape": {"type": "box", "halfExtents": [1, 1, 1], "radius": 2}, "bar": "x"}]})",
            "unknown.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QCOMPARE(r.scene->settings.solver.velocityIterations, 4);
        std::vector<std::string> paths;
        for (const Diagnostic& d : r.diagnostics) {
            QVERIFY(d.severity == Diagnostic::Severity::Warning);
            QCOMPARE(d.file, std::string("unknown.json"));
            QVERIFY(d.toString().starts_with("unknown.json: warning at " + d.path + ": unknown key"));
            paths.push_back(d.path);
        }
        const std::vector<std::string> expected{"/extra", "/settings/solver/foo", "/settings/effects/magic",
                                                "/bodies/0/bar", "/bodies/0/shape/radius"};
        QCOMPARE(paths.size(), expected.size());
        for (const std::string& p : expected)
            QVERIFY2(std::find(paths.begin(), paths.end(), p) != paths.end(), p.c_str());
    }

    void duplicateKeysAreWarnings() {
        const SceneLoadResult r = parseScene(
            R"({"format": "interplay.scene", "version": 1, "bodies": [{"shape": {"type": "sphere", "radius": 1, "radius": 2}}]})",
            "dup.json");
        QVERIFY(r.ok());
        QCOMPARE(r.scene->bodies[0].body.shape.radius, 2.0f);
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].path, std::string("/bodies/0/shape/radius"));
    }

    void diagnosticFormats() {
        Diagnostic d;
        d.file = "a.json";
        d.line = 3;
        d.column = 7;
        d.message = "bad";
        QCOMPARE(d.toString(), std::string("a.json:3:7: error: bad"));
        d.line = d.column = 0;
        d.path = "/bodies/3/shape/radius";
        QCOMPARE(d.toString(), std::string("a.json: error at /bodies/3/shape/radius: bad"));
        d.severity = Diagnostic::Severity::Warning;
        QCOMPARE(d.toString(), std::string("a.json: warning at /bodies/3/shape/radius: bad"));
        d.path.clear();
        d.severity = Diagnostic::Severity::Error;
        QCOMPARE(d.toString(), std::string("a.json: error: bad"));
    }

    void syntaxErrorPosition() {
        const SceneLoadResult r = parseScene("{\n  \"format\": \"interplay.scene\",\n  \"version\": 1,\n  \"bodies\": [1,,]\n}",
                                             "syn.json");
        QVERIFY(!r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].line, 4);
        QCOMPARE(r.diagnostics[0].column, 16);
        QVERIFY(r.diagnostics[0].toString().starts_with("syn.json:4:16: error: "));
    }

    void loadSceneFileErrors() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string missing = dir.filePath("missing.json").toStdString();
        SceneLoadResult r = loadSceneFile(missing);
        QVERIFY(!r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QVERIFY(r.diagnostics[0].toString().starts_with(missing + ": error: "));
        QVERIFY(r.diagnostics[0].message.find("No such file") != std::string::npos);

        r = loadSceneFile(dir.path().toStdString());
        QVERIFY(!r.ok());
        QVERIFY(r.diagnostics[0].message.find("directory") != std::string::npos);

        const QString good = dir.filePath("good.json");
        writeFile(good, kBriefExample);
        r = loadSceneFile(good.toStdString());
        QVERIFY(r.ok());
        QCOMPARE(r.scene->bodies.size(), std::size_t(2));
    }

    void saveWritesAndReplaces() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("scene.json");
        QVERIFY(!saveSceneFile(defaultScene(), path.toStdString()));
        QCOMPARE(readFile(path), serializeScene(defaultScene()));
        const Scene awkward = awkwardScene();
        QVERIFY(!saveSceneFile(awkward, path.toStdString()));
        QCOMPARE(readFile(path), serializeScene(awkward));
        QCOMPARE(entries(dir.path()), QStringList{"scene.json"});  // no temporary left behind

        const SceneLoadResult r = loadSceneFile(path.toStdString());
        QVERIFY(r.ok());
        compareScenes(awkward, *r.scene);

        // Through a symbolic link: the file it points to is replaced, the link stays a link.
        const QString link = dir.filePath("link.json");
        QVERIFY(QFile::link(path, link));
        QVERIFY(!saveSceneFile(defaultScene(), link.toStdString()));
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(readFile(path), serializeScene(defaultScene()));
        QCOMPARE(entries(dir.path()), (QStringList{"link.json", "scene.json"}));
    }

    void saveFailuresLeaveExistingFilesAlone() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const Scene scene = defaultScene();

        // Into a directory that does not exist.
        const std::string missingDir = dir.filePath("no/such/dir/scene.json").toStdString();
        auto error = saveSceneFile(scene, missingDir);
        QVERIFY(error);
        QVERIFY2(error->find(missingDir) != std::string::npos, error->c_str());
        QVERIFY2(error->find("No such file or directory") != std::string::npos, error->c_str());

        // Below a regular file (tests run as root, so permissions cannot be used to make saves fail).
        const QString plainFile = dir.filePath("plain.txt");
        writeFile(plainFile, "keep me");
        error = saveSceneFile(scene, (plainFile + "/scene.json").toStdString());
        QVERIFY(error);
        QVERIFY2(error->find("Not a directory") != std::string::npos, error->c_str());
        QCOMPARE(readFile(plainFile), std::string("keep me"));

        // Onto a directory.
        QVERIFY(QDir(dir.path()).mkdir("adir.json"));
        error = saveSceneFile(scene, dir.filePath("adir.json").toStdString());
        QVERIFY(error);
        QVERIFY2(error->find("adir.json") != std::string::npos, error->c_str());
        QVERIFY(QFileInfo(dir.filePath("adir.json")).isDir());

        // Over an existing file whose temporary sibling cannot be created (its name would exceed the
        // file system's 255-byte limit): the existing file must be untouched.
        const QString longName = QString(240, QChar('n')) + ".json";
        const QString existing = dir.filePath(longName);
        writeFile(existing, "original content");
        QVERIFY(QFileInfo::exists(existing));
        error = saveSceneFile(scene, existing.toStdString());
        QVERIFY(error);
        QVERIFY2(error->find("cannot save '" + existing.toStdString() + "'") != std::string::npos, error->c_str());
        QCOMPARE(readFile(existing), std::string("original content"));

        // Nothing half-written anywhere.
        QCOMPARE(entries(dir.path()), (QStringList{"adir.json", longName, "plain.txt"}));
    }

    void settingOverrides() {
        Scene scene = defaultScene();
        QVERIFY(!applySettingOverride(scene, "solver.velocityIterations=20"));
        QCOMPARE(scene.settings.solver.velocityIterations, 20);
        QVERIFY(!applySettingOverride(scene, "gravity=[0,-1.62,0]"));
        QVERIFY(scene.settings.gravity == Vec3(0.0f, -1.62f, 0.0f));
        QVERIFY(!applySettingOverride(scene, "gravity.0=0.5"));
        QVERIFY(scene.settings.gravity == Vec3(0.5f, -1.62f, 0.0f));
        QVERIFY(!applySettingOverride(scene, "effects.friction=false"));
        QVERIFY(!scene.settings.effects[Effect::Friction]);
        QVERIFY(!applySettingOverride(scene, "timeStep=0.01"));
        QCOMPARE(scene.settings.timeStep, 0.01f);
        QVERIFY(!applySettingOverride(scene, "sleep={\"enabled\": false, \"timeToSleep\": 2}"));
        QVERIFY(!scene.settings.sleep.enabled);
        QCOMPARE(scene.settings.sleep.timeToSleep, 2.0f);

        const WorldSettings before = scene.settings;
        auto error = applySettingOverride(scene, "solver.foo=1");
        QVERIFY(error);
        QVERIFY2(error->find("unknown setting 'solver.foo'") != std::string::npos, error->c_str());
        error = applySettingOverride(scene, "substeps=0");
        QVERIFY(error);
        QVERIFY2(error->find("'substeps'") != std::string::npos && error->find("between 1 and 64") != std::string::npos,
                 error->c_str());
        error = applySettingOverride(scene, "effects.friction=maybe");
        QVERIFY(error);
        QVERIFY2(error->find("'effects.friction'") != std::string::npos, error->c_str());
        error = applySettingOverride(scene, "timeStep=1e999");
        QVERIFY(error);
        QVERIFY2(error->find("'timeStep'") != std::string::npos, error->c_str());
        error = applySettingOverride(scene, "gravity=[0,1]");
        QVERIFY(error);
        QVERIFY2(error->find("'gravity'") != std::string::npos, error->c_str());
        error = applySettingOverride(scene, "solver={\"velocityIterations\": 5, \"bogus\": 1}");
        QVERIFY(error);
        QVERIFY(applySettingOverride(scene, "novalue"));
        QVERIFY(applySettingOverride(scene, "=3"));
        QVERIFY(applySettingOverride(scene, "gravity.3=1"));
        QVERIFY(scene.settings == before);  // failures change nothing
    }

    void buildWorldMatchesScene() {
        const SceneLoadResult r = parseScene(kBriefExample, "brief.json");
        QVERIFY(r.ok());
        Scene scene = *r.scene;
        SceneBody cube = body("cube", Shape::box(Vec3(0.5f)));
        cube.body.position = Vec3(3.0f, 2.0f, 1.0f);
        scene.bodies.push_back(cube);

        BuiltWorld built = buildWorld(scene);
        QCOMPARE(built.world.bodyCount(), scene.bodies.size());
        QCOMPARE(built.bodyIds.size(), scene.bodies.size());
        QVERIFY(built.world.settings() == scene.settings);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const BodyId id = built.bodyIds[i];
            QVERIFY(built.world.contains(id));
            QCOMPARE(built.world.name(id), scene.bodies[i].body.name);
            QVERIFY(built.world.position(id) == scene.bodies[i].body.position);
            QVERIFY(built.world.motionType(id) == scene.bodies[i].body.motion);
        }
        QCOMPARE(built.world.mass(built.bodyIds[1]), 1.0f);
        QVERIFY(qAbs(built.world.mass(built.bodyIds[2]) - 1000.0f) < 1e-2f);  // density 1000, 1 m^3
    }

    void buildWorldNamesTheBadBody() {
        Scene scene;
        SceneBody bad = body("broken", Shape::sphere(-1.0f));
        scene.bodies.push_back(body("fine", Shape::sphere(1.0f)));
        scene.bodies.push_back(bad);
        try {
            buildWorld(scene);
            QFAIL("expected an exception");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find("body 1 ('broken')") != std::string::npos, e.what());
        }
    }

    void defaultSceneHasEveryShape() {
        const Scene scene = defaultScene();
        QVERIFY(scene.settings == WorldSettings{});
        QVERIFY(!scene.bodies.empty());
        const BodyCreationSettings& ground = scene.bodies[0].body;
        QVERIFY(ground.motion == MotionType::Static);
        QVERIFY(ground.shape.type == ShapeType::Box);
        QVERIFY(ground.shape.halfExtents == Vec3(20.0f, 0.5f, 20.0f));
        QVERIFY(ground.position == Vec3(0.0f, -0.5f, 0.0f));

        int perType[kShapeTypeCount] = {};
        for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
            const SceneBody& b = scene.bodies[i];
            QVERIFY(b.body.motion == MotionType::Dynamic);
            QVERIFY(b.color.has_value());
            QVERIFY(worldBounds(b.body.shape, Transform{b.body.position, b.body.orientation}).min.y > 0.0f);  // above the ground
            ++perType[static_cast<int>(b.body.shape.type)];
        }
        for (int t = 0; t < kShapeTypeCount; ++t) QCOMPARE(perType[t], 1);

        BuiltWorld built = buildWorld(scene);
        QCOMPARE(built.world.bodyCount(), scene.bodies.size());
        for (int i = 0; i < 10; ++i) built.world.step();
        QVERIFY(!built.world.findNonFiniteBody());
    }
};

QTEST_APPLESS_MAIN(TestSceneIo)
#include "test_scene_io.moc"
