// The worker tuner (simcore/parallel/worker_tuner.h) against made-up timings: it learns both ways,
// runs the faster, probes the other less often while its choice holds and within its cost budget,
// judges probes by their second step and charges what moving the data costs to them, and switches
// when a scene grows or shrinks. Pure bookkeeping, no thread: the world's use of it, with a pool,
// is in test_threads.

#include "simcore/parallel/worker_tuner.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace simcore;

namespace {

// Steps a one-stage tuner against a machine where a stage takes inlineMs(step) without workers and
// workersMs(step) with them; returns, by step, whether it ran with workers.
template <class InlineMs, class WorkersMs>
std::vector<bool> tune(WorkerTuner& tuner, int steps, InlineMs inlineMs, WorkersMs workersMs, int firstStep = 0) {
    std::vector<bool> ways;
    for (int step = firstStep; step < firstStep + steps; ++step) {
        const bool withWorkers = tuner.useWorkers();
        ways.push_back(withWorkers);
        tuner.record(withWorkers ? workersMs(step) : inlineMs(step));
    }
    return ways;
}

std::vector<int> stepsWith(const std::vector<bool>& ways, bool withWorkers) {
    std::vector<int> steps;
    for (std::size_t i = 0; i < ways.size(); ++i)
        if (ways[i] == withWorkers) steps.push_back(static_cast<int>(i));
    return steps;
}

// The runs of steps one way (a probe, the learning of a way): each run's first step and length.
struct Run {
    int first = 0, length = 0;
};
std::vector<Run> runsWith(const std::vector<bool>& ways, bool withWorkers) {
    std::vector<Run> runs;
    for (std::size_t i = 0; i < ways.size(); ++i) {
        if (ways[i] != withWorkers) continue;
        if (i > 0 && ways[i - 1] == withWorkers) ++runs.back().length;
        else runs.push_back({static_cast<int>(i), 1});
    }
    return runs;
}

// Checks that `ways` runs with workers from its first step, and inline only in probes: at most
// two steps in every kMinProbeInterval, and one probe more.
void verifyWorkersButForProbes(const std::vector<bool>& ways) {
    const auto inlineSteps = std::count(ways.begin(), ways.end(), false);
    QVERIFY2(inlineSteps <= 2 * (1 + static_cast<int>(ways.size()) / WorkerTuner::kMinProbeInterval),
             qPrintable(QString::number(inlineSteps)));
    QCOMPARE(ways.front(), true);
}

}  // namespace

class TestWorkerTuner : public QObject {
    Q_OBJECT

private slots:
    void tunerTriesBothWaysThenRunsTheFaster_data();
    void tunerTriesBothWaysThenRunsTheFaster();
    void tunerProbesLessOftenWhileItsChoiceHolds();
    void tunerJudgesAProbeByItsSecondStep();
    void tunerLearnsThroughATrendAndAPreemption_data();
    void tunerLearnsThroughATrendAndAPreemption();
    void tunerChargesTheStepAfterAProbeToTheProbe();
    void tunerChargesTheStepBackOnlyForMovingTheData();
    void tunerProbesAgainSoonAfterAProbeTheSceneOutgrew();
    void tunerSwitchesWhenTheOtherWayGetsFaster();
    void tunerProbesSoonWhenAStageGrows();
    void tunerResumesWithoutChargingAProbe();
};

void TestWorkerTuner::tunerTriesBothWaysThenRunsTheFaster_data() {
    QTest::addColumn<double>("inlineMs");
    QTest::addColumn<double>("workersMs");
    QTest::addColumn<bool>("workersWin");
    QTest::newRow("workers twice as fast") << 2.0 << 1.0 << true;
    QTest::newRow("workers slower") << 1.0 << 1.6 << false;
}

void TestWorkerTuner::tunerTriesBothWaysThenRunsTheFaster() {
    QFETCH(double, inlineMs);
    QFETCH(double, workersMs);
    QFETCH(bool, workersWin);
    WorkerTuner tuner;
    // The first step (which makes every pair) is ten times the rest: it must not decide, so it is
    // not learnt from. Two steps each way, the first way twice, and the faster runs.
    const std::vector<bool> ways = tune(
        tuner, 600, [&](int step) { return step == 0 ? 10.0 * inlineMs : inlineMs; }, [&](int) { return workersMs; });
    const int learnt = 6;
    const std::vector<bool> learning(ways.begin(), ways.begin() + learnt);
    QCOMPARE(learning, (std::vector<bool>{false, false, true, true, false, false}));
    const std::vector<bool> chosen(ways.begin() + learnt, ways.begin() + learnt + WorkerTuner::kMinProbeInterval);
    QCOMPARE(std::count(chosen.begin(), chosen.end(), workersWin), std::ptrdiff_t{WorkerTuner::kMinProbeInterval});
    // From then on, the other way runs only in probes of two steps, fewer and fewer as they confirm
    // the choice.
    const std::vector<Run> probes = runsWith(std::vector<bool>(ways.begin() + learnt, ways.end()), !workersWin);
    QVERIFY2(probes.size() <= 8, qPrintable(QString::number(probes.size())));
    QVERIFY(probes.size() >= 3);  // but it keeps checking
    for (const Run& probe : probes)
        if (probe.first + learnt + probe.length < static_cast<int>(ways.size())) QCOMPARE(probe.length, 2);
}

