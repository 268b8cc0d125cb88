// Import of the thesis app's scene format: every object type, the settings mapping, the Euler
// convention, warnings and errors, and conversion to v1.

#include "simcore/io/scene.h"
#include "simcore/io/scene_io.h"

#include <QtTest>

#include <bit>
#include <cmath>

using namespace simcore;

namespace {

const std::string kSourceDir = INTERPLAY_SOURCE_DIR;

std::string describe(const std::vector<Diagnostic>& diagnostics) {
    std::string s;
    for (const Diagnostic& d : diagnostics) s += d.toString() + "\n";
    return s;
}

bool near(float a, float b, float tolerance = 1e-5f) { return std::abs(a - b) <= tolerance; }
bool near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
    return near(a.x, b.x, tolerance) && near(a.y, b.y, tolerance) && near(a.z, b.z, tolerance);
}
// q and -q are the same rotation.
bool sameRotation(const Quat& a, const Quat& b) { return std::abs(glm::dot(a, b)) > 1.0f - 1e-6f; }

const Diagnostic* findDiagnostic(const SceneLoadResult& r, const std::string& path) {
    for (const Diagnostic& d : r.diagnostics)
        if (d.path == path) return &d;
    return nullptr;
}

// A thesis scene with one object; `object` is the object's JSON members.
std::string oneObject(const std::string& object, const std::string& settings = "{}") {
    return R"({"settings": )" + settings + R"(, "objects": [{)" + object + "}]}";
}

const Vec3 kX(1.0f, 0.0f, 0.0f), kY(0.0f, 1.0f, 0.0f), kZ(0.0f, 0.0f, 1.0f);

}  // namespace

