// Malformed and hostile scene files: each must be refused with a message naming the file, the JSON
// path (or line and column for syntax errors) and the reason, by the library and by interplay-run
// (exit 3 for a scene that cannot be read, 2 for bad arguments), without crashing or hanging.

#include "simcore/io/scene_io.h"

#include "support/run_program.h"

#include <QtTest>

#include <fstream>

using namespace simcore;

namespace {

// A v1 scene around the given bodies (and optional settings), on one line.
QString v1(const QString& bodies, const QString& settings = {}) {
    QString s = R"({"format": "interplay.scene", "version": 1, )";
    if (!settings.isEmpty()) s += R"("settings": )" + settings + ", ";
    return s + R"("bodies": [)" + bodies + "]}";
}

// One body with the given shape and extra members.
QString body(const QString& shape, const QString& extra = {}) {
    return R"({"shape": )" + shape + (extra.isEmpty() ? QString() : ", " + extra) + "}";
}

const QString kSphere = R"({"type": "sphere", "radius": 0.5})";

std::string describe(const std::vector<Diagnostic>& diagnostics) {
    std::string s;
    for (const Diagnostic& d : diagnostics) s += d.toString() + "\n";
    return s;
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

}  // namespace

class TestMalformedScenes : public QObject {
    Q_OBJECT

private:
    // Columns: the file's bytes, extra runner arguments, the runner's exit code, and the texts
    // that must appear in what it prints (the JSON path, or file:line:column, and the reason).
    void table() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QStringList>("extraArguments");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QStringList>("expected");
        auto row = [](const char* name, const QString& content, const QStringList& expected, int exitCode = 3,
                      const QStringList& extra = {}) {
            QTest::newRow(name) << content.toUtf8() << extra << exitCode << expected;
        };
        const QString sphereBody = body(kSphere);

        // Syntax: line and column of the offending character.
        row("syntax: stray comma",
            "{\n  \"format\": \"interplay.scene\",\n  \"version\": 1,\n  \"bodies\": [ , ]\n}",
            {"scene.json:4:15: error: ", "unexpected ','"});
        row("syntax: unterminated object", R"({"format": "interplay.scene")", {"scene.json:1:29: error: ", "end of input"});
        row("syntax: NaN literal", "{\"format\": \"interplay.scene\", \"version\": 1,\n\"bodies\": [{\"shape\": {\"type\": \"sphere\", \"radius\": NaN}}]}",
            {"scene.json:2:51: error: "});
        row("syntax: number overflow", "{\"format\": \"interplay.scene\", \"version\": 1,\n  \"bodies\": [{\"shape\": {\"type\": \"sphere\", \"radius\": 1e999}}]}",
            {"scene.json:2:53: error: ", "1e999 is too large"});
        row("syntax: single quotes", "{'format': 1}", {"scene.json:1:2: error: "});
        row("syntax: comment", "// scene\n{}", {"scene.json:1:1: error: "});
        row("syntax: trailing garbage", v1(sphereBody) + " x", {"scene.json:1:", "end of input"});
        row("empty file", "", {"scene.json: error: the file is empty"});
        row("whitespace only", "  \n\t\n", {"scene.json: error: the file is empty"});

