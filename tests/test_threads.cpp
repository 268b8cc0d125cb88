// The task pool and the multi-threaded step: the pool splits work into fixed chunks and runs every
// one exactly once, phases of a job in order, waking workers that went to sleep; the world's two
// levels of worker tuners (the tuner itself is in test_worker_tuner) pick the faster way on a
// made-up machine; a world gives the same bits for 1, 2 and 4 threads on every benchmark scene and
// on jointed scenes (bodies and contacts compared after every step); and a step with worker
// threads allocates nothing once the contact set is steady.

#include "support/allocation_counter.h"
#include "support/sanitizers.h"
#include "support/state_hash.h"

#include "simcore/io/scene_io.h"
#include "simcore/parallel/large_array_allocator.h"
#include "simcore/parallel/task_pool.h"
#include "simcore/parallel/worker_tuner.h"
#include "simcore/world/world.h"

#include <QtTest>

#if defined(__linux__)
#include <sched.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace simcore;

namespace {

const std::filesystem::path kSourceDir = INTERPLAY_SOURCE_DIR;

// Every bit of the persistent contacts, in the world's order: which pairs, their points and the
// impulses the next step's warm start begins from.
std::uint64_t contactHash(const World& world) {
    std::uint64_t hash = 1469598103934665603ull;
    auto mix = [&hash](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    };
    auto mixFloat = [&mix](float value) { mix(&value, sizeof value); };
    auto mixVec = [&mixFloat](const Vec3& v) {
        mixFloat(v.x);
        mixFloat(v.y);
        mixFloat(v.z);
    };
    for (std::size_t c = 0; c < world.contactCount(); ++c) {
        const ContactInfo info = world.contact(c);
        mix(&info.bodyA.index, sizeof info.bodyA.index);
        mix(&info.bodyB.index, sizeof info.bodyB.index);
        mix(&info.pointCount, sizeof info.pointCount);
        mixVec(info.normal);
        for (int i = 0; i < info.pointCount; ++i) {
            mixVec(info.points[static_cast<std::size_t>(i)].pointA);
            mixVec(info.points[static_cast<std::size_t>(i)].pointB);
            mixFloat(info.normalImpulses[static_cast<std::size_t>(i)]);
        }
        mixVec(info.frictionImpulse);
    }
    return hash;
}

struct StepTrace {
    std::vector<std::uint64_t> bodies, contacts;  // after every step
};

StepTrace runScene(const std::string& path, int threads, int steps) {
    SceneLoadResult loaded = loadSceneFile(kSourceDir / path);
    if (!loaded.ok()) throw std::runtime_error(path + " does not load");
    loaded.scene->settings.threads = threads;
    BuiltWorld built = buildWorld(*loaded.scene);
    StepTrace trace;
    for (int step = 0; step < steps; ++step) {
        built.world.step();
        trace.bodies.push_back(test_support::stateHash(built.world));
        trace.contacts.push_back(contactHash(built.world));
    }
    return trace;
}

// The first step after which two traces differ, or -1.
int firstDifference(const StepTrace& a, const StepTrace& b) {
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
        if (a.bodies[i] != b.bodies[i] || a.contacts[i] != b.contacts[i]) return static_cast<int>(i) + 1;
    return -1;
}

}  // namespace

class TestThreads : public QObject {
    Q_OBJECT

private slots:
    void poolRunsEveryChunkOnce_data();
    void poolRunsEveryChunkOnce();
    void poolSumsInChunkOrder();
    void poolPhasesRunInOrder_data();
    void poolPhasesRunInOrder();
    void poolWakesSleepingWorkers();
    void poolSequencesWaitForEachOther_data();
    void poolSequencesWaitForEachOther();
    void poolWithWorkersOffRunsOnTheCallerInOrder();
    void poolRunsNarrowPhasesOnTheCaller();
    void poolWorkerLeavesTheCallersCpu();
    void largeArraysKeepTheirElementsOnHugePageBoundaries();
    void worldThreadsRunInlineWhenTheStepLoses();
    void worldThreadsUseWorkersSoonWhenEveryStageGains();
    void worldThreadsRecoverFromAnUnluckyFirstMeasurement();
    void worldThreadsRunEveryStageOfAStepTheSameWay();
    void worldThreadsLearnNothingFromStepsWithNothingToShare();
    void stepIsBitIdenticalForAnyThreadCount_data();
    void stepIsBitIdenticalForAnyThreadCount();
    void changingThreadsMidRunChangesNothing();
    void negativeThreadsAreRefused();
    void steadyStateStepWithWorkersDoesNotAllocate();
};