void TestWorkerTuner::tunerProbesLessOftenWhileItsChoiceHolds() {
    WorkerTuner tuner;
    // Each probe loses 4 ms against 1 ms steps the chosen way: 2 ms in each of its two steps.
    const std::vector<bool> ways = tune(
        tuner, 2000, [](int) { return 1.0; }, [](int) { return 3.0; });
    const std::vector<Run> probes = runsWith(ways, true);  // the first is the learning of workers
    QVERIFY(probes.size() >= 5);
    const int coveringSteps = static_cast<int>(std::lround(4.0 / WorkerTuner::kProbeCostShare));  // 200
    int interval = WorkerTuner::kMinProbeInterval;
    for (std::size_t p = 1; p < probes.size(); ++p) {
        // Two probe steps, one moving back (after the learning of workers, two: inline is learnt
        // again), then `interval` steps the chosen way, and as many more as the loss of the
        // learning or of the probe that lost needs to be kProbeCostShare of their time; then the
        // next probe.
        QCOMPARE(probes[p].length, 2);
        const int stepsBack = p == 1 ? 2 : 1;
        const int chosenSteps = std::max(interval, coveringSteps);
        QCOMPARE(probes[p].first - probes[p - 1].first, 2 + stepsBack + chosenSteps);
        interval = std::min(2 * interval, WorkerTuner::kMaxProbeInterval);
    }
    QCOMPARE(interval, WorkerTuner::kMaxProbeInterval);
    // Learning that loses 40 ms against 0.01 ms steps is followed by 2 s of them (200 000 steps)
    // before the first probe: the tuner spends at most kProbeCostShare of a tiny step's time on
    // probes.
    WorkerTuner tiny;
    const std::vector<bool> tinyWays = tune(
        tiny, 30000, [](int) { return 0.01; }, [](int) { return 20.01; });
    const std::vector<Run> tinyProbes = runsWith(tinyWays, true);
    QCOMPARE(tinyProbes.size(), std::size_t{1});  // the learning of workers
}

void TestWorkerTuner::tunerJudgesAProbeByItsSecondStep() {
    // Workers spread the data over both cores; inline, the first step gathers it onto one and takes
    // 3 ms, the next ones 1 ms; with workers 1.5 ms. Judged by its first step, an inline probe
    // would lose and the workers would stay.
    WorkerTuner tuner(WorkerTuner::FirstWay::Workers);
    std::vector<bool> ways;
    bool lastWithWorkers = true;
    for (int step = 0; step < 300; ++step) {
        const bool withWorkers = tuner.useWorkers();
        ways.push_back(withWorkers);
        tuner.record(withWorkers ? 1.5 : lastWithWorkers ? 3.0 : 1.0);
        lastWithWorkers = withWorkers;
    }
    // Learnt (two steps each way, workers twice), then inline but for probes of two steps.
    QCOMPARE(ways[6], false);
    const std::vector<Run> probes = runsWith(std::vector<bool>(ways.begin() + 6, ways.end()), true);
    QVERIFY(!probes.empty());
    for (const Run& probe : probes) QCOMPARE(probe.length, 2);
    QCOMPARE(ways.back(), false);
}

void TestWorkerTuner::tunerLearnsThroughATrendAndAPreemption_data() {
    QTest::addColumn<double>("trendMsPerStep");
    QTest::addColumn<double>("preemptionMs");
    // A tower of 40 settling at 2 threads (2026-12-07): its step grew by a third over the learning
    // steps, and one step in a few hundred was preempted for 40-80 us. Workers lose 3 us a step.
    QTest::newRow("settling") << 0.004 << 0.0;
    QTest::newRow("preempted while learning inline") << 0.0 << 0.06;
}