class TestThesisImport : public QObject {
    Q_OBJECT

private slots:
    void everyObjectType() {
        const SceneLoadResult r = loadSceneFile(kSourceDir + "/tests/data/thesis/every_type.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY2(r.diagnostics.empty(), describe(r.diagnostics).c_str());
        const Scene& s = *r.scene;

        // Settings.
        QVERIFY(s.settings.gravity == Vec3(0.0f, -20.0f, 0.0f));
        QVERIFY(near(s.settings.damping.linear, static_cast<float>(-std::log(0.9)), 1e-7f));
        QVERIFY(near(s.settings.damping.angular, static_cast<float>(-std::log(0.8)), 1e-7f));
        QCOMPARE(s.settings.solver.velocityIterations, 7);
        QCOMPARE(s.settings.solver.positionIterations, 5);
        QVERIFY(near(s.settings.sleep.linearVelocity, 0.2f, 1e-7f));  // sqrt(0.04)
        QVERIFY(near(s.settings.sleep.angularVelocity, 0.2f, 1e-7f));

        QCOMPARE(s.bodies.size(), std::size_t(7));
        const auto& floor = s.bodies[0].body;
        const auto& crate = s.bodies[1].body;
        const auto& plank = s.bodies[2].body;
        const auto& ball = s.bodies[3].body;
        const auto& drum = s.bodies[4].body;
        const auto& pill = s.bodies[5].body;
        const auto& pedestal = s.bodies[6].body;

        // The floor: a wall 40 x 40 x 1 pitched 90 degrees, its top face horizontal at y = 0.
        QCOMPARE(floor.name, std::string("floor"));
        QVERIFY(floor.motion == MotionType::Static);
        QVERIFY(floor.shape.type == ShapeType::Box);
        QVERIFY(floor.shape.halfExtents == Vec3(20.0f, 20.0f, 0.5f));
        QVERIFY(floor.position == Vec3(0.0f, -0.5f, 0.0f));
        const Vec3 thinAxis = floor.orientation * kZ;
        QVERIFY(near(std::abs(thinAxis.y), 1.0f, 1e-6f));  // thin axis vertical: the top face is horizontal
        const Aabb floorBounds = worldBounds(floor.shape, Transform{floor.position, floor.orientation});
        QVERIFY(near(floorBounds.max.y, 0.0f, 1e-5f));
        QVERIFY(near(floorBounds.min.y, -1.0f, 1e-5f));
        QVERIFY(near(floorBounds.max.x, 20.0f, 1e-4f));
        QVERIFY(near(floorBounds.max.z, 20.0f, 1e-4f));
        QCOMPARE(floor.friction, 0.6f);
        QCOMPARE(floor.restitution, 0.1f);

        QVERIFY(crate.motion == MotionType::Dynamic);
        QVERIFY(crate.shape.type == ShapeType::Box);
        QVERIFY(crate.shape.halfExtents == Vec3(0.5f));
        QVERIFY(crate.mass && *crate.mass == 2.0f);
        QCOMPARE(crate.friction, 0.3f);
        QCOMPARE(crate.restitution, 0.0f);
        QVERIFY(sameRotation(crate.orientation, glm::angleAxis(glm::radians(30.0f), kY)));
        QVERIFY(crate.position == Vec3(-4.0f, 1.0f, 0.0f));

        QVERIFY(plank.shape.type == ShapeType::Box);
        QVERIFY(plank.shape.halfExtents == Vec3(0.25f, 0.25f, 1.5f));
        QVERIFY(plank.mass && *plank.mass == 4.0f);
        QCOMPARE(plank.friction, 0.6f);     // defaultFrictionCoef
        QCOMPARE(plank.restitution, 0.1f);  // defaultRestitutionCoef

        QVERIFY(ball.shape.type == ShapeType::Sphere);
        QCOMPARE(ball.shape.radius, 0.4f);
        QVERIFY(ball.mass && *ball.mass == 32.0f);  // defaultMass
        QCOMPARE(ball.friction, 0.9f);
        QCOMPARE(ball.restitution, 0.7f);

        QVERIFY(drum.shape.type == ShapeType::Cylinder);
        QCOMPARE(drum.shape.radius, 0.3f);
        QCOMPARE(drum.shape.halfHeight, 0.6f);
        QVERIFY(drum.mass && *drum.mass == 8.0f);
        QVERIFY(sameRotation(drum.orientation, glm::angleAxis(glm::radians(45.0f), kY)));

        QVERIFY(pill.shape.type == ShapeType::Capsule);
        QCOMPARE(pill.shape.radius, 0.25f);
        QCOMPARE(pill.shape.halfHeight, 0.5f);
        QVERIFY(pill.mass && *pill.mass == 1.5f);
        QVERIFY(near(pill.orientation * kY, -kX, 1e-6f));  // roll 90: lying along x

        QVERIFY(pedestal.motion == MotionType::Static);
        QVERIFY(pedestal.shape.halfExtents == Vec3(1.0f, 0.5f, 1.0f));

        for (const SceneBody& b : s.bodies) QVERIFY(!b.color);

        // It builds and simulates.
        BuiltWorld built = buildWorld(s);
        QCOMPARE(built.world.bodyCount(), std::size_t(7));
        for (int i = 0; i < 5; ++i) built.world.step();
        QVERIFY(!built.world.findNonFiniteBody());
    }

    void savedAsV1KeepsEverything() {
        const SceneLoadResult thesis = loadSceneFile(kSourceDir + "/tests/data/thesis/every_type.json");
        QVERIFY(thesis.ok());
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("converted.json").toStdString();
        QVERIFY(!saveSceneFile(*thesis.scene, path));

        const SceneLoadResult v1 = loadSceneFile(path);
        QVERIFY2(v1.ok(), describe(v1.diagnostics).c_str());
        QVERIFY(v1.diagnostics.empty());
        QVERIFY(v1.scene->settings == thesis.scene->settings);
        QCOMPARE(v1.scene->bodies.size(), thesis.scene->bodies.size());
        for (std::size_t i = 0; i < v1.scene->bodies.size(); ++i) {
            const BodyCreationSettings& a = thesis.scene->bodies[i].body;
            const BodyCreationSettings& b = v1.scene->bodies[i].body;
            QCOMPARE(b.name, a.name);
            QVERIFY(b.motion == a.motion);
            QVERIFY(b.shape.type == a.shape.type);
            QVERIFY(b.shape.halfExtents == a.shape.halfExtents || a.shape.type != ShapeType::Box);
            QCOMPARE(std::bit_cast<std::uint32_t>(b.shape.radius), std::bit_cast<std::uint32_t>(a.shape.radius));
            QCOMPARE(std::bit_cast<std::uint32_t>(b.shape.halfHeight), std::bit_cast<std::uint32_t>(a.shape.halfHeight));
            QVERIFY(b.position == a.position);
            QVERIFY(b.orientation == a.orientation);  // bit-exact, not just the same rotation
            QCOMPARE(b.mass.has_value(), a.mass.has_value());
            if (a.mass) QCOMPARE(*b.mass, *a.mass);
            QCOMPARE(b.density, a.density);
            QCOMPARE(b.friction, a.friction);
            QCOMPARE(b.restitution, a.restitution);
        }
        QCOMPARE(serializeScene(*v1.scene), serializeScene(*thesis.scene));
    }

    void eulerConvention() {
        // pitch about X, yaw about Y, roll about Z, composed as yaw * pitch * roll.
        auto orientation = [](const std::string& angles) {
            const SceneLoadResult r = parseScene(oneObject(R"("type": "box", "orientation": )" + angles), "e.json");
            return r.ok() ? r.scene->bodies[0].body.orientation : Quat(0.0f, 0.0f, 0.0f, 0.0f);
        };
        const Quat pitch = orientation(R"({"pitch": 90})");
        QVERIFY(near(pitch * kY, kZ, 1e-6f));
        QVERIFY(near(pitch * kZ, -kY, 1e-6f));
        const Quat yaw = orientation(R"({"yaw": 90})");
        QVERIFY(near(yaw * kX, -kZ, 1e-6f));
        const Quat roll = orientation(R"({"roll": 90})");
        QVERIFY(near(roll * kX, kY, 1e-6f));
        // Composition: roll first, then pitch, then yaw.
        const Quat both = orientation(R"({"pitch": 90, "yaw": 90})");
        QVERIFY(near(both * kY, kX, 1e-6f));
        QVERIFY(near(both * kZ, -kY, 1e-6f));
        const Quat all = orientation(R"({"pitch": 30, "yaw": -70, "roll": 125})");
        const Quat expected = glm::angleAxis(glm::radians(-70.0f), kY) * glm::angleAxis(glm::radians(30.0f), kX) *
                              glm::angleAxis(glm::radians(125.0f), kZ);
        QVERIFY(sameRotation(all, expected));
        QVERIFY(near(glm::length(all), 1.0f, 1e-6f));
    }

    // The floor object of the thesis's appendix, with the app's settings as printed there.
    void appendixExample() {
        const char* text = R"({
            "settings": {
                "damping": {"linear": 0.9, "angular": 0.9},
                "forceMultipliers": {"torque": 1.0, "force": 1.0, "impulse": 1.0},
                "gjkepa": {"gjkMaxIters": 100, "epaMaxIters": 50},
                "collisionResolution": {"penMaxIterations": 5, "velMaxIterations": 5,
                    "minVelocityForRestitution": 0.25, "angularMovementLimitFactor": 0.2,
                    "persistentContactDistanceThreshold": 0.001, "coefInterpAlpha": 0.5},
                "rigidBodies": {"defaultMass": 32.0, "defaultRestitutionCoef": 0.1, "defaultFrictionCoef": 0.6,
                    "sleepMotionThreshold": 0.1},
                "gravity": {"x": 0.0, "y": -20.0, "z": 0.0},
                "timeScale": 1.0,
                "rendering": {"renderColliders": true, "renderContacts": true, "renderContactNormals": true,
                    "renderSpawner": true, "renderSelection": true}
            },
            "objects": [{"type": "wall", "name": "floor",
                "position": {"x": 0.0, "y": -0.5, "z": 0.0}, "scale": {"x": 20.0, "y": 20.0, "z": 1.0},
                "orientation": {"pitch": 90.0, "yaw": 0.0, "roll": 0.0},
                "frictionCoef": 0.6, "restitutionCoef": 0.1, "mass": -1.0}]
        })";
        const SceneLoadResult r = parseScene(text, "appendix.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY2(r.diagnostics.empty(), describe(r.diagnostics).c_str());
        QCOMPARE(r.scene->settings.solver.velocityIterations, 5);
        QVERIFY(near(r.scene->settings.damping.linear, 0.1053605f, 1e-6f));
        QVERIFY(near(r.scene->settings.sleep.linearVelocity, std::sqrt(0.1f), 1e-6f));
        const BodyCreationSettings& floor = r.scene->bodies[0].body;
        QVERIFY(floor.motion == MotionType::Static);
        QVERIFY(near(worldBounds(floor.shape, Transform{floor.position, floor.orientation}).max.y, 0.0f));
    }

