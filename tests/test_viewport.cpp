// The editor's first window: the mesh generator (closed meshes with outward normals on the shape's
// surface), the viewport (bodies visible where the camera projects them), and the --screenshot
// command line (a real, deterministic image). Runs under xvfb-run with the xcb platform.

#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/shape_mesh.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/world/debug_draw.h"
#include "simcore/world/world.h"

#include <QApplication>
#include <QImage>
#include <QProcess>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

using interplay::ShapeMesh;
using simcore::Shape;
using simcore::Vec3;

Q_DECLARE_METATYPE(simcore::Shape)

namespace {

Shape hullShape(const std::vector<Vec3>& points) {
    const auto result = simcore::ConvexHull::build(points);
    if (!result.hull) qWarning("hull build failed: %s", result.error.c_str());
    return Shape::convexHull(result.hull);
}

std::vector<Vec3> pointsOnSphere(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) points.push_back(0.8f * glm::normalize(Vec3(normal(rng), normal(rng), normal(rng))));
    return points;
}

// Signed distance from the shape's surface (negative inside), for the primitive shapes in closed
// form and for hulls as the largest plane distance (exact on the surface, which is what we test).
float surfaceDistance(const Shape& s, const Vec3& p) {
    switch (s.type) {
    case simcore::ShapeType::Sphere: return glm::length(p) - s.radius;
    case simcore::ShapeType::Box: {
        const Vec3 q = glm::abs(p) - s.halfExtents;
        return std::max({q.x, q.y, q.z});
    }
    case simcore::ShapeType::Capsule: {
        const Vec3 closest(0.0f, std::clamp(p.y, -s.halfHeight, s.halfHeight), 0.0f);
        return glm::length(p - closest) - s.radius;
    }
    case simcore::ShapeType::Cylinder:
        return std::max(std::sqrt(p.x * p.x + p.z * p.z) - s.radius, std::abs(p.y) - s.halfHeight);
    case simcore::ShapeType::ConvexHull: {
        float d = -1e30f;
        for (const auto& f : s.hull->faces()) d = std::max(d, glm::dot(f.normal, p) - f.offset);
        return d;
    }
    case simcore::ShapeType::Compound:
    case simcore::ShapeType::Mesh:
    case simcore::ShapeType::HeightField: break;  // the mesh tests here build convex shapes only
    }
    return 1e30f;
}

Vec3 interiorPoint(const Shape& s) {
    if (s.type != simcore::ShapeType::ConvexHull) return Vec3(0.0f);
    Vec3 sum(0.0f);
    for (const Vec3& v : s.hull->vertices()) sum += v;
    return sum / static_cast<float>(s.hull->vertices().size());
}

int distinctColors(const QImage& image) {
    std::set<QRgb> colors;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) colors.insert(image.pixel(x, y) & 0xFFFFFFu);
    }
    return static_cast<int>(colors.size());
}

float colorDistance(QRgb a, QRgb b) {
    const float dr = float(qRed(a) - qRed(b)), dg = float(qGreen(a) - qGreen(b)), db = float(qBlue(a) - qBlue(b));
    return std::sqrt(dr * dr + dg * dg + db * db);
}

// Whether some pixel within `radius` of `pixel` passes `test`.
template <typename Test>
bool anyPixelNear(const QImage& image, const glm::vec3& pixel, int radius, Test test) {
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = int(pixel.x) + dx, y = int(pixel.y) + dy;
            if (x >= 0 && y >= 0 && x < image.width() && y < image.height() && test(image.pixel(x, y))) return true;
        }
    }
    return false;
}

// What World::draw hands the viewport's overlay, recorded.
struct OverlayRecorder : simcore::DebugDraw {
    std::vector<simcore::Aabb> bounds;
    std::vector<simcore::DebugContactPoint> contacts;
    std::vector<simcore::DebugJoint> joints;
    void drawBounds(simcore::BodyId, const simcore::Aabb& box, simcore::DebugBoundsKind) override { bounds.push_back(box); }
    void drawContactPoint(const simcore::DebugContactPoint& p) override { contacts.push_back(p); }
    void drawJoint(const simcore::DebugJoint& j) override { joints.push_back(j); }
};