        // Document structure.
        row("top-level array", "[]", {"scene.json: error: expected a JSON object at the top level, got an array"});
        row("top-level number", "42", {"expected a JSON object at the top level, got a number"});
        row("missing format", R"({"version": 1, "bodies": []})", {"error at /format: required key 'format' is missing"});
        row("wrong format tag", R"({"format": "blender.scene", "version": 1, "bodies": []})",
            {"error at /format: ", "\"interplay.scene\""});
        row("format not a string", R"({"format": 1, "version": 1, "bodies": []})", {"error at /format: expected a string, got a number"});
        row("newer version", R"({"format": "interplay.scene", "version": 2, "bodies": []})",
            {"error at /version: version 2 is newer than this program supports (1)"});
        row("version zero", R"({"format": "interplay.scene", "version": 0, "bodies": []})", {"error at /version: "});
        row("missing version", R"({"format": "interplay.scene", "bodies": []})", {"error at /version: required key"});
        row("missing bodies", R"({"format": "interplay.scene", "version": 1})", {"error at /bodies: required key 'bodies' is missing"});
        row("bodies not an array", R"({"format": "interplay.scene", "version": 1, "bodies": {}})",
            {"error at /bodies: expected an array, got an object"});
        row("body not an object", v1(sphereBody + ", 7"), {"error at /bodies/1: expected an object, got a number"});
        row("joint without bodyA", v1(sphereBody) .chopped(1) + R"(, "joints": [{"type": "hinge"}]})",
            {"error at /joints/0/bodyA: required key 'bodyA' is missing"});
        row("joints not an array", v1(sphereBody).chopped(1) + R"(, "joints": 3})", {"error at /joints: expected an array"});

