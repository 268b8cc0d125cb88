// The parts Play runs on, alone and without a window: the worker thread runs each job away from
// the caller, in order, and stop() ends one that sleeps at once; the real-time meter
// gives simulated seconds per wall second over its window; a snapshot holds what World::draw
// emits; and the controller, playing, steps on the worker while the caller's event loop runs,
// shows in snapshot() what the last batch left, and lets world() in only after the step in flight.

#include "app/simulation/real_time_meter.h"
#include "app/simulation/simulation_controller.h"
#include "app/simulation/worker_thread.h"
#include "app/simulation/world_snapshot.h"

#include "support/scene_builders.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <chrono>
#include <thread>
#include <vector>

using interplay::RealTimeMeter;
using interplay::SimulationController;
using interplay::WorkerThread;
using interplay::WorldSnapshot;

namespace {

// A ground and a 3 x 3 x 3 grid of cubes dropped onto it.
simcore::Scene cubeScene() {
    simcore::Scene scene;
    simcore::SceneBody ground;
    ground.body.motion = simcore::MotionType::Static;
    ground.body.shape = simcore::Shape::box(simcore::Vec3(20.0f, 0.5f, 20.0f));
    ground.body.position = simcore::Vec3(0.0f, -0.5f, 0.0f);
    scene.bodies.push_back(ground);
    for (const simcore::Vec3& centre : scene_builders::gridCentres(3, 3, 3, 1.2f, 1.0f)) {
        simcore::SceneBody cube;
        cube.body = scene_builders::cube(centre);
        scene.bodies.push_back(cube);
    }
    return scene;
}

}  // namespace

class TestPlaybackParts : public QObject {
    Q_OBJECT

private slots:
    void workerRunsEachJobAwayFromTheCallerInOrder();
    void workerStopEndsAJobThatSleeps();
    void meterGivesSimulatedSecondsPerWallSecond_data();
    void meterGivesSimulatedSecondsPerWallSecond();
    void meterForgetsWhatRanBeforeItsWindow();
    void snapshotHoldsWhatWorldDrawEmits();
    void playingStepsWhileTheEventLoopRuns();
};

void TestPlaybackParts::workerRunsEachJobAwayFromTheCallerInOrder() {
    WorkerThread worker;
    std::vector<int> order;  // the jobs, in the order they ran
    std::thread::id jobThread;
    worker.start([&] {
        jobThread = std::this_thread::get_id();
        order.push_back(1);
    });
    worker.start([&] { order.push_back(2); });  // waits for the first
    worker.wait();
    QVERIFY(jobThread != std::this_thread::get_id());
    QCOMPARE(order, (std::vector<int>{1, 2}));
}

void TestPlaybackParts::workerStopEndsAJobThatSleeps() {
    WorkerThread worker;
    bool slept = true;
    worker.start([&] { slept = worker.sleepFor(std::chrono::seconds(60)); });
    QElapsedTimer clock;
    clock.start();
    worker.stop();
    QVERIFY(!slept);
    QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));
    // The next job is not asked to stop.
    bool stopRequested = true;
    worker.start([&] { stopRequested = worker.stopRequested() || !worker.sleepFor(std::chrono::milliseconds(1)); });
    worker.wait();
    QVERIFY(!stopRequested);
}

void TestPlaybackParts::meterGivesSimulatedSecondsPerWallSecond_data() {
    QTest::addColumn<double>("simulatedPerBatch");  // s, a batch every 1/60 s of wall time
    QTest::addColumn<double>("factor");
    QTest::newRow("real time") << 1.0 / 60.0 << 1.0;
    QTest::newRow("behind") << 0.42 / 60.0 << 0.42;
    QTest::newRow("slow motion asked") << 0.25 / 60.0 << 0.25;
}

void TestPlaybackParts::meterGivesSimulatedSecondsPerWallSecond() {
    QFETCH(double, simulatedPerBatch);
    QFETCH(double, factor);
    RealTimeMeter meter;
    meter.restart(10.0);
    QVERIFY(!meter.factor());
    double now = 10.0;
    for (int batch = 1; batch <= 120; ++batch) {
        now = 10.0 + batch / 60.0;
        meter.add(now, simulatedPerBatch);
        // Nothing said before a quarter second, whatever the first batches did.
        if (now - 10.0 < RealTimeMeter::kMinSpanSeconds) QVERIFY(!meter.factor());
    }
    QVERIFY(meter.factor());
    QVERIFY2(std::abs(*meter.factor() - factor) < 1e-9, qPrintable(QString::number(*meter.factor())));
}

