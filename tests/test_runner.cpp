// interplay-run end to end: arguments, exit codes, and the report contract from the brief.

#include "simcore/settings_schema.h"
#include "simcore/world/stages.h"

#include "support/run_program.h"

#include <QtTest>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace {

struct RunResult {
    int exitCode = -1;
    QString out;
    QString err;
};

RunResult runRunner(const QStringList& arguments) {
    const test_support::ProgramRun run = test_support::runProgram(INTERPLAY_RUN_PATH, arguments);
    return {run.exitCode, QString::fromUtf8(run.out), QString::fromUtf8(run.err)};
}

// A sphere thrown from (0, 10, 0) at (2, 3, 0) m/s, alone in the world.
const char* kProjectileScene = R"({
  "format": "interplay.scene", "version": 1,
  "settings": { "gravity": [0, -9.81, 0], "timeStep": 0.01, "substeps": 1, "sleep": { "enabled": false } },
  "bodies": [ { "name": "ball", "shape": { "type": "sphere", "radius": 0.25 },
                "position": [0, 10, 0], "mass": 1.5, "linearVelocity": [2, 3, 0] } ],
  "joints": []
})";

// A 1 kg ball of radius 0.25 m rolling along +x at 3 m/s without slipping (w = v / r), with
// rolling resistance 0.1, on a plain floor.
const char* kRollingScene = R"({
  "format": "interplay.scene", "version": 1,
  "settings": { "sleep": { "enabled": false } },
  "bodies": [
    { "name": "ground", "motion": "static", "shape": { "type": "box", "halfExtents": [50, 0.5, 50] },
      "position": [0, -0.5, 0], "friction": 0.6 },
    { "name": "ball", "shape": { "type": "sphere", "radius": 0.25 }, "position": [-10, 0.25, 0], "mass": 1,
      "linearVelocity": [3, 0, 0], "angularVelocity": [0, 0, -12], "rollingResistance": 0.1 } ],
  "joints": []
})";

}  // namespace

class TestRunner : public QObject {
    Q_OBJECT

private slots:
    void init();
    void badArgumentsExitTwo_data();
    void badArgumentsExitTwo();
    void missingSceneExitsThreeNamingTheFile();
    void reportHasTheContractFieldsAndTheRightPhysics();
    void optionsChangeTheSettings();
    void unknownSettingIsNamed();
    void helpListsEverySetting();
    void secondsBecomeSteps();
    void traceAndOutFilesAreWritten();
    void saveWithZeroStepsConvertsTheScene();
    void rollingResistanceFromTheFile();

private:
    QString writeScene(const QByteArray& text, const QString& name = "scene.json");
    QTemporaryDir dir_;
};

void TestRunner::init() { QVERIFY(dir_.isValid()); }

QString TestRunner::writeScene(const QByteArray& text, const QString& name) {
    const QString path = dir_.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return {};
    file.write(text);
    return path;
}

void TestRunner::badArgumentsExitTwo_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no scene") << QStringList{"--steps", "3"} << "no scene file given";
    QTest::newRow("unknown option") << QStringList{"SCENE", "--bogus", "1"} << "unknown option --bogus";
    QTest::newRow("steps not a number") << QStringList{"SCENE", "--steps", "ten"} << "--steps";
    QTest::newRow("negative dt") << QStringList{"SCENE", "--dt", "-0.01"} << "--dt";
    QTest::newRow("zero substeps") << QStringList{"SCENE", "--substeps", "0"} << "--substeps";
    QTest::newRow("negative threads") << QStringList{"SCENE", "--threads", "-1"} << "--threads expects an integer in [0, 256]";
    QTest::newRow("too many threads") << QStringList{"SCENE", "--threads", "257"} << "--threads expects an integer in [0, 256]";
    QTest::newRow("steps and seconds") << QStringList{"SCENE", "--steps", "1", "--seconds", "1"} << "exclude";
    QTest::newRow("missing value") << QStringList{"SCENE", "--steps"} << "needs a value";
    QTest::newRow("set without =") << QStringList{"SCENE", "--set", "gravity"} << "key.path=value";
    QTest::newRow("two scenes") << QStringList{"SCENE", "other.json"} << "more than one scene";
}

void TestRunner::badArgumentsExitTwo() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const QString scene = writeScene(kProjectileScene);
    arguments.replaceInStrings("SCENE", scene);
    const RunResult r = runRunner(arguments);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
}

void TestRunner::missingSceneExitsThreeNamingTheFile() {
    const QString path = dir_.filePath("does-not-exist.json");
    const RunResult r = runRunner({path});
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(path), qPrintable(r.err));
}