void TestThreads::poolRunsEveryChunkOnce_data() {
    QTest::addColumn<int>("threads");
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("grain");
    QTest::newRow("inline, one thread") << 1 << 1000 << 64;
    QTest::newRow("two threads, ragged last chunk") << 2 << 1000 << 64;
    QTest::newRow("four threads, more threads than chunks") << 4 << 100 << 64;
    QTest::newRow("four threads, grain 1") << 4 << 777 << 1;
    QTest::newRow("all cores") << 0 << 5000 << 16;
    QTest::newRow("nothing to do") << 4 << 0 << 8;
}

void TestThreads::poolRunsEveryChunkOnce() {
    QFETCH(int, threads);
    QFETCH(int, count);
    QFETCH(int, grain);
    TaskPool pool(threads);
    QVERIFY(pool.threadCount() >= 1);
    if (threads > 0) QCOMPARE(pool.threadCount(), threads);
    const auto n = static_cast<std::size_t>(count), g = static_cast<std::size_t>(grain);
    // Several rounds: a worker must see each job once, however quickly they follow each other.
    for (int round = 0; round < 50; ++round) {
        std::vector<std::atomic<int>> visits(n);
        std::vector<std::atomic<int>> chunkBegin(TaskPool::chunkCount(n, g));
        std::atomic<bool> badRange{false};  // Qt Test's macros belong to the test's thread
        pool.parallelFor(n, g, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
            chunkBegin[chunk].store(static_cast<int>(begin));
            if (!(begin < end && end - begin <= g && end <= n)) badRange.store(true);
            for (std::size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
        });
        QVERIFY(!badRange.load());
        for (std::size_t i = 0; i < n; ++i) QCOMPARE(visits[i].load(), 1);
        for (std::size_t k = 0; k < chunkBegin.size(); ++k) QCOMPARE(chunkBegin[k].load(), static_cast<int>(k * g));
    }
}

void TestThreads::poolSumsInChunkOrder() {
    TaskPool pool(4);
    for (int round = 0; round < 20; ++round) {
        const std::uint64_t sum = pool.parallelSum(1001, 10, [](std::size_t begin, std::size_t end) {
            std::uint64_t s = 0;
            for (std::size_t i = begin; i < end; ++i) s += i;
            return s;
        });
        QCOMPARE(sum, std::uint64_t{1000 * 1001 / 2});
    }
}

void TestThreads::poolPhasesRunInOrder_data() {
    QTest::addColumn<int>("threads");
    QTest::addColumn<bool>("workersOn");
    QTest::newRow("inline, one thread") << 1 << true;
    QTest::newRow("two threads") << 2 << true;
    QTest::newRow("four threads") << 4 << true;
    QTest::newRow("four threads, workers off") << 4 << false;
}

// Phase q reads what phase q - 1 wrote (as a solver colour reads the bodies the colour before
// moved): each value must be the previous phase's plus one, so a chunk that started before the
// phase before it finished, or ran twice, or not at all, shows. Phases of every size, empty
// ones among them, and more phases than the pool has seen before.
void TestThreads::poolPhasesRunInOrder() {
    QFETCH(int, threads);
    QFETCH(bool, workersOn);
    TaskPool pool(threads);
    pool.setWorkersEnabled(workersOn);
    constexpr std::size_t kGrain = 4, kWidth = 40;
    for (int round = 0; round < 30; ++round) {
        const std::size_t phases = 1 + static_cast<std::size_t>(round) % 12;
        // Phase sizes 0..kWidth: some phases have no work, some one chunk, some many.
        auto phaseSize = [&](std::size_t q) { return (q * 13 + static_cast<std::size_t>(round)) % (kWidth + 1); };
        std::vector<std::atomic<int>> value(kWidth);  // index i: the last phase that wrote it, plus one
        std::vector<std::atomic<int>> visits(phases * kWidth);
        std::atomic<bool> readStale{false};
        const std::uint64_t sum = pool.parallelSumInPhases(
            phases, kGrain, phaseSize, [&](std::size_t q, std::size_t begin, std::size_t end) {
                std::uint64_t count = 0;
                for (std::size_t i = begin; i < end; ++i) {
                    visits[q * kWidth + i].fetch_add(1);
                    // Every index below this phase's size was written by each earlier phase as
                    // large; the value is the number of phases so far that covered it.
                    int expected = 0;
                    for (std::size_t p = 0; p < q; ++p) expected += i < phaseSize(p) ? 1 : 0;
                    if (value[i].load() != expected) readStale.store(true);
                    value[i].fetch_add(1);
                    count += i + 1;
                }
                return count;
            });
        QVERIFY(!readStale.load());
        std::uint64_t expectedSum = 0;
        for (std::size_t q = 0; q < phases; ++q)
            for (std::size_t i = 0; i < kWidth; ++i) {
                QCOMPARE(visits[q * kWidth + i].load(), i < phaseSize(q) ? 1 : 0);
                if (i < phaseSize(q)) expectedSum += i + 1;
            }
        QCOMPARE(sum, expectedSum);
    }
}

