// The step's stage table (simcore/world/stages.h): the profiler reports every stage in the
// table's order with times that add up to no more than the step; each stage a scene leaves out is
// reported as skipped with the reason that applies to that scene; a tower's stages hand the
// workers no job; and the runner's report lists the stages in the same order, saying which were
// skipped and why and how many jobs each handed the workers.

#include "support/scene_builders.h"
#include "support/run_program.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/world.h"

#include <QtTest>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

using namespace simcore;
using namespace scene_builders;

namespace {

std::size_t at(Stage stage) { return static_cast<std::size_t>(stage); }

// A square pyramid of base 4 on the ground: contacts, no restitution, no ccd body.
World pyramid(const WorldSettings& settings = {}) {
    World world(settings);
    addGround(world);
    for (const Vec3& centre : squarePyramidCentres(4)) world.createBody(cube(centre));
    return world;
}

StageSkip skipOf(const World& world, Stage stage) { return world.lastStepProfile().skipped[at(stage)]; }

}  // namespace

class TestStages : public QObject {
    Q_OBJECT

private slots:
    void tableHasOneUniqueNamedRowPerStage();
    void profileHasEveryStageWithinTheStepTotal();
    void pyramidRunsTheSolverStagesAndSkipsTheRest();
    void skipReasonsFollowTheScene_data();
    void skipReasonsFollowTheScene();
    void fastOrFlaggedBodyRunsContinuous();
    void bouncyContactRunsRestitution();
    void profileCountsHandOversAndATowerHasNone();
    void runnerReportListsStagesInOrderWithSkips();
    void runnerListsTheStageTable();
};

void TestStages::tableHasOneUniqueNamedRowPerStage() {
    std::set<std::string_view> keys, names;
    for (const StageInfo& info : kStages) {
        QVERIFY(!info.key.empty() && !info.name.empty() && !info.doc.empty() && !info.skippedWhen.empty());
        QVERIFY2(keys.insert(info.key).second, info.key.data());
        QVERIFY2(names.insert(info.name).second, info.name.data());
    }
    QCOMPARE(keys.size(), std::size_t{kStageCount});
    // The split the profiler promises, in order of execution.
    const std::vector<std::string_view> expected{"pairs", "collide", "islands", "prepare", "integrateVelocities",
                                                 "warmStart", "solve", "integratePositions", "restitution",
                                                 "relax", "storeImpulses", "continuous", "sleep"};
    QCOMPARE(expected.size(), kStages.size());
    for (std::size_t s = 0; s < expected.size(); ++s) QCOMPARE(kStages[s].key, expected[s]);
}

void TestStages::profileHasEveryStageWithinTheStepTotal() {
    WorldSettings settings;
    settings.substeps = 4;
    World world = pyramid(settings);
    for (int step = 0; step < 60; ++step) {
        world.step();
        const StepProfile& profile = world.lastStepProfile();
        double sum = 0.0;
        for (std::size_t s = 0; s < profile.stageMs.size(); ++s) {
            QVERIFY2(profile.stageMs[s] >= 0.0, kStages[s].key.data());
            // A stage that did not run and has no check to make costs nothing.
            if (profile.skipped[s] != StageSkip::Ran && profile.skipped[s] != StageSkip::NoFastBody)
                QCOMPARE(profile.stageMs[s], 0.0);
            sum += profile.stageMs[s];
        }
        // Each stage's timer lies inside the step's, so their sum cannot exceed it (no tolerance
        // needed: the same clock, disjoint intervals).
        QVERIFY2(sum <= profile.totalMs, qPrintable(QString("stages %1 ms > step %2 ms").arg(sum).arg(profile.totalMs)));
        QVERIFY(profile.totalMs > 0.0);
    }
}

void TestStages::pyramidRunsTheSolverStagesAndSkipsTheRest() {
    World world = pyramid();
    world.step();
    for (Stage stage : {Stage::Pairs, Stage::Collide, Stage::Islands, Stage::Prepare, Stage::IntegrateVelocities,
                        Stage::WarmStart, Stage::Solve, Stage::IntegratePositions, Stage::Relax,
                        Stage::StoreImpulses, Stage::Sleep})
        QVERIFY2(skipOf(world, stage) == StageSkip::Ran, stageName(stage).data());
    QCOMPARE(skipOf(world, Stage::Restitution), StageSkip::NoBouncyContact);
    // No body is flagged ccd and none moves half its size in a step.
    QCOMPARE(skipOf(world, Stage::Continuous), StageSkip::NoFastBody);
}