void TestRunner::reportHasTheContractFieldsAndTheRightPhysics() {
    const RunResult r = runRunner({writeScene(kProjectileScene), "--steps", "100"});
    QCOMPARE(r.exitCode, 0);
    const auto report = nlohmann::json::parse(r.out.toStdString());

    for (const char* key : {"steps", "dt", "wallMs", "msPerStep", "stages", "effects", "counters", "metrics", "bodies"})
        QVERIFY2(report.contains(key), key);
    QCOMPARE(report["steps"].get<int>(), 100);
    QCOMPARE(report["dt"].get<float>(), 0.01f);
    QVERIFY(report["msPerStep"].get<double>() >= 0.0);
    // Every stage of the table in its order (test_stages checks the table and the skips).
    QCOMPARE(report["stages"].size(), simcore::kStages.size());
    for (std::size_t s = 0; s < simcore::kStages.size(); ++s)
        QCOMPARE(report["stages"][s]["stage"].get<std::string>(), std::string(simcore::kStages[s].key));
    const auto& integratePositions = report["stages"][static_cast<std::size_t>(simcore::Stage::IntegratePositions)];
    QVERIFY(report["wallMs"].get<double>() >= integratePositions["msPerStep"].get<double>());
    QCOMPARE(integratePositions["stepsRun"].get<int>(), 100);
    // One ball: nothing to collide with, and sleep is off in the scene.
    QCOMPARE(report["stages"][static_cast<std::size_t>(simcore::Stage::Collide)]["skipped"].get<std::string>(),
             std::string(simcore::stageSkipReason(simcore::StageSkip::SingleBody)));
    QCOMPARE(report["stages"][static_cast<std::size_t>(simcore::Stage::Sleep)]["skipped"].get<std::string>(),
             std::string(simcore::stageSkipReason(simcore::StageSkip::SleepOff)));
    for (const char* effect : {"gravity", "damping", "gyroscopic", "contacts", "friction", "restitution",
                               "joints", "ccd", "sleeping"})
        QVERIFY2(report["effects"].contains(effect), effect);
    QCOMPARE(report["effects"]["gravity"].get<bool>(), true);
    QCOMPARE(report["effects"]["damping"].get<bool>(), false);   // damping rates are zero
    QCOMPARE(report["effects"]["sleeping"].get<bool>(), false);  // switched off in the scene
    QCOMPARE(report["counters"]["bodies"].get<int>(), 1);
    for (const char* metric : {"maxPenetration", "kineticEnergy", "potentialEnergy", "totalEnergy"})
        QVERIFY2(report["metrics"].contains(metric), metric);

    const auto& ball = report["bodies"][0];
    QCOMPARE(ball["name"].get<std::string>(), std::string("ball"));
    for (const char* key : {"position", "orientation", "linearVelocity", "angularVelocity", "awake"})
        QVERIFY2(ball.contains(key), key);
    // Semi-implicit Euler's exact discrete answer: y = y0 + v0 t - 1/2 g t^2 - 1/2 g h t.
    const double t = 1.0, h = 0.01, g = 9.81;
    const double y = 10.0 + 3.0 * t - 0.5 * g * t * t - 0.5 * g * h * t;
    QVERIFY(std::abs(ball["position"][0].get<double>() - 2.0) < 1e-4);
    QVERIFY(std::abs(ball["position"][1].get<double>() - y) < 1e-4);
    QVERIFY(std::abs(ball["linearVelocity"][1].get<double>() - (3.0 - g * t)) < 1e-4);
    // Energy: kinetic + potential with potential -m g.x; semi-implicit Euler's drift is O(h).
    const double e0 = 0.5 * 1.5 * 13.0 + 1.5 * g * 10.0;
    QVERIFY(std::abs(report["metrics"]["totalEnergy"].get<double>() - e0) < 1.5 * g * 0.5 * g * h * t + 1e-3);
}

void TestRunner::optionsChangeTheSettings() {
    const RunResult r = runRunner({writeScene(kProjectileScene), "--steps", "10", "--dt", "0.005", "--substeps", "3",
                                   "--iterations", "12", "--set", "gravity=[0,0,0]", "--set", "damping.linear=1"});
    QCOMPARE(r.exitCode, 0);
    const auto report = nlohmann::json::parse(r.out.toStdString());
    QCOMPARE(report["dt"].get<float>(), 0.005f);
    QCOMPARE(report["substeps"].get<int>(), 3);
    QCOMPARE(report["effects"]["gravity"].get<bool>(), false);  // zero gravity: nothing to do
    QCOMPARE(report["effects"]["damping"].get<bool>(), true);
    // v = 3 exp(-1 * 0.05) along y with no gravity.
    QVERIFY(std::abs(report["bodies"][0]["linearVelocity"][1].get<double>() - 3.0 * std::exp(-0.05)) < 1e-5);
}