// The scene without what moves: what the viewport shows behind the bodies.
simcore::Scene withoutMovingBodies(simcore::Scene scene) {
    std::erase_if(scene.bodies, [](const simcore::SceneBody& b) { return b.body.motion != simcore::MotionType::Static; });
    return scene;
}

}  // namespace

class TestViewport : public QObject {
    Q_OBJECT

private slots:
    void meshIsClosedWithOutwardNormalsOnTheSurface_data();
    void meshIsClosedWithOutwardNormalsOnTheSurface();
    void documentLoadFailureLeavesDocumentUnchanged();
    void simulationPlaysStepsAndResetsToTheAuthoredScene();
    void mainWindowShowsEveryBody();
    void overlaysDrawWhatTheWorldEmits();
    void screenshotCommandWritesDeterministicImage();
    void screenshotCommandRejectsUnreadableScene();
};

void TestViewport::meshIsClosedWithOutwardNormalsOnTheSurface_data() {
    QTest::addColumn<Shape>("shape");
    QTest::newRow("sphere") << Shape::sphere(0.5f);
    QTest::newRow("sphere large") << Shape::sphere(3.0f);
    QTest::newRow("box cube") << Shape::box(Vec3(0.5f));
    QTest::newRow("box plank") << Shape::box(Vec3(2.0f, 0.1f, 0.7f));
    QTest::newRow("capsule") << Shape::capsule(0.3f, 0.6f);
    QTest::newRow("capsule short") << Shape::capsule(1.0f, 0.05f);
    QTest::newRow("cylinder") << Shape::cylinder(0.4f, 0.8f);
    QTest::newRow("cylinder disc") << Shape::cylinder(1.5f, 0.05f);
    QTest::newRow("hull tetrahedron") << hullShape({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    QTest::newRow("hull cube with interior points")
        << hullShape({{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1},
                      {0.2f, 0.1f, 0}, {0, 0, 0.5f}});
    QTest::newRow("hull offset from origin")
        << hullShape({{2, 3, 4}, {3, 3, 4}, {2, 4, 4}, {2, 3, 5}, {3, 4, 5}, {2.5f, 4.2f, 4.5f}});
    QTest::newRow("hull round") << hullShape(pointsOnSphere(60, 7));
}

void TestViewport::meshIsClosedWithOutwardNormalsOnTheSurface() {
    QFETCH(Shape, shape);
    if (shape.type == simcore::ShapeType::ConvexHull) QVERIFY2(shape.hull, "the hull did not build");

    const ShapeMesh mesh = interplay::buildShapeMesh(shape);
    QVERIFY(mesh.triangleCount() >= 4);
    QCOMPARE(mesh.indices.size() % 3, std::size_t(0));
    const simcore::Aabb bounds = simcore::localBounds(shape);
    const float scale = glm::length(bounds.max - bounds.min);
    const Vec3 inside = interiorPoint(shape);

    for (const interplay::MeshVertex& v : mesh.vertices) {
        QVERIFY2(std::abs(surfaceDistance(shape, v.position)) < 1e-5f * scale + 1e-6f,
                 qPrintable(QString("vertex (%1, %2, %3) is %4 m off the surface")
                                .arg(v.position.x).arg(v.position.y).arg(v.position.z)
                                .arg(surfaceDistance(shape, v.position))));
        QVERIFY(std::abs(glm::length(v.normal) - 1.0f) < 1e-4f);
        QVERIFY2(glm::dot(v.normal, v.position - inside) > 0.0f, "normal points inwards");
    }

    // Weld by position (faces carry their own vertices for flat normals), then every edge must be
    // used once in each direction: closed, and consistently wound.
    std::map<std::tuple<long, long, long>, std::uint32_t> weld;
    const auto welded = [&](std::uint32_t index) {
        const Vec3 p = mesh.vertices[index].position / (1e-5f * scale);
        const auto key = std::make_tuple(std::lround(p.x), std::lround(p.y), std::lround(p.z));
        return weld.emplace(key, static_cast<std::uint32_t>(weld.size())).first->second;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const auto& a = mesh.vertices[mesh.indices[t]];
        const auto& b = mesh.vertices[mesh.indices[t + 1]];
        const auto& c = mesh.vertices[mesh.indices[t + 2]];
        const Vec3 faceNormal = glm::cross(b.position - a.position, c.position - a.position);
        QVERIFY2(glm::length(faceNormal) > 1e-9f * scale * scale, "degenerate triangle");
        // Counter-clockwise seen from outside: the winding agrees with the vertex normals.
        QVERIFY2(glm::dot(faceNormal, a.normal + b.normal + c.normal) > 0.0f, "triangle wound inwards");
        const std::uint32_t w[3] = {welded(mesh.indices[t]), welded(mesh.indices[t + 1]), welded(mesh.indices[t + 2])};
        for (int k = 0; k < 3; ++k) ++directedEdges[{w[k], w[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directedEdges) {
        QCOMPARE(count, 1);
        const auto reverse = directedEdges.find({edge.second, edge.first});
        QVERIFY2(reverse != directedEdges.end(), "open edge: the mesh has a hole");
    }
}

void TestViewport::documentLoadFailureLeavesDocumentUnchanged() {
    interplay::SceneDocument document;
    document.newDefault();
    const std::size_t bodies = document.scene().bodies.size();
    QSignalSpy replaced(&document, &interplay::SceneDocument::sceneReplaced);
    QString error;
    QVERIFY(!document.load(QStringLiteral("/nonexistent/dir/missing-scene.json"), &error));
    QVERIFY2(error.contains(QStringLiteral("missing-scene.json")), qPrintable(error));
    QCOMPARE(document.scene().bodies.size(), bodies);
    QVERIFY(document.filePath().isEmpty());
    QVERIFY(!document.isModified());
    QCOMPARE(replaced.count(), 0);
}

void TestViewport::simulationPlaysStepsAndResetsToTheAuthoredScene() {
    const simcore::Scene scene = simcore::defaultScene();
    interplay::SimulationController simulation;
    QSignalSpy rebuilt(&simulation, &interplay::SimulationController::worldRebuilt);
    QSignalSpy stepped(&simulation, &interplay::SimulationController::stepped);
    QSignalSpy playing(&simulation, &interplay::SimulationController::playingChanged);
    QVERIFY(simulation.setScene(scene));
    QCOMPARE(rebuilt.count(), 1);
    QCOMPARE(simulation.bodyIds().size(), scene.bodies.size());
    QCOMPARE(simulation.authoredColors().size(), scene.bodies.size());
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(0));

    simulation.stepOnce();
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(1));
    simulation.stepFrames(9);
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(10));
    QCOMPARE(stepped.count(), 2);

    // Real-time playback: only that it advances and stops, not how fast (the clock is not ours).
    simulation.play();
    QVERIFY(simulation.isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(simulation.world()->stepCount() > 12, 5000);
    simulation.pause();
    QVERIFY(!simulation.isPlaying());
    QCOMPARE(playing.count(), 2);
    const std::uint64_t steps = simulation.world()->stepCount();
    QTest::qWait(100);
    QCOMPARE(simulation.world()->stepCount(), steps);

    // Reset: the authored state again (up to the rounding of origin <-> centre of mass).
    const simcore::BodyId dynamicBody = simulation.bodyIds()[1];
    QVERIFY(glm::length(simulation.world()->position(dynamicBody) - scene.bodies[1].body.position) > 0.01f);
    simulation.reset();
    QCOMPARE(rebuilt.count(), 2);
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(0));
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        QVERIFY(glm::length(simulation.world()->position(simulation.bodyIds()[i]) - scene.bodies[i].body.position) < 1e-5f);
    }

    // A scene the engine rejects keeps the running world.
    simcore::Scene bad = scene;
    bad.bodies[1].body.shape.radius = -1.0f;
    bad.bodies[1].body.shape.halfExtents = Vec3(-1.0f);
    QString error;
    QVERIFY(!simulation.setScene(bad, &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(simulation.bodyIds().size(), scene.bodies.size());
}

void TestViewport::mainWindowShowsEveryBody() {
    interplay::MainWindow window;
    window.openDefaultScene();
    window.resize(1024, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.windowTitle().endsWith(QStringLiteral("— Interplay")));

    interplay::Viewport* viewport = window.viewport();
    const QImage image = viewport->grabViewport();
    QVERIFY2(!image.isNull(), "no OpenGL framebuffer");
    QVERIFY(image.width() > 100 && image.height() > 100);
    const int colors = distinctColors(image);
    QVERIFY2(colors > 300, qPrintable(QString("only %1 distinct colours: blank or flat image").arg(colors)));

    // What is behind the bodies: the same view of the scene without them.
    const simcore::Scene scene = window.document()->scene();
    const interplay::Camera camera = viewport->camera();
    QVERIFY(window.simulation()->setScene(withoutMovingBodies(scene)));
    viewport->camera() = camera;
    const QImage background = viewport->grabViewport();
    QCOMPARE(background.size(), image.size());

    // Each moving body projects into the image, and the pixels around its centre are not the
    // background's: the body is visible there.
    int checked = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const simcore::BodyCreationSettings& body = scene.bodies[i].body;
        if (body.motion == simcore::MotionType::Static) continue;
        const Vec3 center = simcore::worldBounds(body.shape, {body.position, body.orientation}).center();
        const glm::vec3 pixel = camera.project(center, float(image.width()), float(image.height()));
        const QString what = QString("body %1 \"%2\" at pixel (%3, %4)")
                                 .arg(i).arg(QString::fromStdString(body.name)).arg(pixel.x).arg(pixel.y);
        QVERIFY2(pixel.x >= 0 && pixel.y >= 0 && pixel.x < image.width() && pixel.y < image.height() && pixel.z < 1.0f,
                 qPrintable(what + " is outside the view"));
        int differing = 0, total = 0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const int x = std::clamp(int(pixel.x) + dx, 0, image.width() - 1);
                const int y = std::clamp(int(pixel.y) + dy, 0, image.height() - 1);
                ++total;
                if (colorDistance(image.pixel(x, y), background.pixel(x, y)) > 30.0f) ++differing;
            }
        }
        QVERIFY2(differing > total * 3 / 4, qPrintable(what + " is not visible"));
        ++checked;
    }
    QVERIFY2(checked >= 5, "the default scene should hold one moving body of every shape type");
}