void TestWorkerTuner::tunerLearnsThroughATrendAndAPreemption() {
    QFETCH(double, trendMsPerStep);
    QFETCH(double, preemptionMs);
    const auto inlineMs = [&](int step) {
        return 0.04 + trendMsPerStep * std::min(step, 10) + (step == 3 ? preemptionMs : 0.0);
    };
    const auto workersMs = [&](int step) { return 0.003 + 0.04 + trendMsPerStep * std::min(step, 10); };
    // Learnt from step 1 (workers) against step 3 (inline) alone, either made workers look faster.
    QVERIFY(workersMs(1) < inlineMs(3));
    WorkerTuner tuner(WorkerTuner::FirstWay::Workers);
    const std::vector<bool> ways = tune(tuner, 6 + WorkerTuner::kMinProbeInterval, inlineMs, workersMs);
    QCOMPARE(std::vector<bool>(ways.begin() + 6, ways.end()), std::vector<bool>(WorkerTuner::kMinProbeInterval, false));
}

void TestWorkerTuner::tunerChargesTheStepAfterAProbeToTheProbe() {
    // Inline runs 1 ms a step, a probe with workers 3 ms in each of its steps, and the step after
    // a probe 3 ms too, as it moves the data back: each probe costs 6 ms over the chosen way.
    WorkerTuner tuner;
    bool lastWithWorkers = false;
    double spentMs = 0.0;
    int counted = 0;
    // Before the probes reach kMaxProbeInterval apart, where their cost, not their interval, sets
    // how often they come.
    for (int step = 0; step < 1000; ++step) {
        const bool withWorkers = tuner.useWorkers();
        const double ms = withWorkers || lastWithWorkers ? 3.0 : 1.0;
        tuner.record(ms);
        lastWithWorkers = withWorkers;
        if (step >= 5) {  // past the learning of both ways and the step back from it
            spentMs += ms;
            ++counted;
        }
    }
    // Probes and the steps after them take at most kProbeCostShare of the chosen way's time, and
    // one probe's cost at the end (here 18 ms over 995, three probes).
    const double chosenMs = counted * 1.0;
    QVERIFY2(spentMs - chosenMs <= WorkerTuner::kProbeCostShare * chosenMs + 6.0,
             qPrintable(QString("%1 ms over %2").arg(spentMs - chosenMs).arg(chosenMs)));
}

void TestWorkerTuner::tunerChargesTheStepBackOnlyForMovingTheData() {
    // mixed1k at 2 threads (2026-12-07): inline was learnt as the faster while the bodies fell, a
    // probe of workers lost against those small steps, and the step back came as the landing
    // tripled the step. Charged in full to the probe, it put off the next one past the landing.
    // Here a step that changes way pays 0.2 ms to move the data; workers lose while the scene is
    // small and take 0.6 of inline's time while it is big (1.5 ms inline for 60 steps).
    const auto run = [](int growthStep, std::vector<bool>& ways) {
        WorkerTuner tuner(WorkerTuner::FirstWay::Workers);
        bool lastWithWorkers = true;
        for (int step = 0; step < growthStep + 80; ++step) {
            const bool big = step >= growthStep && step < growthStep + 60;
            const bool withWorkers = tuner.useWorkers();
            const double inlineMs = big ? 1.5 : 0.5;
            const double ms =
                (withWorkers ? (big ? 0.6 * inlineMs : 0.55) : inlineMs) + (withWorkers != lastWithWorkers ? 0.2 : 0.0);
            tuner.record(ms);
            ways.push_back(withWorkers);
            lastWithWorkers = withWorkers;
        }
    };
    // Where the first probe of workers after the learning falls in a scene that stays small.
    std::vector<bool> small;
    run(1000, small);
    const std::vector<Run> probes = runsWith(std::vector<bool>(small.begin() + 6, small.end()), true);
    QVERIFY(!probes.empty());
    const int stepBack = 6 + probes.front().first + probes.front().length;
    // The same scene growing from the step back after that probe on.
    std::vector<bool> landing;
    run(stepBack, landing);
    const auto bigWithWorkers = std::count(landing.begin() + stepBack, landing.begin() + stepBack + 60, true);
    QVERIFY2(bigWithWorkers >= 30, qPrintable(QString("%1 of 60 big steps with workers").arg(bigWithWorkers)));
}