// Idle workers spin a short while and then sleep: jobs that come after a pause longer than the spin
// must wake them (a lost wake-up would hang here, or leave chunks unrun).
void TestThreads::poolWakesSleepingWorkers() {
    TaskPool pool(3);
    constexpr std::size_t kCount = 300, kGrain = 10;
    for (int round = 0; round < 10; ++round) {
        std::this_thread::sleep_for(std::chrono::milliseconds(round % 2 == 0 ? 2 : 0));
        std::vector<std::atomic<int>> visits(kCount);
        pool.parallelFor(kCount, kGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
        });
        for (std::size_t i = 0; i < kCount; ++i) QCOMPARE(visits[i].load(), 1);
    }
}

// Sequences that wait for each other's steps, one per thread: every step runs once, after the
// steps it waits for, and the job ends. Each round starts about when the workers go to sleep
// (their spin and yield last 200 us): a wake-up lost there leaves the caller waiting for a worker
// forever, as one did in about 1 run in 10 of the bit-identity test with workers forced on, before
// the fix in TaskPool::wakeSleepingWorkers.
void TestThreads::poolSequencesWaitForEachOther() {
    QFETCH(int, threads);
    TaskPool pool(threads);
    const auto sequences = static_cast<std::size_t>(threads);
    constexpr std::uint32_t kSteps = 50;
    std::mt19937 random(7);
    for (int round = 0; round < 1000; ++round) {
        const auto pause = std::chrono::microseconds(190 + random() % 40);
        for (const auto until = std::chrono::steady_clock::now() + pause; std::chrono::steady_clock::now() < until;) {}
        // Step k of sequence s reads step k - 1 of sequence s + 1 (the last one: of sequence 0).
        std::vector<std::atomic<std::uint32_t>> value(sequences * kSteps);
        std::atomic<bool> misread{false};
        const std::uint64_t steps = pool.runSequences([&](std::size_t s) {
            const std::size_t next = (s + 1) % sequences;
            for (std::uint32_t k = 0; k < kSteps; ++k) {
                if (k > 0) {
                    pool.awaitSteps(next, k);
                    if (value[next * kSteps + k - 1].load(std::memory_order_relaxed) != k) misread = true;
                }
                value[s * kSteps + k].store(k + 1, std::memory_order_relaxed);
                pool.publishSteps(s, k + 1);
            }
            return std::uint64_t{kSteps};
        });
        QCOMPARE(steps, std::uint64_t{kSteps} * sequences);
        QVERIFY(!misread.load());
    }
}

void TestThreads::poolSequencesWaitForEachOther_data() {
    QTest::addColumn<int>("threads");
    QTest::newRow("two threads") << 2;
    QTest::newRow("four threads") << 4;
}

void TestThreads::poolWithWorkersOffRunsOnTheCallerInOrder() {
    TaskPool pool(4);
    pool.setWorkersEnabled(false);
    const std::thread::id caller = std::this_thread::get_id();
    std::vector<std::size_t> chunks;  // unguarded: only the caller may write it
    bool elsewhere = false;
    pool.parallelFor(100, 7, [&](std::size_t chunk, std::size_t, std::size_t) {
        elsewhere = elsewhere || std::this_thread::get_id() != caller;
        chunks.push_back(chunk);
    });
    QVERIFY(!elsewhere);
    QCOMPARE(chunks.size(), TaskPool::chunkCount(100, 7));
    for (std::size_t k = 0; k < chunks.size(); ++k) QCOMPARE(chunks[k], k);
    // Counted as work the workers could have shared, not offered to them.
    QCOMPARE(pool.sharableJobs(), std::uint64_t{1});
    QCOMPARE(pool.jobsOffered(), std::uint64_t{0});
}

