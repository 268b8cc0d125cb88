// Determinism: the same scene and settings give bit-identical states, run after run, across
// save -> load, and between the library and the headless runner (same binary, same machine).

#include "simcore/io/scene_io.h"

#include <QtTest>

#include <nlohmann/json.hpp>

#include <cstring>

using namespace simcore;

namespace {

// FNV-1a over the bytes of every body's pose and velocities: any bit that differs changes it.
std::uint64_t stateHash(const World& world) {
    std::uint64_t hash = 1469598103934665603ull;
    auto mix = [&hash](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    };
    const BodyStorage& b = world.bodies();
    for (std::size_t i = 0; i < b.size(); ++i) {
        mix(&b.centerOfMass[i], sizeof(Vec3));
        mix(&b.orientation[i], sizeof(Quat));
        mix(&b.linearVelocity[i], sizeof(Vec3));
        mix(&b.angularVelocity[i], sizeof(Vec3));
        mix(&b.awake[i], sizeof(std::uint8_t));
    }
    return hash;
}

Scene loadScene(const QString& relativePath) {
    const std::string path = std::string(INTERPLAY_SOURCE_DIR) + "/" + relativePath.toStdString();
    SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok()) qFatal("cannot load %s", path.c_str());
    return *loaded.scene;
}

std::uint64_t runAndHash(const Scene& scene, int steps) {
    BuiltWorld built = buildWorld(scene);
    for (int i = 0; i < steps; ++i) built.world.step();
    return stateHash(built.world);
}

}  // namespace

class TestDeterminism : public QObject {
    Q_OBJECT

private slots:
    void sameSceneSameBits_data();
    void sameSceneSameBits();
    void runnerMatchesTheLibrary();
};

void TestDeterminism::sameSceneSameBits_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    // Scenes with every shape pair, collisions, friction, restitution, sleeping and waking.
    QTest::newRow("mixed rain") << "scenes/mixed_rain.json" << 240;
    QTest::newRow("dominoes") << "scenes/dominoes.json" << 240;
    QTest::newRow("newton's cradle") << "scenes/newtons_cradle.json" << 240;
    QTest::newRow("incline") << "scenes/incline.json" << 240;
    QTest::newRow("tumbling") << "scenes/tumbling.json" << 240;
}

void TestDeterminism::sameSceneSameBits() {
    QFETCH(QString, scene);
    QFETCH(int, steps);
    const Scene loaded = loadScene(scene);
    const std::uint64_t first = runAndHash(loaded, steps);
    QCOMPARE(runAndHash(loaded, steps), first);

    // Saving writes every float exactly, so the reloaded scene runs to the same bits.
    const SceneLoadResult reloaded = parseScene(serializeScene(loaded), "saved");
    QVERIFY(reloaded.ok());
    QCOMPARE(runAndHash(*reloaded.scene, steps), first);

    // And the state did change: a hash of a scene that never moved would prove nothing.
    QVERIFY(runAndHash(loaded, 0) != first);
}

void TestDeterminism::runnerMatchesTheLibrary() {
    const QString scene = "scenes/dominoes.json";
    const int steps = 180;
    BuiltWorld built = buildWorld(loadScene(scene));
    for (int i = 0; i < steps; ++i) built.world.step();

    QProcess runner;
    runner.start(INTERPLAY_RUN_PATH, {QString(INTERPLAY_SOURCE_DIR) + "/" + scene, "--steps", QString::number(steps)});
    QVERIFY(runner.waitForFinished(60'000));
    QCOMPARE(runner.exitCode(), 0);
    const auto report = nlohmann::json::parse(runner.readAllStandardOutput().toStdString());
    const BodyStorage& b = built.world.bodies();
    QCOMPARE(report["bodies"].size(), b.size());
    for (std::size_t i = 0; i < b.size(); ++i) {
        // The report prints each float as the double it converts to exactly.
        const Vec3 p = b.origin(i);
        const auto& position = report["bodies"][i]["position"];
        QCOMPARE(position[0].get<float>(), p.x);
        QCOMPARE(position[1].get<float>(), p.y);
        QCOMPARE(position[2].get<float>(), p.z);
        QCOMPARE(report["bodies"][i]["orientation"][0].get<float>(), b.orientation[i].w);
    }
}

QTEST_GUILESS_MAIN(TestDeterminism)
#include "test_determinism.moc"