        // Shapes.
        row("missing shape", v1(R"({"name": "x"})"), {"error at /bodies/0/shape: required key 'shape' is missing"});
        row("missing shape type", v1(body(R"({"radius": 1})")), {"error at /bodies/0/shape/type: required key"});
        row("unknown shape type", v1(body(R"({"type": "cone", "radius": 1})")),
            {"error at /bodies/0/shape/type: unknown shape type 'cone'"});
        row("negative radius", v1(body(R"({"type": "sphere", "radius": -1})")),
            {"error at /bodies/0/shape/radius: radius must be positive, got -1"});
        row("radius as string", v1(body(R"({"type": "sphere", "radius": "big"})")),
            {"error at /bodies/0/shape/radius: expected a number, got a string"});
        row("zero half extent", v1(body(R"({"type": "box", "halfExtents": [1, 0, 1]})")),
            {"error at /bodies/0/shape/halfExtents/1: halfExtents[1] must be positive, got 0"});
        row("huge half extent", v1(body(R"({"type": "box", "halfExtents": [1, 1, 1e300]})")),
            {"error at /bodies/0/shape/halfExtents/2: ", "at most"});
        row("half extents of two", v1(body(R"({"type": "box", "halfExtents": [1, 1]})")),
            {"error at /bodies/0/shape/halfExtents: expected 3 numbers, got 2"});
        row("capsule without halfHeight", v1(body(R"({"type": "capsule", "radius": 1})")),
            {"error at /bodies/0/shape/halfHeight: required key"});
        row("cylinder tiny", v1(body(R"({"type": "cylinder", "radius": 1e-9, "halfHeight": 1})")),
            {"error at /bodies/0/shape/radius: radius must be at least 0.0001 m"});
        row("hull with 3 points", v1(body(R"({"type": "convexHull", "points": [[0,0,0], [1,0,0], [0,1,0]]})")),
            {"error at /bodies/0/shape/points: ", "at least 4 points, got 3"});
        row("coplanar hull", v1(body(R"({"type": "convexHull", "points": [[0,0,0], [1,0,0], [0,1,0], [1,1,0], [0.5,0.5,0]]})")),
            {"error at /bodies/0/shape/points: cannot build a convex hull"});
        row("hull point not a triple", v1(body(R"({"type": "convexHull", "points": [[0,0,0], [1,0,0], [0,1,0], [0,0]]})")),
            {"error at /bodies/0/shape/points/3: expected 3 numbers, got 2"});
        row("compound child radius", v1(body(R"({"type": "compound", "children": [{"shape": {"type": "sphere", "radius": 1}},
               {"shape": {"type": "sphere", "radius": 0}}]})")),
            {"error at /bodies/0/shape/children/1/shape/radius: "});
        row("compound nested", v1(body(R"({"type": "compound", "children": [{"shape": {"type": "compound", "children": []}}]})")),
            {"error at /bodies/0/shape/children/0/shape/type: ", "compounds do not nest"});
        row("compound without children", v1(body(R"({"type": "compound", "children": []})")),
            {"error at /bodies/0/shape/children: a compound has 1 to 64 children, got 0"});
        row("dynamic mesh", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1,0,0], [0,0,1]], "triangles": [[0,2,1]]})")),
            {"error at /bodies/0/motion: a mesh body must be static or kinematic", "convexHull", "compound"});
        row("dynamic height field", v1(body(R"({"type": "heightField", "rows": 2, "columns": 2, "cellSize": 1, "heights": [0,0,0,0]})")),
            {"error at /bodies/0/motion: a heightField body must be static or kinematic"});
        row("mesh index out of range", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1,0,0], [0,0,1]], "triangles": [[0,2,3]]})",
                                                R"("motion": "static")")),
            {"error at /bodies/0/shape/triangles: cannot build the mesh: ", "triangle 0"});
        row("mesh degenerate triangle", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1,0,0], [2,0,0]], "triangles": [[0,1,2]]})",
                                                 R"("motion": "static")")),
            {"error at /bodies/0/shape/triangles: cannot build the mesh: ", "triangle 0"});
        row("mesh triangle of two", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1,0,0], [0,0,1]], "triangles": [[0,2]]})",
                                             R"("motion": "static")")),
            {"error at /bodies/0/shape/triangles/0: expected 3 vertex indices [i, j, k], got 2 items"});
        row("mesh negative index", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1,0,0], [0,0,1]], "triangles": [[0,-2,1]]})",
                                            R"("motion": "static")")),
            {"error at /bodies/0/shape/triangles/0/1: "});
        row("mesh vertex out of range", v1(body(R"({"type": "mesh", "vertices": [[0,0,0], [1e7,0,0], [0,0,1]], "triangles": [[0,2,1]]})",
                                                 R"("motion": "static")")),
            {"error at /bodies/0/shape/vertices/1/0: vertices[1][0] must be between -1000000 and 1000000 m"});
        row("mesh without triangles", v1(body(R"({"type": "mesh", "vertices": [[0,0,0]]})", R"("motion": "static")")),
            {"error at /bodies/0/shape/triangles: required key"});
        row("mesh in a compound", v1(body(R"({"type": "compound", "children": [{"shape": {"type": "mesh"}}]})")),
            {"error at /bodies/0/shape/children/0/shape/type: a compound's child must be a convex shape, not a mesh"});
        row("height field short of heights", v1(body(R"({"type": "heightField", "rows": 2, "columns": 3, "cellSize": 1, "heights": [0,0,0,0]})",
                                                      R"("motion": "static")")),
            {"error at /bodies/0/shape/heights: expected rows x columns = 6 heights, got 4"});
        row("height field of one row", v1(body(R"({"type": "heightField", "rows": 1, "columns": 3, "cellSize": 1, "heights": [0,0,0]})",
                                                R"("motion": "static")")),
            {"error at /bodies/0/shape/rows: "});
        row("height field zero cell", v1(body(R"({"type": "heightField", "rows": 2, "columns": 2, "cellSize": 0, "heights": [0,0,0,0]})",
                                               R"("motion": "static")")),
            {"error at /bodies/0/shape/cellSize: "});
        row("height field too many triangles", v1(body(R"({"type": "heightField", "rows": 1001, "columns": 1002, "cellSize": 1, "heights": []})",
                                                        R"("motion": "static")")),
            {"error at /bodies/0/shape: a height field may have at most 2000000 triangles"});
        row("height field NaN-like height", v1(body(R"({"type": "heightField", "rows": 2, "columns": 2, "cellSize": 1, "heights": [0,0,"x",0]})",
                                                     R"("motion": "static")")),
            {"error at /bodies/0/shape/heights/2: expected a number, got a string"});

        // Body properties.
        row("mass zero", v1(body(kSphere, R"("mass": 0)")), {"error at /bodies/0/mass: mass must be positive, got 0"});
        row("negative density", v1(body(kSphere, R"("density": -5)")), {"error at /bodies/0/density: density must be positive"});
        row("mass and density", v1(body(kSphere, R"("mass": 1, "density": 1000)")),
            {"error at /bodies/0/density: give either mass or density, not both"});
        row("friction -1", v1(body(kSphere, R"("friction": -1)")), {"error at /bodies/0/friction: friction must not be negative"});
        row("restitution 2", v1(body(kSphere, R"("restitution": 2)")), {"error at /bodies/0/restitution: restitution must be at most 1, got 2"});
        row("rolling resistance negative", v1(body(kSphere, R"("rollingResistance": -0.1)")),
            {"error at /bodies/0/rollingResistance: rollingResistance must not be negative"});
        row("rolling resistance beyond float", v1(body(kSphere, R"("rollingResistance": 1e300)")),
            {"error at /bodies/0/rollingResistance: rollingResistance must be at most 100"});
        row("rolling resistance as string", v1(body(kSphere, R"("rollingResistance": "low")")),
            {"error at /bodies/0/rollingResistance: expected a number, got a string"});
        row("zero quaternion", v1(body(kSphere, R"("orientation": [0, 0, 0, 0])")),
            {"error at /bodies/0/orientation: orientation cannot be normalised"});
        row("quaternion of three", v1(body(kSphere, R"("orientation": [1, 0, 0])")),
            {"error at /bodies/0/orientation: expected 4 numbers"});
        row("position huge", v1(body(kSphere, R"("position": [1e30, 0, 0])")),
            {"error at /bodies/0/position/0: position[0] must be between"});
        row("position with a string", v1(body(kSphere, R"("position": [0, "up", 0])")),
            {"error at /bodies/0/position/1: expected a number, got a string"});
        row("velocity null", v1(body(kSphere, R"("linearVelocity": null)")),
            {"error at /bodies/0/linearVelocity: expected an array of 3 numbers, got null"});
        row("name not a string", v1(body(kSphere, R"("name": 12)")), {"error at /bodies/0/name: expected a string, got a number"});
        row("unknown motion", v1(body(kSphere, R"("motion": "floating")")), {"error at /bodies/0/motion: unknown motion 'floating'"});
        row("ccd not a bool", v1(body(kSphere, R"("ccd": "yes")")), {"error at /bodies/0/ccd: expected true or false, got a string"});
        row("color out of range", v1(body(kSphere, R"("color": [1, 2, 0])")), {"error at /bodies/0/color/1: "});
        row("second body bad", v1(sphereBody + ", " + body(R"({"type": "sphere", "radius": 0})")),
            {"error at /bodies/1/shape/radius: "});

        // Settings.
        row("gravity of two", v1(sphereBody, R"({"gravity": [0, -9.81]})"), {"error at /settings/gravity: expected 3 numbers, got 2"});
        row("timeStep zero", v1(sphereBody, R"({"timeStep": 0})"), {"error at /settings/timeStep: timeStep must be positive, got 0"});
        row("timeStep too long", v1(sphereBody, R"({"timeStep": 10})"), {"error at /settings/timeStep: timeStep must be at most 1 s"});
        row("substeps zero", v1(sphereBody, R"({"substeps": 0})"), {"error at /settings/substeps: substeps must be between 1 and 64, got 0"});
        row("substeps fractional", v1(sphereBody, R"({"substeps": 1.5})"), {"error at /settings/substeps: expected an integer, got 1.5"});
        row("unknown integrator", v1(sphereBody, R"({"integrator": "rk4"})"),
            {"error at /settings/integrator: unknown integrator 'rk4' (expected symplecticEuler, explicitEuler or velocityVerlet)"});
        row("iterations string", v1(sphereBody, R"({"solver": {"velocityIterations": "many"}})"),
            {"error at /settings/solver/velocityIterations: expected an integer, got a string"});
        row("iterations huge", v1(sphereBody, R"({"solver": {"positionIterations": 1e12}})"),
            {"error at /settings/solver/positionIterations: ", "between 0 and 1000"});
        row("negative damping", v1(sphereBody, R"({"damping": {"linear": -1}})"), {"error at /settings/damping/linear: "});
        row("effect not a bool", v1(sphereBody, R"({"effects": {"friction": 1}})"), {"error at /settings/effects/friction: expected true or false"});
        row("settings not an object", v1(sphereBody, "[]"), {"error at /settings: expected an object, got an array"});

        // Thesis format.
        row("thesis negative scale", R"({"objects": [{"type": "box"}, {"type": "box", "scale": {"x": 1, "y": -2, "z": 1}}]})",
            {"error at /objects/1/scale/y: scale.y must be positive, got -2"});
        row("thesis unknown type", R"({"objects": [{"type": "torus"}]})", {"error at /objects/0/type: unknown object type 'torus'"});
        row("thesis damping zero", R"({"settings": {"damping": {"linear": 0}}, "objects": []})",
            {"error at /settings/damping/linear: "});
        row("thesis objects not array", R"({"objects": 5})", {"error at /objects: expected an array, got a number"});

        // Hostile.
        row("deep nesting", QString(10000, '[') + QString(10000, ']'), {"scene.json: error: ", "nested more than"});

        // Bad arguments to an otherwise fine scene: exit 2, the message names the key.
        row("set unknown key", v1(sphereBody), {"solver.foo"}, 2, {"--set", "solver.foo=1"});
        row("set bad value", v1(sphereBody), {"substeps"}, 2, {"--set", "substeps=0"});
    }