void TestRunner::unknownSettingIsNamed() {
    const RunResult r = runRunner({writeScene(kProjectileScene), "--set", "solver.bogus=3"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("solver.bogus"), qPrintable(r.err));
}

void TestRunner::helpListsEverySetting() {
    const RunResult r = runRunner({"--help"});
    QCOMPARE(r.exitCode, 0);
    const QStringList lines = r.out.split('\n');
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const QString key = QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size()));
        const QString doc = QString::fromLatin1(info.doc.data(), static_cast<qsizetype>(info.doc.size()));
        const QString range = info.type == simcore::SettingType::Bool     ? QString("true or false")
                              : info.type == simcore::SettingType::Choice ? QString::fromStdString(info.choiceList())
                                                                          : QString::fromStdString(info.range.describe());
        const bool listed = std::any_of(lines.begin(), lines.end(), [&](const QString& line) {
            return line.startsWith("  " + key + "  ") && line.contains(range) && line.endsWith(doc);
        });
        QVERIFY2(listed, qPrintable(key));
    }
}

void TestRunner::secondsBecomeSteps() {
    const RunResult r = runRunner({writeScene(kProjectileScene), "--seconds", "2"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(nlohmann::json::parse(r.out.toStdString())["steps"].get<int>(), 200);
}

void TestRunner::traceAndOutFilesAreWritten() {
    const QString trace = dir_.filePath("trace.csv");
    const QString out = dir_.filePath("report.json");
    const RunResult r = runRunner({writeScene(kProjectileScene), "--steps", "5", "--trace", trace, "--out", out});
    QCOMPARE(r.exitCode, 0);
    QFile traceFile(trace);
    QVERIFY(traceFile.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(traceFile.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + 6);  // header, then steps 0..5 for one body
    QVERIFY(lines[0].startsWith("step,time,body,x,y,z"));
    QVERIFY(lines[1].startsWith("0,0,0,0,10,0"));
    QFile outFile(out);
    QVERIFY(outFile.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(outFile.readAll()).trimmed(), r.out.trimmed());
}

void TestRunner::saveWithZeroStepsConvertsTheScene() {
    const QString saved = dir_.filePath("saved.json");
    const RunResult r = runRunner({writeScene(kProjectileScene), "--steps", "0", "--save", saved, "--set",
                                   "solver.velocityIterations=17"});
    QCOMPARE(r.exitCode, 0);
    const RunResult again = runRunner({saved, "--steps", "0"});
    QCOMPARE(again.exitCode, 0);
    QFile file(saved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto scene = nlohmann::json::parse(file.readAll().toStdString());
    QCOMPARE(scene["format"].get<std::string>(), std::string("interplay.scene"));
    QCOMPARE(scene["settings"]["solver"]["velocityIterations"].get<int>(), 17);
    QCOMPARE(scene["bodies"][0]["name"].get<std::string>(), std::string("ball"));
}

// The key works end to end: read, simulated ((5/7) C g = 0.70 m/s^2 of deceleration: 3 m/s becomes
// 2.30 m/s in a second) as part of the friction effect, and saved again.
void TestRunner::rollingResistanceFromTheFile() {
    const QString saved = dir_.filePath("rolling_saved.json");
    const RunResult r = runRunner({writeScene(kRollingScene), "--seconds", "1", "--save", saved});
    QCOMPARE(r.exitCode, 0);
    const auto report = nlohmann::json::parse(r.out.toStdString());
    const double v = report["bodies"][1]["linearVelocity"][0].get<double>();
    const double expected = 3.0 - 5.0 / 7.0 * 0.1 * 9.81 * 1.0;
    // 1 %: the closed form holds to 0.01 % in test_contacts; the first steps' settling adds little.
    QVERIFY2(std::abs(v - expected) < 0.01 * expected, qPrintable(QString("v = %1 m/s, expected %2").arg(v).arg(expected)));
    QCOMPARE(report["effects"]["friction"].get<bool>(), true);
    QFile file(saved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto scene = nlohmann::json::parse(file.readAll().toStdString());
    QCOMPARE(scene["bodies"][1]["rollingResistance"].get<double>(), 0.1);
    QVERIFY(!scene["bodies"][0].contains("rollingResistance"));  // not set on the ground
}

QTEST_GUILESS_MAIN(TestRunner)
#include "test_runner.moc"
