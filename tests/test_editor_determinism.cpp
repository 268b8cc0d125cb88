// The editor simulates what the runner simulates: a demo scene opened in the document and played by
// the SimulationController (Step, stepFrames, or the real-time Play loop) reaches, after N steps, the
// bit-identical state `interplay-run SCENE --steps N` reports, and so does the library. Play's
// clock and time scale decide only how many fixed steps run per batch on its worker thread, and a
// read of the world from the GUI thread only where a batch ends, never what a step does. Reset and
// an edit undone give back the same run; edits made before the first step run as the saved file.

#include "support/editor_session.h"
#include "support/runner_states.h"
#include "support/state_hash.h"

#include "app/document/undo_commands.h"

#include "simcore/io/scene_io.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using interplay::SceneDocument;
using interplay::SimulationController;
using test_support::stateHash;

namespace {

QString scenePath(const QString& name) {
    return QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/") + name;
}

// What the library alone gives: the scene file built and stepped `steps` times.
std::uint64_t libraryHash(const QString& path, int steps) {
    simcore::SceneLoadResult loaded = simcore::loadSceneFile(path.toStdString());
    if (!loaded.ok()) qFatal("cannot load %s", qPrintable(path));
    simcore::BuiltWorld built = simcore::buildWorld(*loaded.scene);
    for (int i = 0; i < steps; ++i) built.world.step();
    return stateHash(built.world);
}

// Loads `path` into `simulation` and plays it at the largest time scale (tests stay short);
// empty, or why it could not.
QString playFastForward(SimulationController& simulation, const QString& path) {
    SceneDocument document;
    QString error;
    if (!document.load(path, &error) || !simulation.setScene(document.scene(), &error)) return error;
    simulation.setTimeScale(SimulationController::kMaxTimeScale);
    simulation.play();
    return {};
}

// The runner's state after `steps` steps of `path` must be `world`'s, bit for bit.
void compareWithRunner(const QString& path, int steps, const simcore::World& world) {
    QString error;
    const auto runner = test_support::runnerBodyStates(path, steps, &error);
    QVERIFY2(runner, qPrintable(error));
    QCOMPARE(stateHash(*runner), stateHash(world));
}

}  // namespace

class TestEditorDeterminism : public QObject {
    Q_OBJECT

private slots:
    void editorMatchesRunner_data();
    void editorMatchesRunner();
    void playLoopMatchesRunner();
    void playLoopReadEveryMillisecondMatchesRunner();
    void undoneEditAndSaveRunTheSame();
};

void TestEditorDeterminism::editorMatchesRunner_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    // Every shape pair, stacking, sleep, restitution, CCD, every joint type, a motor and limits.
    QTest::newRow("mixed_rain") << "mixed_rain.json" << 240;
    QTest::newRow("dominoes") << "dominoes.json" << 240;
    QTest::newRow("incline") << "incline.json" << 240;
    QTest::newRow("bullets_vs_walls") << "bullets_vs_walls.json" << 120;
    QTest::newRow("pendulums") << "pendulums.json" << 240;
    QTest::newRow("ragdoll") << "ragdoll.json" << 240;
    QTest::newRow("hinge_door") << "hinge_door.json" << 240;
    QTest::newRow("tumbling") << "tumbling.json" << 240;
}

void TestEditorDeterminism::editorMatchesRunner() {
    QFETCH(QString, scene);
    QFETCH(int, steps);
    const QString path = scenePath(scene);

    SceneDocument document;
    QString error;
    QVERIFY2(document.load(path, &error), qPrintable(error));
    SimulationController simulation;
    QVERIFY2(simulation.setScene(document.scene(), &error), qPrintable(error));
    const std::uint64_t initial = stateHash(*simulation.world());
    simulation.stepFrames(steps);
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(steps));
    const std::uint64_t editor = stateHash(*simulation.world());
    // A scene that never moved would prove nothing.
    QVERIFY(editor != initial);

    const auto runner = test_support::runnerBodyStates(path, steps, &error);
    QVERIFY2(runner, qPrintable(error));
    QCOMPARE(runner->size(), simulation.world()->bodyCount());
    QCOMPARE(stateHash(*runner), editor);
    QCOMPARE(libraryHash(path, steps), editor);

    // Reset returns to the authored scene exactly; the Step button (one step at a time) runs the same.
    simulation.reset();
    QCOMPARE(stateHash(*simulation.world()), initial);
    for (int i = 0; i < steps; ++i) simulation.stepOnce();
    QCOMPARE(stateHash(*simulation.world()), editor);
}