void TestThreads::poolRunsNarrowPhasesOnTheCaller() {
    // With at most one chunk per thread in every phase, no thread can take over from a slower one,
    // so workers would only wait at the end of each phase (a tower's solver colours): the whole job
    // stays on the caller, in order, as with workers off.
    TaskPool pool(2);
    pool.parallelFor(64, 1, [](std::size_t, std::size_t, std::size_t) {});  // the worker is awake
    const std::thread::id caller = std::this_thread::get_id();
    std::vector<std::size_t> phases;  // unguarded: only the caller may write it
    bool elsewhere = false;
    // Phases of 0 to 8 indices in chunks of 4: none, one or two chunks each.
    const std::uint64_t sum = pool.parallelSumInPhases(
        27, 4, [](std::size_t phase) { return phase % 9; },
        [&](std::size_t phase, std::size_t begin, std::size_t end) {
            if (std::this_thread::get_id() != caller) {
                elsewhere = true;  // a data race only where the test fails anyway
                return std::uint64_t{0};
            }
            phases.push_back(phase);
            // Long enough for a worker that joins to take the chunks of its own share.
            const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
            while (std::chrono::steady_clock::now() < until) {
            }
            return std::uint64_t{end - begin};
        });
    QVERIFY(!elsewhere);
    QCOMPARE(pool.sharableJobs(), std::uint64_t{1});  // the first parallelFor only
    QCOMPARE(pool.jobsOffered(), std::uint64_t{1});
    QCOMPARE(sum, std::uint64_t{3 * (0 + 1 + 2 + 3 + 4 + 5 + 6 + 7 + 8)});
    QCOMPARE(phases.size(), std::size_t{3 * (4 * 1 + 4 * 2)});  // the phases of size 0 have no chunk
    QVERIFY(std::is_sorted(phases.begin(), phases.end()));
}

// A worker waiting on the CPU the caller runs on only takes turns with it, and the kernel left such
// a worker there for tens of steps (task_pool.cpp): the worker must move off by itself. Here the
// test puts it there: the caller and the worker both pinned to the caller's CPU, where only the
// worker's own move can take it away.
void TestThreads::poolWorkerLeavesTheCallersCpu() {
#if defined(__linux__)
    cpu_set_t callerWas;
    QCOMPARE(sched_getaffinity(0, sizeof callerWas, &callerWas), 0);
    if (CPU_COUNT(&callerWas) < 2) QSKIP("needs two CPUs");
    TaskPool pool(2);
    const pid_t caller = gettid();
    std::atomic<pid_t> worker{0};
    const auto keepOffering = [&](const auto& until) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (!until() && std::chrono::steady_clock::now() < deadline) {
            pool.parallelFor(64, 1, [&](std::size_t, std::size_t, std::size_t) {
                if (gettid() != caller) worker.store(gettid());
            });
        }
    };
    keepOffering([&] { return worker.load() != 0; });  // a chunk ran on the worker
    QVERIFY(worker.load() != 0);
    const int callerCpu = sched_getcpu();
    cpu_set_t onlyThere;
    CPU_ZERO(&onlyThere);
    CPU_SET(callerCpu, &onlyThere);
    QCOMPARE(sched_setaffinity(0, sizeof onlyThere, &onlyThere), 0);
    QCOMPARE(sched_setaffinity(worker.load(), sizeof onlyThere, &onlyThere), 0);
    cpu_set_t workerMay;
    const auto workerMayRunThere = [&] {
        return sched_getaffinity(worker.load(), sizeof workerMay, &workerMay) != 0 || CPU_ISSET(callerCpu, &workerMay);
    };
    keepOffering([&] { return !workerMayRunThere(); });
    keepOffering([&] { return pool.lastCpu(1) >= 0 && pool.lastCpu(1) != callerCpu; });  // seen elsewhere since
    sched_setaffinity(0, sizeof callerWas, &callerWas);
    QVERIFY2(!workerMayRunThere(), "the worker stayed on the caller's CPU");
    QVERIFY(CPU_COUNT(&workerMay) > 0);
    QVERIFY(pool.lastCpu(1) >= 0 && pool.lastCpu(1) != callerCpu);