// The overlays are drawn where World::draw puts them: contact crosses (pink) at every contact
// point, bounds (green) along every box's edges, and a joint's anchor cross (near black), which
// is drawn with the overlays off too.
void TestViewport::overlaysDrawWhatTheWorldEmits() {
    simcore::Scene scene;
    simcore::SceneBody ground;
    ground.body.name = "ground";
    ground.body.motion = simcore::MotionType::Static;
    ground.body.shape = Shape::box(Vec3(4.0f, 0.5f, 4.0f));
    ground.body.position = Vec3(0.0f, -0.5f, 0.0f);
    simcore::SceneBody box;
    box.body.name = "box";
    box.body.shape = Shape::box(Vec3(0.5f));
    box.body.position = Vec3(-1.0f, 0.5f, 0.0f);
    simcore::SceneBody bob;
    bob.body.name = "bob";
    bob.body.shape = Shape::box(Vec3(0.25f));
    bob.body.position = Vec3(1.5f, 1.5f, 0.0f);
    scene.bodies = {ground, box, bob};
    simcore::SceneJoint hang;
    hang.joint.type = simcore::JointType::Ball;
    hang.joint.anchor = Vec3(1.5f, 2.5f, 0.0f);
    hang.bodyA = 2;
    scene.joints = {hang};

    interplay::SimulationController simulation;
    QVERIFY(simulation.setScene(scene));
    simulation.stepFrames(30);  // the box settles: four touching points
    interplay::DebugDrawOptions options;
    interplay::Viewport viewport;
    viewport.setSimulation(&simulation);
    viewport.setDebugDrawOptions(&options);
    viewport.resize(800, 600);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    viewport.grabViewport();  // the first frame frames the scene; then aim where all of it shows
    viewport.camera().setTarget(glm::vec3(0.0f, 1.0f, 0.0f));
    viewport.camera().setDistance(7.0f);
    const QImage plain = viewport.grabViewport();
    options.setProperty("contactPoints", true);
    options.setProperty("aabbs", true);
    const QImage overlaid = viewport.grabViewport();
    QCOMPARE(overlaid.size(), plain.size());

    OverlayRecorder world;
    simcore::DebugDrawOptions everything;
    everything.bodies = false;
    everything.tightBounds = everything.contacts = everything.joints = true;
    simulation.world()->draw(world, everything);
    QCOMPARE(world.contacts.size(), std::size_t{4});
    QCOMPARE(world.bounds.size(), std::size_t{3});
    QCOMPARE(world.joints.size(), std::size_t{1});

    const interplay::Camera& camera = viewport.camera();
    const float w = float(overlaid.width()), h = float(overlaid.height());
    const auto pink = [](QRgb c) { return qRed(c) > 200 && qGreen(c) < 110 && qBlue(c) > 80; };
    const auto green = [](QRgb c) { return qGreen(c) > 160 && qRed(c) < 140 && qBlue(c) < 140; };
    const auto dark = [](QRgb c) { return qRed(c) < 90 && qGreen(c) < 90 && qBlue(c) < 90; };
    for (const simcore::DebugContactPoint& p : world.contacts) {
        const glm::vec3 pixel = camera.project(p.point, w, h);
        QVERIFY2(anyPixelNear(overlaid, pixel, 2, pink), "no contact cross at a contact point");
        QVERIFY2(!anyPixelNear(plain, pixel, 2, pink), "a contact cross with the overlay off");
    }
    // The top edges of the moving bodies' bounds, at their middles, seen against the sky or floor.
    for (std::size_t b = 1; b < world.bounds.size(); ++b) {
        const simcore::Aabb& bounds = world.bounds[b];
        const glm::vec3 edge(bounds.center().x, bounds.max.y, bounds.max.z);
        const glm::vec3 pixel = camera.project(edge, w, h);
        QVERIFY2(anyPixelNear(overlaid, pixel, 2, green), "no bounds edge where the world's bounds are");
        QVERIFY2(!anyPixelNear(plain, pixel, 2, green), "a bounds edge with the overlay off");
    }
    const glm::vec3 anchor = camera.project(world.joints[0].anchorA, w, h);
    QVERIFY(glm::length(world.joints[0].anchorA - hang.joint.anchor) < 1e-3f);
    QVERIFY2(anyPixelNear(plain, anchor, 2, dark), "no joint cross at the joint's anchor");
}