void TestWorkerTuner::tunerProbesAgainSoonAfterAProbeTheSceneOutgrew() {
    // pile1k at 2 threads with the cores far apart (2026-12-07): workers won while the boxes fell,
    // inline won by a quarter as they settled, and the inline probe that could have shown it ran
    // as the step grew by half. Here workers take 1 ms a step and inline 1.1 until step 100, then
    // 0.7; from the first inline probe after step 100 on, every step takes 1.6 times as long.
    const auto run = [](int growthStep) {
        WorkerTuner tuner(WorkerTuner::FirstWay::Workers);
        return tune(
            tuner, 600, [=](int step) { return (step < 100 ? 1.1 : 0.7) * (step >= growthStep ? 1.6 : 1.0); },
            [=](int step) { return step >= growthStep ? 1.6 : 1.0; });
    };
    // Where that probe falls in a scene that does not grow.
    const std::vector<bool> steady = run(1000);
    const std::vector<Run> probes = runsWith(std::vector<bool>(steady.begin() + 100, steady.end()), false);
    QVERIFY(!probes.empty());
    const int growthStep = 100 + probes.front().first;
    const std::vector<bool> growing = run(growthStep);
    // The probe loses (1.12 ms against 1.0 before it) and the workers run on; their steps after it
    // (1.6 ms) show it lost to the scene, and the next probe comes within kMinProbeInterval steps:
    // inline from then on, not from the probe after the interval the probes had grown to (128).
    QCOMPARE(growing[growthStep], false);
    QCOMPARE(growing[growthStep + 2], true);
    const int settled = growthStep + 4 + WorkerTuner::kMinProbeInterval + 2;
    QCOMPARE(std::count(growing.begin() + settled, growing.begin() + settled + WorkerTuner::kMinProbeInterval, false),
             std::ptrdiff_t{WorkerTuner::kMinProbeInterval});
}

void TestWorkerTuner::tunerSwitchesWhenTheOtherWayGetsFaster() {
    WorkerTuner tuner;
    // A scene that grows: the workers lose for 300 steps, then win by 2x.
    const auto inlineMs = [](int step) { return step < 300 ? 1.0 : 4.0; };
    const auto workersMs = [](int step) { return step < 300 ? 1.5 : 2.0; };
    const std::vector<bool> ways = tune(tuner, 900, inlineMs, workersMs);
    QCOMPARE(ways[299], false);
    // The change shows at the next probe: at most the longest interval later.
    const std::vector<int> after = stepsWith(std::vector<bool>(ways.begin() + 300, ways.end()), false);
    QVERIFY2(after.empty() || after.front() <= WorkerTuner::kMaxProbeInterval + 1,
             qPrintable(QString::number(after.front())));
    QCOMPARE(ways.back(), true);
    QVERIFY(std::count(ways.begin() + 300 + WorkerTuner::kMaxProbeInterval + 1, ways.end(), false) <= 8);
    // Two ways within the switch ratio, with noise of that size: the choice holds, so probes keep
    // getting rarer (flipping would probe every 9 steps: over 100 changes of way).
    WorkerTuner close;
    const std::vector<bool> near = tune(
        close, 600, [](int) { return 1.0; }, [](int step) { return step % 2 ? 0.97 : 1.01; });
    int changes = 0;
    for (std::size_t i = 1; i < near.size(); ++i) changes += near[i] != near[i - 1];
    QVERIFY2(changes <= 16, qPrintable(QString::number(changes)));
}

void TestWorkerTuner::tunerProbesSoonWhenAStageGrows() {
    // pile1k's solve as the boxes land: 0.03 ms a step for 300 steps, where workers lose, then 1 ms
    // inline against 0.6 with workers. By then the probes that lost have grown 64 steps apart.
    WorkerTuner tuner;
    const auto inlineMs = [](int step) { return step < 300 ? 0.03 : 1.0; };
    const auto workersMs = [](int step) { return step < 300 ? 0.04 : 0.6; };
    const std::vector<bool> ways = tune(tuner, 400, inlineMs, workersMs);
    QCOMPARE(ways[299], false);
    // The growth shows in the second step of it (a way's time is the faster of its last two), the
    // probe takes two more, and then workers run but for probes of inline.
    verifyWorkersButForProbes(std::vector<bool>(ways.begin() + 304, ways.end()));
}

void TestWorkerTuner::tunerResumesWithoutChargingAProbe() {
    // A world's tuner is not told of steps with nothing the workers could share. Told again after a
    // stretch of them, the first step's time is the scene's, not the cost of a probe (mixed1k's
    // prepare and solver, when they were tuned on their own, learnt inline at 0.07 ms a step while
    // the boxes fell and took 0.45 ms when timed again 47 steps later: charged as a lost probe's
    // cost, that put their next probe off past the boxes' landing, 2026-12-07).
    WorkerTuner tuner(WorkerTuner::FirstWay::Workers);
    const std::vector<bool> learning = tune(
        tuner, 6, [](int) { return 0.07; }, [](int) { return 0.09; });
    QCOMPARE(learning.back(), true);  // the first way again, so the chosen way is a move away
    const std::vector<bool> resumed = tune(
        tuner, 30, [](int) { return 1.0; }, [](int) { return 0.6; });
    QCOMPARE(resumed.front(), false);
    // The growth brings a probe as soon as the learning's loss has been paid for (2 steps), the
    // probe takes two: workers from the sixth step on, but for probes of inline.
    verifyWorkersButForProbes(std::vector<bool>(resumed.begin() + 6, resumed.end()));
}

QTEST_APPLESS_MAIN(TestWorkerTuner)
#include "test_worker_tuner.moc"