#else
    QSKIP("CPU placement is read and set on Linux only");
#endif
}

void TestThreads::largeArraysKeepTheirElementsOnHugePageBoundaries() {
    using Allocator = simcore::LargeArrayAllocator<std::uint64_t>;
    constexpr std::size_t kHugeCount = Allocator::kHugePageBytes / sizeof(std::uint64_t);
    // Grown one element at a time past the huge-page size (reallocating on the way): every element
    // written is kept, and the array then starts on a huge-page boundary.
    std::vector<std::uint64_t, Allocator> values;
    for (std::uint64_t k = 0; k < kHugeCount + 1000; ++k) values.push_back(k * k);
    QCOMPARE(reinterpret_cast<std::uintptr_t>(values.data()) % Allocator::kHugePageBytes, std::uintptr_t{0});
    for (std::size_t k = 0; k < values.size(); ++k)
        if (values[k] != k * k) QFAIL(qPrintable(QString("element %1 lost").arg(k)));
    // Copies and resizes keep the elements too; a small array is an ordinary allocation.
    const std::vector<std::uint64_t, Allocator> copy = values;
    QVERIFY(std::equal(copy.begin(), copy.end(), values.begin(), values.end()));
    values.resize(16);
    values.shrink_to_fit();
    QCOMPARE(values.size(), std::size_t{16});
    QCOMPARE(values[15], std::uint64_t{225});
    // What a resize adds is left for its filler to write; written, it reads back.
    values.resize(kHugeCount);
    for (std::size_t k = 16; k < values.size(); ++k) values[k] = k;
    QCOMPARE(values.back(), std::uint64_t{kHugeCount - 1});
    QCOMPARE(values[15], std::uint64_t{225});
}

namespace {

// One step of a world whose only stages are `stages`, run in that order, each with work the
// workers can share (unless `sharable` is false) and taking stageMs(stage, withWorkers) as the
// world's threads chose: how many ran with workers, and the step's time.
struct MadeUpStep {
    int stagesWithWorkers = 0;
    double ms = 0.0;
    bool workerRanInline = false;  // a worker ran a chunk in a step the world ran inline
};
template <class StageMs>
MadeUpStep stepStages(WorldThreads& threads, std::initializer_list<Stage> stages, StageMs&& stageMs,
                      bool sharable = true) {
    StepProfile profile;
    profile.skipped.fill(StageSkip::NothingAwake);
    MadeUpStep step;
    const bool withWorkers = threads.startStep();
    for (const Stage stage : stages) {
        const auto s = static_cast<std::size_t>(stage);
        profile.skipped[s] = StageSkip::Ran;
        if (sharable) {
            std::atomic<bool> elsewhere{false};
            const std::thread::id caller = std::this_thread::get_id();
            threads.pool().parallelFor(64, 1, [&](std::size_t, std::size_t, std::size_t) {
                if (std::this_thread::get_id() != caller) elsewhere.store(true);
            });
            step.workerRanInline = step.workerRanInline || (elsewhere.load() && !withWorkers);
        }
        step.stagesWithWorkers += withWorkers;
        profile.stageMs[s] = stageMs(stage, withWorkers);
        step.ms += profile.stageMs[s];
    }
    threads.learn(profile);
    return step;
}

}  // namespace

void TestThreads::worldThreadsRunInlineWhenTheStepLoses() {
    // A machine where collide runs faster with workers but the step does not: collide with workers
    // leaves its data split between the cores, and prepare inline then takes twice as long (2 ms,
    // not 1); with workers it takes 1.3 ms either way. Stage by stage that would pick workers for
    // both (0.9 + 1.3 ms); the step inline takes 2 ms.
    WorldThreads threads;
    threads.configure(2);
    double lateMs = 0.0;
    int lateSteps = 0;
    for (int step = 0; step < 2000; ++step) {
        bool collideWithWorkers = false;
        const MadeUpStep made = stepStages(threads, {Stage::Collide, Stage::Prepare}, [&](Stage stage, bool withWorkers) {
            if (stage == Stage::Collide) {
                collideWithWorkers = withWorkers;
                return withWorkers ? 0.9 : 1.0;
            }
            return withWorkers ? 1.3 : collideWithWorkers ? 2.0 : 1.0;
        });
        if (step >= 1000) {
            lateMs += made.ms;
            ++lateSteps;
        }
    }
    // Inline, but for the probes that keep checking (at most one step in kMaxProbeInterval, each
    // at most 1.3 ms slower).
    const double meanMs = lateMs / lateSteps;
    QVERIFY2(meanMs < 2.0 + 2.0 * 1.3 / WorkerTuner::kMaxProbeInterval, qPrintable(QString::number(meanMs)));
}

