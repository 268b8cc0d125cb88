// Determinism: the same scene and settings give bit-identical states, run after run, across
// save -> load, and between the library and the headless runner (same binary, same machine).

#include "support/runner_states.h"
#include "support/state_hash.h"

#include "simcore/io/scene_io.h"

#include <QtTest>

using namespace simcore;
using test_support::stateHash;

namespace {

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

    QString error;
    const auto runner = test_support::runnerBodyStates(QString(INTERPLAY_SOURCE_DIR) + "/" + scene, steps, &error);
    QVERIFY2(runner, qPrintable(error));
    QCOMPARE(runner->size(), built.world.bodyCount());
    QCOMPARE(stateHash(*runner), stateHash(built.world));
}

QTEST_GUILESS_MAIN(TestDeterminism)
#include "test_determinism.moc"