    void missingSettingsUseV1Defaults() {
        const SceneLoadResult r = parseScene(R"({"objects": [{"type": "sphere"}]})", "bare.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY(r.scene->settings == WorldSettings{});
        const BodyCreationSettings& b = r.scene->bodies[0].body;
        QCOMPARE(b.name, std::string("sphere 0"));
        QCOMPARE(b.shape.radius, 0.5f);  // unit scale
        QVERIFY(!b.mass);
        QCOMPARE(b.density, 1000.0f);
        QCOMPARE(b.friction, 0.5f);
        QCOMPARE(b.restitution, 0.0f);
        QVERIFY(b.position == Vec3(0.0f));
        QVERIFY(b.orientation == Quat(1.0f, 0.0f, 0.0f, 0.0f));
    }

    void fullRetentionIsNoDamping() {
        const SceneLoadResult r = parseScene(
            oneObject(R"("type": "box")", R"({"damping": {"linear": 1.0, "angular": 1}})"), "d.json");
        QVERIFY(r.ok());
        // +0, not -0 = -ln(1): saved files should say 0.0.
        QCOMPARE(std::bit_cast<std::uint32_t>(r.scene->settings.damping.linear), 0u);
        QCOMPARE(std::bit_cast<std::uint32_t>(r.scene->settings.damping.angular), 0u);
    }

    void warnings() {
        const SceneLoadResult r = parseScene(
            R"({"settings": {"timeScale": 2.0, "shadows": true},
                "objects": [{"type": "sphere", "scale": {"x": 1, "y": 2, "z": 1}, "color": "red"},
                            {"type": "wall", "mass": 5},
                            {"type": "capsule", "scale": {"x": 1, "y": 2, "z": 3}}],
                "camera": {}})",
            "warn.json");
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        for (const Diagnostic& d : r.diagnostics) QVERIFY(d.severity == Diagnostic::Severity::Warning);
        for (const char* path : {"/settings/timeScale", "/settings/shadows", "/objects/0/scale", "/objects/0/color",
                                 "/objects/1/mass", "/objects/2/scale", "/camera"})
            QVERIFY2(findDiagnostic(r, path), (std::string(path) + "\n" + describe(r.diagnostics)).c_str());
        QCOMPARE(r.diagnostics.size(), std::size_t(7));
        QVERIFY(r.scene->bodies[1].body.motion == MotionType::Static);  // walls are always static
        QCOMPARE(r.scene->bodies[0].body.shape.radius, 0.5f);
        QCOMPARE(r.scene->bodies[2].body.shape.radius, 0.5f);
        QCOMPARE(r.scene->bodies[2].body.shape.halfHeight, 1.0f);
    }

    void errors_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("message");
        QTest::newRow("negative scale") << QString::fromStdString(oneObject(R"("type": "box", "scale": {"x": 1, "y": -1, "z": 1})"))
                                        << "/objects/0/scale/y" << "scale.y must be positive";
        QTest::newRow("tiny scale") << QString::fromStdString(oneObject(R"("type": "box", "scale": {"x": 1e-9, "y": 1, "z": 1})"))
                                    << "/objects/0/scale/x" << "at least";
        QTest::newRow("scale missing z") << QString::fromStdString(oneObject(R"("type": "box", "scale": {"x": 1, "y": 1})"))
                                         << "/objects/0/scale/z" << "missing";
        QTest::newRow("unknown type") << QString::fromStdString(oneObject(R"("type": "cone")")) << "/objects/0/type"
                                      << "unknown object type 'cone'";
        QTest::newRow("missing type") << QString::fromStdString(oneObject(R"("name": "x")")) << "/objects/0/type"
                                      << "missing";
        QTest::newRow("mass zero") << QString::fromStdString(oneObject(R"("type": "box", "mass": 0)")) << "/objects/0/mass"
                                   << "positive";
        QTest::newRow("mass -2") << QString::fromStdString(oneObject(R"("type": "box", "mass": -2)")) << "/objects/0/mass"
                                 << "-1 for a static object";
        QTest::newRow("mass string") << QString::fromStdString(oneObject(R"("type": "box", "mass": "heavy")"))
                                     << "/objects/0/mass" << "expected a number, got a string";
        QTest::newRow("friction") << QString::fromStdString(oneObject(R"("type": "box", "frictionCoef": -0.5)"))
                                  << "/objects/0/frictionCoef" << "must not be negative";
        QTest::newRow("restitution") << QString::fromStdString(oneObject(R"("type": "box", "restitutionCoef": 1.5)"))
                                     << "/objects/0/restitutionCoef" << "at most 1";
        QTest::newRow("position as array") << QString::fromStdString(oneObject(R"("type": "box", "position": [0, 1, 0])"))
                                           << "/objects/0/position" << "expected an object";
        QTest::newRow("pitch string") << QString::fromStdString(oneObject(R"("type": "box", "orientation": {"pitch": "up"})"))
                                      << "/objects/0/orientation/pitch" << "expected a number";
        QTest::newRow("damping zero") << QString::fromStdString(oneObject(R"("type": "box")", R"({"damping": {"linear": 0}})"))
                                      << "/settings/damping/linear" << "positive";
        QTest::newRow("damping above one")
            << QString::fromStdString(oneObject(R"("type": "box")", R"({"damping": {"angular": 1.5}})"))
            << "/settings/damping/angular" << "at most 1";
        QTest::newRow("gravity array") << QString::fromStdString(oneObject(R"("type": "box")", R"({"gravity": [0, -9.81, 0]})"))
                                       << "/settings/gravity" << "expected an object";
        QTest::newRow("iterations") << QString::fromStdString(oneObject(R"("type": "box")", R"({"collisionResolution": {"velMaxIterations": 0}})"))
                                    << "/settings/collisionResolution/velMaxIterations" << "between 1 and 1000";
        QTest::newRow("default mass") << QString::fromStdString(oneObject(R"("type": "box")", R"({"rigidBodies": {"defaultMass": -1}})"))
                                      << "/settings/rigidBodies/defaultMass" << "positive";
        QTest::newRow("objects not array") << R"({"objects": {"type": "box"}})" << "/objects" << "expected an array";
        QTest::newRow("object not object") << R"({"objects": [42]})" << "/objects/0" << "expected an object";
    }

    void errors() {
        QFETCH(QString, text);
        QFETCH(QString, path);
        QFETCH(QString, message);
        const SceneLoadResult r = parseScene(text.toStdString(), "bad.json");
        QVERIFY(!r.ok());
        const Diagnostic* d = findDiagnostic(r, path.toStdString());
        QVERIFY2(d, describe(r.diagnostics).c_str());
        QVERIFY(d->severity == Diagnostic::Severity::Error);
        QVERIFY2(d->message.find(message.toStdString()) != std::string::npos, d->toString().c_str());
        QVERIFY(d->toString().starts_with("bad.json: error at " + path.toStdString() + ": "));
    }

    void formatTagWins() {
        // A file with a format tag is v1 even if it also has "objects" (reported as unknown).
        const SceneLoadResult r =
            parseScene(R"({"format": "interplay.scene", "version": 1, "bodies": [], "objects": []})", "both.json");
        QVERIFY(r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].path, std::string("/objects"));
    }

    void demoScenesLoad_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("slope") << "scenes/thesis/slope.json";
        QTest::newRow("every type") << "scenes/thesis/every_type.json";
    }

    void demoScenesLoad() {
        QFETCH(QString, file);
        const SceneLoadResult r = loadSceneFile(kSourceDir + "/" + file.toStdString());
        QVERIFY2(r.ok(), describe(r.diagnostics).c_str());
        QVERIFY2(r.diagnostics.empty(), describe(r.diagnostics).c_str());
        BuiltWorld built = buildWorld(*r.scene);
        QCOMPARE(built.world.bodyCount(), r.scene->bodies.size());
    }

    // The incline demo: three 30-degree inclines with friction 0, 0.5 and 1, each with a block
    // resting flush on it (tan 30 = 0.577: the first two slide, the last holds).
    void slopeGeometry() {
        const SceneLoadResult r = loadSceneFile(kSourceDir + "/scenes/thesis/slope.json");
        QVERIFY(r.ok());
        const auto& bodies = r.scene->bodies;
        QCOMPARE(bodies.size(), std::size_t(7));
        const float frictions[3] = {0.0f, 0.5f, 1.0f};
        for (int k = 0; k < 3; ++k) {
            const BodyCreationSettings& incline = bodies[1 + 2 * k].body;
            const BodyCreationSettings& block = bodies[2 + 2 * k].body;
            QVERIFY(incline.motion == MotionType::Static);
            QVERIFY(block.motion == MotionType::Dynamic);
            QCOMPARE(incline.friction, frictions[k]);
            QCOMPARE(block.friction, frictions[k]);
            // The incline's upper face normal is its local -z; the block's local y matches it.
            const Vec3 normal = incline.orientation * -kZ;
            QVERIFY(near(std::acos(normal.y), glm::radians(30.0f), 1e-5f));
            QVERIFY(near(block.orientation * kY, normal, 1e-5f));
            // The block's bottom face rests 2 cm above the incline's top face.
            const float gap = glm::dot(block.position - incline.position, normal) - 0.5f - incline.shape.halfExtents.z;
            QVERIFY(near(gap, 0.02f, 1e-3f));
        }
    }
};

QTEST_APPLESS_MAIN(TestThesisImport)
#include "test_thesis_import.moc"