void TestThreads::worldThreadsUseWorkersSoonWhenEveryStageGains() {
    // A machine where both stages take half the time with workers.
    WorldThreads threads;
    threads.configure(2);
    int inlineSteps = 0;
    for (int step = 0; step < 100; ++step) {
        const MadeUpStep made =
            stepStages(threads, {Stage::Collide, Stage::Prepare}, [](Stage, bool withWorkers) { return withWorkers ? 0.5 : 1.0; });
        if (step >= 3 && made.stagesWithWorkers == 0) ++inlineSteps;
    }
    // From the fourth step on, inline only in the learning's two steps and in probes.
    QVERIFY2(inlineSteps <= 8, qPrintable(QString::number(inlineSteps)));
}

void TestThreads::worldThreadsRecoverFromAnUnluckyFirstMeasurement() {
    // pyramid10 at 2 threads, as one run of 8 went (2026-12-07): the step's learning step with
    // workers happened to take 1.73 ms against 1.5 inline while the scene settled, then workers take
    // 0.8 ms a step against 1.12 inline. The first probe of workers must find that out.
    WorldThreads threads;
    threads.configure(2);
    int lateWorkerSteps = 0;
    for (int step = 0; step < 600; ++step) {
        const MadeUpStep made = stepStages(threads, {Stage::Collide, Stage::Solve}, [step](Stage, bool withWorkers) {
            return step == 1 ? 0.865 : step < 4 ? 0.75 : withWorkers ? 0.4 : 0.56;
        });
        if (step >= 100 && made.stagesWithWorkers == 2) ++lateWorkerSteps;
    }
    // All but probes of inline: at most 2 steps in each interval of at least kMinProbeInterval.
    QVERIFY2(lateWorkerSteps >= 500 * (1.0 - 2.0 / WorkerTuner::kMinProbeInterval),
             qPrintable(QString::number(lateWorkerSteps)));
}

void TestThreads::worldThreadsRunEveryStageOfAStepTheSameWay() {
    // A stage with workers leaves its data on both cores for the next: a step's stages run all
    // with workers or all inline, whatever each alone would gain (here prepare loses, solve gains).
    WorldThreads threads;
    threads.configure(2);
    int withWorkers = 0;
    for (int step = 0; step < 300; ++step) {
        const MadeUpStep made = stepStages(threads, {Stage::Prepare, Stage::Solve}, [](Stage stage, bool workers) {
            return stage == Stage::Prepare ? (workers ? 0.2 : 0.1) : (workers ? 0.5 : 1.0);
        });
        QVERIFY(made.stagesWithWorkers == 0 || made.stagesWithWorkers == 2);
        QVERIFY(!made.workerRanInline);
        withWorkers += made.stagesWithWorkers == 2;
    }
    // The step gains (0.7 ms against 1.1): with workers but for probes of inline.
    QVERIFY2(withWorkers >= 300 * (1.0 - 2.0 / WorkerTuner::kMinProbeInterval),
             qPrintable(QString::number(withWorkers)));
}

void TestThreads::worldThreadsLearnNothingFromStepsWithNothingToShare() {
    // A tower's steps: every job too narrow to share, so with workers or without the same code
    // runs, and what the timings say (here inline twice as fast) is noise.
    WorldThreads threads;
    threads.configure(2);
    const auto stageMs = [](Stage, bool withWorkers) { return withWorkers ? 1.0 : 0.5; };
    for (int step = 0; step < 50; ++step) stepStages(threads, {Stage::Collide}, stageMs, false);
    // The first steps with work to share start the learning (workers first, twice, then inline),
    // as in a world that has just been made.
    std::vector<bool> ways;
    for (int step = 0; step < 4; ++step)
        ways.push_back(stepStages(threads, {Stage::Collide}, stageMs).stagesWithWorkers > 0);
    QCOMPARE(ways, (std::vector<bool>{true, true, false, false}));
}

