// No heap allocation per step in steady state: every global operator new of this binary counts
// (support/allocation_counter.cpp), and pile1k and pyramid10 step at 1 and 2 threads, after a
// warm-up in which their contact sets and scratch buffers reach their size, without one.

#include "support/allocation_counter.h"

#include "simcore/io/scene_io.h"

#include <QtTest>

#include <filesystem>

using namespace simcore;

class TestStepAllocations : public QObject {
    Q_OBJECT

private slots:
    void steadyStepAllocatesNothing_data();
    void steadyStepAllocatesNothing();
};

void TestStepAllocations::steadyStepAllocatesNothing_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("threads");
    QTest::addColumn<int>("warmUpSteps");
    // pile1k's cubes fall 2 m and settle: 3 s of warm-up, then the pile is a steady contact set.
    for (int threads : {1, 2}) {
        QTest::addRow("pile1k, %d threads", threads) << "pile1k" << threads << 180;
        QTest::addRow("pyramid10, %d threads", threads) << "pyramid10" << threads << 60;
    }
}

void TestStepAllocations::steadyStepAllocatesNothing() {
    QFETCH(QString, scene);
    QFETCH(int, threads);
    QFETCH(int, warmUpSteps);
    const std::filesystem::path path =
        std::filesystem::path(INTERPLAY_SOURCE_DIR) / "scenes/bench" / (scene.toStdString() + ".json");
    SceneLoadResult loaded = loadSceneFile(path);
    QVERIFY(loaded.ok());
    loaded.scene->settings.threads = threads;
    loaded.scene->settings.sleep.enabled = false;  // every body keeps being stepped
    BuiltWorld built = buildWorld(*loaded.scene);
    // The first step makes the contacts and sizes the scratch: it allocates, which shows the
    // counter sees the engine's allocations.
    test_support::startCountingAllocations();
    built.world.step();
    QVERIFY(test_support::stopCountingAllocations() > 0);
    for (int i = 1; i < warmUpSteps; ++i) built.world.step();

    test_support::startCountingAllocations();
    for (int i = 0; i < 30; ++i) built.world.step();
    const std::size_t allocations = test_support::stopCountingAllocations();
    const StepCounters& counters = built.world.lastStepProfile().counters;
    QVERIFY(counters.contactPoints > 0);
    QCOMPARE(counters.awakeBodies, counters.dynamicBodies);
    QCOMPARE(allocations, std::size_t{0});
}

QTEST_GUILESS_MAIN(TestStepAllocations)
#include "test_step_allocations.moc"