private slots:
    void library_data() { table(); }

    // The same table through the library: the scene is refused, every error names the file, and
    // the expected texts appear in the diagnostics.
    void library() {
        QFETCH(QByteArray, content);
        QFETCH(int, exitCode);
        QFETCH(QStringList, expected);
        const SceneLoadResult r = parseScene(std::string_view(content.constData(), std::size_t(content.size())), "scene.json");
        const std::string text = describe(r.diagnostics);
        if (exitCode != 3) {
            QVERIFY2(r.ok(), text.c_str());
            return;
        }
        QVERIFY(!r.ok());
        QVERIFY(!r.diagnostics.empty());
        QVERIFY(r.diagnostics.size() <= 101);
        bool anyError = false;
        for (const Diagnostic& d : r.diagnostics) {
            QCOMPARE(d.file, std::string("scene.json"));
            QVERIFY(!d.message.empty());
            anyError = anyError || d.severity == Diagnostic::Severity::Error;
        }
        QVERIFY(anyError);
        for (const QString& e : expected)
            QVERIFY2(text.find(e.toStdString()) != std::string::npos, (e.toStdString() + " not in:\n" + text).c_str());
    }

    void runner_data() { table(); }

    // The same table through interplay-run.
    void runner() {
        QFETCH(QByteArray, content);
        QFETCH(QStringList, extraArguments);
        QFETCH(int, exitCode);
        QFETCH(QStringList, expected);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        writeFile(dir.filePath("scene.json"), content);

        // In the scene's folder, so the file is named "scene.json" in messages.
        const test_support::ProgramRun run = test_support::runProgram(
            INTERPLAY_RUN_PATH, QStringList{"scene.json", "--steps", "1"} + extraArguments, 30'000, dir.path());
        const QString err = QString::fromUtf8(run.err);
        QVERIFY2(run.finished, "interplay-run did not exit by itself within 30 s");
        QVERIFY2(run.exitCode == exitCode,
                 qPrintable(QString("exit code %1, expected %2; stderr:\n%3").arg(run.exitCode).arg(exitCode).arg(err)));
        for (const QString& e : expected) QVERIFY2(err.contains(e), qPrintable(e + " not in:\n" + err));
        if (exitCode == 3) QVERIFY(run.out.isEmpty());  // no report for an unread scene
    }

    void runnerMissingFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("absent.json");
        const test_support::ProgramRun run = test_support::runProgram(INTERPLAY_RUN_PATH, {path, "--steps", "1"}, 30'000);
        QVERIFY(run.finished);
        QCOMPARE(run.exitCode, 3);
        const QString err = QString::fromUtf8(run.err);
        QVERIFY2(err.contains(path) && err.contains("No such file"), qPrintable(err));
    }

    // Raw bytes that are not UTF-8 inside a string: a syntax error with a position.
    void invalidUtf8() {
        const std::string text = std::string("{\"format\": \"interplay.scene\", \"version\": 1, \"bodies\": [{\"name\": \"") +
                                 "\xff\xfe" + "\"}]}";
        const SceneLoadResult r = parseScene(text, "utf.json");
        QVERIFY(!r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].line, 1);
        QCOMPARE(r.diagnostics[0].column, 66);  // the first invalid byte
        QVERIFY(r.diagnostics[0].toString().starts_with("utf.json:1:66: error: "));
    }

    // Thousands of bad bodies: the first problems are reported, the rest summarised, quickly.
    void diagnosticsAreCapped() {
        QString bodies;
        for (int i = 0; i < 5000; ++i) bodies += (i ? ", " : "") + body(R"({"type": "sphere", "radius": -1})", R"("bogus": 1)");
        QElapsedTimer timer;
        timer.start();
        const SceneLoadResult r = parseScene(v1(bodies).toStdString(), "many.json");
        QVERIFY(timer.elapsed() < 5000);
        QVERIFY(!r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(101));
        QVERIFY(r.diagnostics.back().path.empty());
        QVERIFY2(r.diagnostics.back().message.find("more problems not shown") != std::string::npos,
                 r.diagnostics.back().message.c_str());
        QVERIFY(r.diagnostics.back().severity == Diagnostic::Severity::Error);
    }

    // Warnings alone never hide an error behind the cap.
    void manyWarningsThenAnError() {
        QString bodies;
        for (int i = 0; i < 300; ++i) bodies += (i ? ", " : "") + body(kSphere, R"("bogus": 1)");
        bodies += ", " + body(R"({"type": "sphere", "radius": 0})");
        const SceneLoadResult r = parseScene(v1(bodies).toStdString(), "warn.json");
        QVERIFY(!r.ok());
        QVERIFY(r.diagnostics.back().severity == Diagnostic::Severity::Error);
    }

    void hugeHullIsRefused() {
        QString points;
        for (int i = 0; i < 5000; ++i) points += QString(i ? ", [%1, %2, %3]" : "[%1, %2, %3]").arg(i % 17).arg(i % 13).arg(i % 7);
        const SceneLoadResult r = parseScene(v1(body(R"({"type": "convexHull", "points": [)" + points + "]}")).toStdString(), "h.json");
        QVERIFY(!r.ok());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].path, std::string("/bodies/0/shape/points"));
    }

    // Random byte damage to a valid scene never crashes and always yields a scene or a diagnostic.
    void corruptedBytes() {
        const std::string valid = v1(body(kSphere, R"("position": [0, 1, 0], "mass": 2)") + ", " +
                                     body(R"({"type": "convexHull", "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})"),
                                     R"({"gravity": [0, -9.81, 0], "solver": {"velocityIterations": 4}})")
                                      .toStdString();
        QVERIFY(parseScene(valid, "v.json").ok());
        std::uint32_t seed = 12345;
        auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
        for (int trial = 0; trial < 3000; ++trial) {
            std::string text = valid;
            const int edits = 1 + int(next() % 4);
            for (int e = 0; e < edits; ++e) {
                const std::size_t at = next() % text.size();
                switch (next() % 3) {
                    case 0: text[at] = char(next() % 256); break;
                    case 1: text.erase(at, 1 + next() % 8); break;
                    default: text.insert(at, 1, "{}[],:\"0-e."[next() % 11]); break;
                }
            }
            const SceneLoadResult r = parseScene(text, "fuzz.json");
            QVERIFY(r.ok() || !r.diagnostics.empty());
        }
    }
};

QTEST_APPLESS_MAIN(TestMalformedScenes)
#include "test_malformed_scenes.moc"