void TestThreads::stepIsBitIdenticalForAnyThreadCount_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    // Short enough for the suite to stay under a minute on a busy two-core machine (and a few
    // times shorter under ThreadSanitizer), long enough for stacks to settle and piles to collide.
    // Every scene in scenes/bench, so a new benchmark scene is covered without a new row; one not
    // listed here runs kOtherBenchSteps.
    const int scale = test_support::kSanitized ? 5 : 1;
    const std::map<std::string, int> benchSteps{
        {"pile1k", 240}, {"mixed1k", 120}, {"pyramid10", 60}, {"pyramid20", 30}, {"tower20", 120}};
    constexpr int kOtherBenchSteps = 60;
    std::vector<std::string> benchScenes;
    for (const auto& entry : std::filesystem::directory_iterator(kSourceDir / "scenes/bench"))
        if (entry.path().extension() == ".json") benchScenes.push_back(entry.path().stem().string());
    std::sort(benchScenes.begin(), benchScenes.end());
    QVERIFY2(benchScenes.size() >= 5, "scenes/bench has lost its scenes");
    for (const std::string& name : benchScenes) {
        const auto known = benchSteps.find(name);
        const int steps = known != benchSteps.end() ? known->second : kOtherBenchSteps;
        QTest::newRow(name.c_str()) << QString::fromStdString("scenes/bench/" + name + ".json") << steps / scale;
    }
    QTest::newRow("chain20 (joints)") << "scenes/chain20.json" << 240 / scale;
    QTest::newRow("ragdoll (joints)") << "scenes/ragdoll.json" << 240 / scale;
}

void TestThreads::stepIsBitIdenticalForAnyThreadCount() {
    QFETCH(QString, scene);
    QFETCH(int, steps);
    const std::string path = scene.toStdString();
    const StepTrace one = runScene(path, 1, steps);
    // A scene that stood still would compare nothing: the bodies must have moved.
    QVERIFY2(one.bodies.front() != one.bodies.back(), "the scene does not move");
    for (int threads : {2, 4}) {
        const int step = firstDifference(one, runScene(path, threads, steps));
        QVERIFY2(step < 0, qPrintable(QString("%1 threads differ from 1 after step %2").arg(threads).arg(step)));
    }
}

void TestThreads::changingThreadsMidRunChangesNothing() {
    SceneLoadResult loaded = loadSceneFile(kSourceDir / "scenes/bench/pile1k.json");
    QVERIFY(loaded.ok());
    BuiltWorld single = buildWorld(*loaded.scene);
    BuiltWorld switching = buildWorld(*loaded.scene);
    for (int step = 0; step < 60; ++step) {
        if (step % 20 == 10) {
            WorldSettings settings = switching.world.settings();
            settings.threads = settings.threads == 1 ? 3 : 1;
            switching.world.setSettings(settings);
        }
        single.world.step();
        switching.world.step();
    }
    QCOMPARE(test_support::stateHash(switching.world), test_support::stateHash(single.world));
    QCOMPARE(contactHash(switching.world), contactHash(single.world));
}

void TestThreads::negativeThreadsAreRefused() {
    WorldSettings settings;
    settings.threads = -1;
    try {
        World world(settings);
        QFAIL("a negative thread count was accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(std::strstr(e.what(), "threads") != nullptr, e.what());
    }
}

void TestThreads::steadyStateStepWithWorkersDoesNotAllocate() {
    SceneLoadResult loaded = loadSceneFile(kSourceDir / "scenes/bench/pyramid10.json");
    QVERIFY(loaded.ok());
    loaded.scene->settings.threads = 2;
    loaded.scene->settings.sleep.enabled = false;  // every body keeps being stepped
    BuiltWorld built = buildWorld(*loaded.scene);
    for (int i = 0; i < 60; ++i) built.world.step();

    test_support::startCountingAllocations();
    for (int i = 0; i < 30; ++i) built.world.step();
    const std::size_t allocations = test_support::stopCountingAllocations();
    QVERIFY(built.world.lastStepProfile().counters.contactPoints > 0);
    QCOMPARE(allocations, std::size_t{0});
}

QTEST_GUILESS_MAIN(TestThreads)
#include "test_threads.moc"