void TestEditorDeterminism::playLoopMatchesRunner() {
    // Real-time playback: the timer and accumulator pick how many steps run per tick (fast-forward at
    // the largest time scale, so the test stays short); whatever count it stops at, the state is the
    // runner's for that count.
    const QString path = scenePath(QStringLiteral("dominoes.json"));
    SimulationController simulation;
    const QString error = playFastForward(simulation, path);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(simulation.world()->stepCount() >= 150, 30'000);
    simulation.pause();
    const int steps = static_cast<int>(simulation.world()->stepCount());
    qInfo("Play ran %d steps", steps);

    compareWithRunner(path, steps, *simulation.world());
}

void TestEditorDeterminism::playLoopReadEveryMillisecondMatchesRunner() {
    // Every read of the world while playing (a pick, a panel) ends the batch in flight after its
    // step under way: read every millisecond, the batches are cut anywhere, and the run is the same.
    const QString path = scenePath(QStringLiteral("dominoes.json"));
    SimulationController simulation;
    const QString error = playFastForward(simulation, path);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QElapsedTimer clock;
    clock.start();
    int reads = 0;
    while (simulation.world()->stepCount() < 150) {
        QVERIFY(clock.elapsed() < 30'000);
        QTest::qWait(1);
        ++reads;
    }
    simulation.pause();
    const int steps = static_cast<int>(simulation.world()->stepCount());
    qInfo("Play ran %d steps, read %d times", steps, reads);

    compareWithRunner(path, steps, *simulation.world());
}

void TestEditorDeterminism::undoneEditAndSaveRunTheSame() {
    // Edits reach the paused world in place (wired as in the window); a world edited before its
    // first step runs as the edited scene saved and reopened, so the runner runs the saved file to
    // the editor's bits. Undone and reset, the run is the original file's again.
    const QString path = scenePath(QStringLiteral("ragdoll.json"));
    const int steps = 180;
    test_support::EditorSession session;
    SceneDocument& document = session.document;
    QString error;
    QVERIFY2(document.load(path, &error), qPrintable(error));

    simcore::SceneBody moved = document.body(1);
    moved.body.position.y += 0.37f;
    document.undoStack()->push(new interplay::ChangeBodies(&document, QStringLiteral("Move"),
                                                           interplay::BodyField::Position, {1}, {moved}));
    simcore::WorldSettings settings = document.scene().settings;
    settings.substeps += 3;
    document.undoStack()->push(new interplay::ChangeSettings(&document, QStringLiteral("Substeps"),
                                                             QStringLiteral("substeps"), settings));
    document.undoStack()->push(new interplay::RemoveBodies(&document, {0, 2}));
    session.simulation.stepFrames(steps);
    const std::uint64_t edited = stateHash(*session.simulation.world());

    const QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("edited.json"));
    QVERIFY2(document.save(saved, &error), qPrintable(error));
    const auto runner = test_support::runnerBodyStates(saved, steps, &error);
    QVERIFY2(runner, qPrintable(error));
    QCOMPARE(stateHash(*runner), edited);

    document.undoStack()->setIndex(0);
    session.simulation.reset();
    session.simulation.stepFrames(steps);
    const std::uint64_t undone = stateHash(*session.simulation.world());
    QCOMPARE(undone, libraryHash(path, steps));
    QVERIFY(edited != undone);  // the edits did change the run
    QVERIFY2(session.editErrors.isEmpty() && session.simulationErrors.isEmpty(),
             qPrintable((session.editErrors + session.simulationErrors).join(u'\n')));
}

QTEST_GUILESS_MAIN(TestEditorDeterminism)
#include "test_editor_determinism.moc"