void TestStages::skipReasonsFollowTheScene_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("stage");
    QTest::addColumn<int>("expected");
    auto row = [](const char* name, const char* scene, Stage stage, StageSkip skip) {
        QTest::newRow(name) << QString(scene) << static_cast<int>(stage) << static_cast<int>(skip);
    };
    row("one body: no pairs", "ball", Stage::Pairs, StageSkip::SingleBody);
    row("one body: no collide", "ball", Stage::Collide, StageSkip::SingleBody);
    row("one body: nothing to solve", "ball", Stage::Prepare, StageSkip::NothingToSolve);
    row("one body: no warm start", "ball", Stage::WarmStart, StageSkip::NothingToSolve);
    row("one body: no continuous", "ball", Stage::Continuous, StageSkip::SingleBody);
    row("one body: still integrates", "ball", Stage::IntegrateVelocities, StageSkip::Ran);
    row("contacts off", "contactsOff", Stage::Collide, StageSkip::ContactsOff);
    row("contacts off: no relax", "contactsOff", Stage::Relax, StageSkip::NothingToSolve);
    row("sleep off", "sleepOff", Stage::Sleep, StageSkip::SleepOff);
    row("ccd off", "ccdOff", Stage::Continuous, StageSkip::CcdOff);
    row("restitution off", "restitutionOff", Stage::Restitution, StageSkip::RestitutionOff);
    row("Baumgarte: no relax", "baumgarte", Stage::Relax, StageSkip::Baumgarte);
    row("Baumgarte: still solves", "baumgarte", Stage::Solve, StageSkip::Ran);
    row("static only: nothing awake", "staticOnly", Stage::Pairs, StageSkip::NothingAwake);
    row("static only: no sleep", "staticOnly", Stage::Sleep, StageSkip::NothingAwake);
    row("static only: no velocities", "staticOnly", Stage::IntegrateVelocities, StageSkip::NothingMoves);
    row("static only: no positions", "staticOnly", Stage::IntegratePositions, StageSkip::NothingMoves);
    row("kinematic only: moves", "kinematicOnly", Stage::IntegratePositions, StageSkip::Ran);
    row("kinematic only: nothing awake to collide", "kinematicOnly", Stage::Collide, StageSkip::NothingAwake);
    row("apart: no constraint", "apart", Stage::Solve, StageSkip::NoConstraint);
    row("apart: no restitution", "apart", Stage::Restitution, StageSkip::NoConstraint);
}

void TestStages::skipReasonsFollowTheScene() {
    QFETCH(QString, scene);
    QFETCH(int, stage);
    QFETCH(int, expected);
    WorldSettings settings;
    if (scene == "contactsOff") settings.effects[Effect::Contacts] = false;
    if (scene == "sleepOff") settings.sleep.enabled = false;
    if (scene == "ccdOff") settings.effects[Effect::Ccd] = false;
    if (scene == "restitutionOff") settings.effects[Effect::Restitution] = false;
    if (scene == "baumgarte") settings.solver.positionCorrection = PositionCorrection::Baumgarte;
    World world(settings);
    if (scene == "ball") {
        BodyCreationSettings ball;
        ball.shape = Shape::sphere(0.25f);
        ball.position = Vec3(0.0f, 10.0f, 0.0f);
        world.createBody(ball);
    } else if (scene == "staticOnly") {
        addGround(world);
        BodyCreationSettings post = cube(Vec3(0.0f, 0.5f, 0.0f));
        post.motion = MotionType::Static;
        world.createBody(post);
    } else if (scene == "kinematicOnly") {
        addGround(world);
        BodyCreationSettings platform = cube(Vec3(0.0f, 2.0f, 0.0f));
        platform.motion = MotionType::Kinematic;
        platform.linearVelocity = Vec3(1.0f, 0.0f, 0.0f);
        world.createBody(platform);
    } else if (scene == "apart") {
        // Two cubes 10 m apart in zero gravity: awake, paired by nothing.
        settings.gravity = Vec3(0.0f);
        world.setSettings(settings);
        world.createBody(cube(Vec3(-5.0f, 0.0f, 0.0f)));
        world.createBody(cube(Vec3(5.0f, 0.0f, 0.0f)));
    } else {
        // A cube resting on the ground, bouncy so that only the settings decide restitution.
        addGround(world, 0.6f, 0.5f);
        BodyCreationSettings box = cube(Vec3(0.0f, 0.5f, 0.0f));
        box.restitution = 0.5f;
        world.createBody(box);
    }
    world.step();
    const StageSkip got = skipOf(world, static_cast<Stage>(stage));
    QVERIFY2(got == static_cast<StageSkip>(expected),
             qPrintable(QString("%1: got '%2', expected '%3'")
                            .arg(stageName(static_cast<Stage>(stage)).data())
                            .arg(stageSkipReason(got).data())
                            .arg(stageSkipReason(static_cast<StageSkip>(expected)).data())));
}

void TestStages::fastOrFlaggedBodyRunsContinuous() {
    World world;
    addGround(world);
    BodyCreationSettings ball;
    ball.shape = Shape::sphere(0.25f);
    ball.position = Vec3(0.0f, 5.0f, 0.0f);
    ball.ccd = true;
    world.createBody(ball);
    world.step();
    QCOMPARE(skipOf(world, Stage::Continuous), StageSkip::Ran);
    QVERIFY(world.effectUsage().ran(Effect::Ccd));
}