void TestPlaybackParts::meterForgetsWhatRanBeforeItsWindow() {
    RealTimeMeter meter;
    meter.restart(0.0);
    double now = 0.0;
    for (int batch = 1; batch <= 180; ++batch) meter.add(now = batch / 60.0, 1.0 / 60.0);  // 3 s at real time
    for (int batch = 1; batch <= 90; ++batch) meter.add(now += 1.0 / 60.0, 0.5 / 60.0);    // 1.5 s at half
    QVERIFY(meter.factor());
    QVERIFY2(std::abs(*meter.factor() - 0.5) < 0.02, qPrintable(QString::number(*meter.factor())));
    meter.restart(now);
    QVERIFY(!meter.factor());
}

void TestPlaybackParts::snapshotHoldsWhatWorldDrawEmits() {
    simcore::BuiltWorld built = simcore::buildWorld(cubeScene());
    for (int i = 0; i < 60; ++i) built.world.step();  // landed: contacts exist
    simcore::DebugDrawOptions overlays;
    overlays.contacts = true;
    const WorldSnapshot snapshot = WorldSnapshot::take(built.world, overlays);
    QCOMPARE(snapshot.bodies.size(), built.world.bodyCount());
    QCOMPARE(snapshot.stepCount, std::uint64_t(60));
    QCOMPARE(snapshot.simulatedTime, built.world.simulatedTime());
    for (const simcore::BodyId id : built.bodyIds) {
        const WorldSnapshot::Body* body = snapshot.find(id);
        QVERIFY(body);
        QCOMPARE(body->transform.position, built.world.position(id));
        QCOMPARE(body->transform.rotation, built.world.orientation(id));
        QCOMPARE(body->awake, built.world.isAwake(id));
    }
    QVERIFY(!snapshot.contacts.empty());
    QVERIFY(snapshot.bounds.empty());  // not asked for

    // Handed on only as asked.
    struct Count : simcore::DebugDraw {
        int contacts = 0;
        void drawContactPoint(const simcore::DebugContactPoint&) override { ++contacts; }
    };
    Count none, all;
    snapshot.drawOverlays(none, simcore::DebugDrawOptions{});
    snapshot.drawOverlays(all, overlays);
    QCOMPARE(none.contacts, 0);
    QCOMPARE(all.contacts, int(snapshot.contacts.size()));

    // A body destroyed since is not found, and one made since (maybe in its slot) is not in the
    // older snapshot.
    const simcore::BodyId gone = built.bodyIds.back();
    built.world.destroyBody(gone);
    const simcore::BodyId made = built.world.createBody(scene_builders::cube(simcore::Vec3(0.0f, 5.0f, 0.0f)));
    const WorldSnapshot after = WorldSnapshot::take(built.world, {});
    QVERIFY(!after.find(gone));
    QVERIFY(after.find(made));
    QVERIFY(!snapshot.find(made));
}

void TestPlaybackParts::playingStepsWhileTheEventLoopRuns() {
    SimulationController simulation;
    QString error;
    QVERIFY2(simulation.setScene(cubeScene(), &error), qPrintable(error));
    QSignalSpy stepped(&simulation, &SimulationController::stepped);
    simulation.play();
    // The event loop runs (qWait spins it) while the worker steps; each batch is announced.
    QTRY_VERIFY_WITH_TIMEOUT(simulation.snapshot().stepCount >= 30, 10000);
    QVERIFY(stepped.count() > 0);
    // world() waits for the step in flight and takes it in: the snapshot is then the world's.
    const simcore::World* world = simulation.world();
    QCOMPARE(simulation.snapshot().stepCount, world->stepCount());
    QCOMPARE(simulation.series().back().step, world->stepCount());
    // Pause takes in and announces the last batch: nothing steps or is announced after it.
    simulation.pause();
    const std::uint64_t paused = simulation.world()->stepCount();
    const int announced = stepped.count();
    QTest::qWait(100);
    QCOMPARE(simulation.world()->stepCount(), paused);
    QCOMPARE(stepped.count(), announced);
}

QTEST_MAIN(TestPlaybackParts)
#include "test_playback_parts.moc"