namespace {

struct RunResult {
    int exitCode = -1;
    QString standardError;
};

RunResult runInterplay(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(INTERPLAY_APP_PATH), arguments);
    if (!process.waitForFinished(120000)) {
        process.kill();
        return {};
    }
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromLocal8Bit(process.readAllStandardError())};
}

}  // namespace

void TestViewport::screenshotCommandWritesDeterministicImage() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString first = dir.filePath(QStringLiteral("first.png"));
    const QString second = dir.filePath(QStringLiteral("second.png"));

    const RunResult run = runInterplay({QStringLiteral("--screenshot"), first, QStringLiteral("--frames"), QStringLiteral("30")});
    QVERIFY2(run.exitCode == 0, qPrintable(QString("exit %1: %2").arg(run.exitCode).arg(run.standardError)));
    const QImage image(first);
    QVERIFY2(!image.isNull(), "the screenshot is not a readable PNG");
    QVERIFY(image.width() >= 640 && image.height() >= 400);
    const int colors = distinctColors(image);
    QVERIFY2(colors > 300, qPrintable(QString("only %1 distinct colours: blank or flat screenshot").arg(colors)));

    // Same arguments, same pixels: the screenshot does not depend on the wall clock.
    const RunResult again = runInterplay({QStringLiteral("--screenshot"), second, QStringLiteral("--frames"), QStringLiteral("30")});
    QCOMPARE(again.exitCode, 0);
    QVERIFY(QImage(second).convertToFormat(QImage::Format_RGB32) == image.convertToFormat(QImage::Format_RGB32));
}

void TestViewport::screenshotCommandRejectsUnreadableScene() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString shot = dir.filePath(QStringLiteral("shot.png"));
    const RunResult run = runInterplay({dir.filePath(QStringLiteral("no-such-scene.json")), QStringLiteral("--screenshot"), shot});
    QCOMPARE(run.exitCode, 3);
    QVERIFY2(run.standardError.contains(QStringLiteral("no-such-scene.json")), qPrintable(run.standardError));
    QVERIFY(!QFile::exists(shot));

    const RunResult badFrames = runInterplay({QStringLiteral("--screenshot"), shot, QStringLiteral("--frames"), QStringLiteral("-4")});
    QCOMPARE(badFrames.exitCode, 2);
}

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestViewport test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport.moc"