void TestStages::bouncyContactRunsRestitution() {
    World world;
    addGround(world, 0.6f, 0.8f);
    BodyCreationSettings ball;
    ball.shape = Shape::sphere(0.25f);
    ball.position = Vec3(0.0f, 0.3f, 0.0f);  // within the speculative margin: a contact from step 1
    ball.linearVelocity = Vec3(0.0f, -3.0f, 0.0f);
    ball.restitution = 0.8f;
    world.createBody(ball);
    world.step();
    QCOMPARE(skipOf(world, Stage::Restitution), StageSkip::Ran);
    QVERIFY(world.lastStepProfile().stageMs[at(Stage::Restitution)] >= 0.0);
}

void TestStages::profileCountsHandOversAndATowerHasNone() {
    // A tower's jobs have at most a chunk per thread, and handing one over wakes a worker that has
    // gone to sleep, for more than the job takes: tower40 at 2 threads was 1.5% slower than at 1
    // while the filling of its solver's lanes did (2026-12-07). A pile of a thousand does hand
    // over, so the count is not stuck at zero.
    const auto handOvers = [](const char* path, int threads, int steps) {
        SceneLoadResult loaded = loadSceneFile(std::filesystem::path(INTERPLAY_SOURCE_DIR) / path);
        if (!loaded.ok()) throw std::runtime_error(std::string(path) + " does not load");
        loaded.scene->settings.threads = threads;
        BuiltWorld built = buildWorld(*loaded.scene);
        std::uint64_t jobs = 0;
        for (int step = 0; step < steps; ++step) {
            built.world.step();
            for (std::uint32_t stageJobs : built.world.lastStepProfile().handOvers) jobs += stageJobs;
        }
        return jobs;
    };
    QCOMPARE(handOvers("scenes/bench/tower40.json", 2, 600), std::uint64_t{0});
    QCOMPARE(handOvers("scenes/bench/tower20.json", 4, 120), std::uint64_t{0});
    QVERIFY(handOvers("scenes/bench/pile1k.json", 2, 20) > 0);
    QCOMPARE(handOvers("scenes/bench/pile1k.json", 1, 20), std::uint64_t{0});
}

void TestStages::runnerReportListsStagesInOrderWithSkips() {
    const test_support::ProgramRun run =
        test_support::runProgram(INTERPLAY_RUN_PATH, {QString(INTERPLAY_SOURCE_DIR) + "/scenes/bench/pyramid10.json", "--steps", "5"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const auto report = nlohmann::json::parse(run.out.toStdString());
    const auto& stages = report["stages"];
    QVERIFY(stages.is_array());
    QCOMPARE(stages.size(), kStages.size());
    double sum = 0.0;
    for (std::size_t s = 0; s < kStages.size(); ++s) {
        QCOMPARE(stages[s]["stage"].get<std::string>(), std::string(kStages[s].key));
        const double ms = stages[s]["msPerStep"].get<double>();
        QVERIFY(ms >= 0.0);
        sum += ms;
        const auto run = stages[s]["stepsRun"].get<std::uint64_t>();
        QVERIFY(run <= 5);
        // A stage says why exactly when some step skipped it.
        QCOMPARE(stages[s].contains("skipped"), run < 5);
        QVERIFY(stages[s]["handOversPerStep"].get<double>() >= 0.0);
    }
    // Finding islands is serial at any thread count.
    QCOMPARE(stages[at(Stage::Islands)]["handOversPerStep"].get<double>(), 0.0);
    QVERIFY(sum <= report["msPerStep"].get<double>());
    QCOMPARE(stages[at(Stage::Solve)]["stepsRun"].get<int>(), 5);
    QCOMPARE(stages[at(Stage::Continuous)]["skipped"].get<std::string>(),
             std::string(stageSkipReason(StageSkip::NoFastBody)));
    QCOMPARE(stages[at(Stage::Restitution)]["skipped"].get<std::string>(),
             std::string(stageSkipReason(StageSkip::NoBouncyContact)));
}

void TestStages::runnerListsTheStageTable() {
    const test_support::ProgramRun run = test_support::runProgram(INTERPLAY_RUN_PATH, {"--list-stages"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = QString::fromUtf8(run.out).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), kStageCount + 2);  // header, rule, one row per stage
    for (int s = 0; s < kStageCount; ++s) {
        const QString expected = QString("| %1 | `%2` |").arg(s + 1).arg(kStages[static_cast<std::size_t>(s)].key.data());
        QVERIFY2(lines[s + 2].startsWith(expected), qPrintable(lines[s + 2]));
    }
}

QTEST_APPLESS_MAIN(TestStages)
#include "test_stages.moc"
