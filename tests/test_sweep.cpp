// The scene sweep engine (app/accuracy/scene_sweep.h): errors against closed forms, the reference's
// reported convergence against a finer reference, the grid and its checks, threads, resuming and
// cancelling. The command line and its job recipes are test_sweep_cli (tests/test_sweep_cli.cmake).

#include "accuracy/scene_sweep.h"
#include "accuracy/sweep_files.h"

#include "simcore/io/scene_io.h"

#include <QtTest>

#include <cmath>

namespace {

using accuracy::Measure;

std::size_t at(Measure m) { return static_cast<std::size_t>(m); }

// A 1 kg ball thrown at (3, 5, 0) m/s with nothing to hit and no damping: its exact path is
// x = v0 t + g t^2 / 2. Semi-implicit Euler with substep h lands at v0 t + g t^2 / 2 + g h t / 2
// after each step (velocity first, then position), so its position error at t is g h t / 2 exactly.
const char* kProjectile = R"({
  "format": "interplay.scene", "version": 1,
  "settings": { "gravity": [0, -9.81, 0], "damping": { "linear": 0, "angular": 0 }, "sleep": { "enabled": false } },
  "bodies": [ { "name": "ball", "shape": { "type": "sphere", "radius": 0.1 }, "position": [0, 0, 0], "mass": 1,
                "linearVelocity": [3, 5, 0] } ]
})";

constexpr double kGravity = 9.81;

simcore::Scene parse(const char* text) {
    simcore::SceneLoadResult loaded = simcore::parseScene(text, "test");
    if (!loaded.ok()) qFatal("%s", loaded.diagnostics.front().toString().c_str());
    return *loaded.scene;
}

simcore::Scene sceneFile(const char* name) {
    simcore::SceneLoadResult loaded = simcore::loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/scenes/" + name);
    if (!loaded.ok()) qFatal("%s", loaded.diagnostics.front().toString().c_str());
    return *loaded.scene;
}

// The projectile over 1 s at 1/60 and 1/120 s steps, 1 and 2 substeps, against a reference at
// 1/240 s with 2 substeps (h = 1/480 s): sample instants every 1/60 s fall on every run's steps.
accuracy::SweepSpec projectileSpec() {
    accuracy::SweepSpec spec;
    spec.knobs = {{"timeStep", {"0.016666668", "0.008333334"}}, {"substeps", {"1", "2"}}};
    spec.seconds = 1.0;
    spec.sampleRate = 60.0;
    spec.reference = {"timeStep=0.004166667", "substeps=2"};
    return spec;
}

accuracy::Reference reference(const simcore::Scene& scene, const accuracy::SweepSpec& spec) {
    std::string error;
    std::optional<accuracy::Reference> r = accuracy::runReference(scene, spec, error);
    if (!r) qFatal("reference failed: %s", error.c_str());
    return *r;
}

std::vector<accuracy::PointResult> sweep(const simcore::Scene& scene, const accuracy::SweepSpec& spec,
                                         const accuracy::Reference& r, int jobs = 1) {
    accuracy::SweepRunOptions options;
    options.jobs = jobs;
    return accuracy::runSweep(scene, spec, accuracy::expandGrid(spec.knobs), r, options);
}

double substep(const accuracy::GridPoint& p) {
    simcore::Scene s = parse(kProjectile);
    for (const std::string& a : p.assignments) simcore::applySettingOverride(s, a);
    return static_cast<double>(s.settings.timeStep) / s.settings.substeps;
}

// Float rounding of the reference's own path: each of its 480 substeps rounds the position (under
// 5 m: half an ulp is 2.4e-7 m) and the velocity (under 6 m/s: 2.4e-7 m/s, carried for at most
// 1 s), so its drift from the exact discrete path is at most 480 x 4.8e-7 = 2.3e-4 m; the runs of
// the grid take fewer substeps and drift less. Measured: under 1e-5 m.
constexpr double kRoundingAllowance = 2.3e-4 + 1.2e-4;

}  // namespace

class TestSweep : public QObject {
    Q_OBJECT

private slots:
    void positionErrorMatchesClosedForm();
    void referenceConvergenceIsItsDistanceFromTheFinerRun();
    void finerReferenceChangesErrorsByLessThanReported();
    void gridIsEveryCombinationWithStableIds();
    void effectTogglesAreTheEffectsTheSceneUses();
    void badSpecNamesTheProblem_data();
    void badSpecNamesTheProblem();
    void threadsGiveTheSameNumbers();
    void resumedPointsAreNotRunAgain();
    void cancelStopsTheSweep();
    void fileRoundTripIsExact();
    void corruptPointFileIsRefused();
    void recommendationPicksTheCheapestWithinTheLimit();
};

void TestSweep::positionErrorMatchesClosedForm() {
    const simcore::Scene scene = parse(kProjectile);
    const accuracy::SweepSpec spec = projectileSpec();
    const accuracy::Reference r = reference(scene, spec);
    const double hReference = 1.0 / 480.0;
    const std::vector<accuracy::PointResult> points = sweep(scene, spec, r);
    QCOMPARE(points.size(), std::size_t(4));
    for (const accuracy::PointResult& p : points) {
        const double h = substep(p.point);
        // Both paths err by g h t / 2 in y, in the same direction: their distance is g (h - h_ref) t / 2,
        // largest at t = 1 s, and its RMS over the instants t_k = k / 60 is that times sqrt(mean(t_k^2)).
        const double largest = 0.5 * kGravity * (h - hReference) * 1.0;
        double meanSquare = 0.0;
        for (int k = 1; k <= 60; ++k) meanSquare += (k / 60.0) * (k / 60.0) / 60.0;
        QVERIFY2(std::abs(p.measures[at(Measure::PositionMax)] - largest) <= kRoundingAllowance,
                 qPrintable(QString("h %1: %2 against %3").arg(h).arg(p.measures[at(Measure::PositionMax)]).arg(largest)));
        QVERIFY(std::abs(p.measures[at(Measure::PositionRms)] - largest * std::sqrt(meanSquare)) <= kRoundingAllowance);
        // Against the exact path (error g h t / 2) the sweep's figure is off by the reference's own error.
        QVERIFY(std::abs(p.measures[at(Measure::PositionMax)] - 0.5 * kGravity * h) <=
                0.5 * kGravity * hReference + kRoundingAllowance);
        // Velocity is exact at every step for this method (gravity is constant): so is momentum.
        QVERIFY(p.measures[at(Measure::MomentumDrift)] <= 480 * 2.4e-7);
        QCOMPARE(p.measures[at(Measure::OrientationMax)], 0.0);
        QCOMPARE(p.measures[at(Measure::Penetration)], 0.0);
        QCOMPARE(p.measures[at(Measure::JointError)], 0.0);
        QVERIFY(!p.failed);
    }
}

void TestSweep::referenceConvergenceIsItsDistanceFromTheFinerRun() {
    const simcore::Scene scene = parse(kProjectile);
    const accuracy::Reference r = reference(scene, projectileSpec());
    // The run twice as fine (h = 1/960 s) is g (1/480 - 1/960) / 2 from the reference at 1 s; the
    // reference's own error, g / 480 / 2, is twice that (first order: halving h halves the error).
    const double expected = 0.5 * kGravity * (1.0 / 480.0 - 1.0 / 960.0);
    QVERIFY2(std::abs(r.convergence[at(Measure::PositionMax)] - expected) <= kRoundingAllowance,
             qPrintable(QString::number(r.convergence[at(Measure::PositionMax)])));
    QCOMPARE(r.assignments.back(), std::string("substeps=2"));
    const std::string finer = accuracy::finerAssignments(scene, r.assignments).back();
    QCOMPARE(finer.substr(0, 9), std::string("timeStep="));
    QCOMPARE(std::stof(finer.substr(9)), 0.004166667f * 0.5f);  // exactly half the reference's float step
}

void TestSweep::finerReferenceChangesErrorsByLessThanReported() {
    // A scene with joints, contacts-free swinging and rotation: the pendulums demo, half a second.
    const simcore::Scene scene = sceneFile("pendulums.json");
    accuracy::SweepSpec spec;
    spec.knobs = {{"substeps", {"1", "4"}}, {"solver.velocityIterations", {"1", "4"}}};
    spec.seconds = 0.5;
    spec.reference = {"timeStep=0.004166667", "substeps=4"};
    const accuracy::Reference coarse = reference(scene, spec);
    accuracy::SweepSpec finerSpec = spec;
    finerSpec.reference = accuracy::finerAssignments(scene, coarse.assignments);
    const accuracy::Reference fine = reference(scene, finerSpec);
    const std::vector<accuracy::PointResult> a = sweep(scene, spec, coarse);
    const std::vector<accuracy::PointResult> b = sweep(scene, finerSpec, fine);
    QCOMPARE(a.size(), b.size());
    // The measures against the reference are distances, so by the triangle inequality a new
    // reference moves each by at most its distance from the old one: the reported convergence.
    for (Measure m : {Measure::PositionMax, Measure::PositionRms, Measure::OrientationMax, Measure::OrientationRms,
                      Measure::EnergyDrift, Measure::MomentumDrift}) {
        QVERIFY(coarse.convergence[at(m)] > 0.0);
        for (std::size_t i = 0; i < a.size(); ++i) {
            const double change = std::abs(a[i].measures[at(m)] - b[i].measures[at(m)]);
            QVERIFY2(change <= coarse.convergence[at(m)] * (1.0 + 1e-9),
                     qPrintable(QString("%1 point %2: changed by %3, reported %4")
                                    .arg(QString::fromStdString(std::string(accuracy::measureKey(m))))
                                    .arg(i)
                                    .arg(change)
                                    .arg(coarse.convergence[at(m)])));
        }
    }
    // The run's own worst values do not depend on the reference at all.
    for (std::size_t i = 0; i < a.size(); ++i) {
        QCOMPARE(a[i].measures[at(Measure::JointError)], b[i].measures[at(Measure::JointError)]);
        QCOMPARE(a[i].measures[at(Measure::Penetration)], b[i].measures[at(Measure::Penetration)]);
    }
}

void TestSweep::gridIsEveryCombinationWithStableIds() {
    const std::vector<accuracy::GridPoint> grid =
        accuracy::expandGrid({{"substeps", {"1", "2", "4"}}, {"effects.friction", {"true", "false"}}});
    QCOMPARE(grid.size(), std::size_t(6));
    QCOMPARE(grid[0].assignments, (std::vector<std::string>{"substeps=1", "effects.friction=true"}));
    QCOMPARE(grid[1].assignments, (std::vector<std::string>{"substeps=1", "effects.friction=false"}));
    QCOMPARE(grid[5].assignments, (std::vector<std::string>{"substeps=4", "effects.friction=false"}));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        QCOMPARE(grid[i].id, accuracy::pointId(grid[i].assignments));
        QCOMPARE(grid[i].id.size(), std::size_t(16));
        for (std::size_t j = 0; j < i; ++j) QVERIFY(grid[i].id != grid[j].id);
    }
    QCOMPARE(accuracy::expandGrid(accuracy::defaultKnobs()).size(), std::size_t(72));
    QVERIFY(accuracy::expandGrid({{"substeps", {}}}).empty());
}

void TestSweep::effectTogglesAreTheEffectsTheSceneUses() {
    accuracy::SweepSpec spec;
    spec.seconds = 0.5;
    // Nothing to touch: no friction, restitution or sleeping can run; damping is off in the scene.
    const std::vector<std::vector<std::string>> none = accuracy::effectToggles(parse(kProjectile), spec);
    for (const auto& point : none)
        for (const char* effect : {"friction", "restitution", "damping", "sleeping"})
            QVERIFY2(point.front().find(effect) == std::string::npos, point.front().c_str());
    // A tower stands on friction; gravity, contacts and joints define a scene and are never toggled.
    const std::vector<std::vector<std::string>> tower = accuracy::effectToggles(sceneFile("tower20.json"), spec);
    QVERIFY(std::find(tower.begin(), tower.end(), std::vector<std::string>{"effects.friction=false"}) != tower.end());
    for (const auto& point : tower) QVERIFY(point.front().find("gravity") == std::string::npos);
    // Extra points come after the product, once each, and not again when the product holds them.
    spec.knobs = {{"substeps", {"1", "2"}}};
    spec.extraPoints = {{"effects.friction=false"}, {"substeps=2"}, {"effects.friction=false"}};
    const std::vector<accuracy::GridPoint> grid = accuracy::gridPoints(spec);
    QCOMPARE(grid.size(), std::size_t(3));
    QCOMPARE(grid[2].assignments, std::vector<std::string>{"effects.friction=false"});
    QVERIFY(!accuracy::checkSpec(sceneFile("tower20.json"), spec));
    spec.extraPoints = {{"effects.bogus=false"}};
    QVERIFY(accuracy::checkSpec(sceneFile("tower20.json"), spec)->find("unknown setting 'effects.bogus'") != std::string::npos);
}

void TestSweep::badSpecNamesTheProblem_data() {
    QTest::addColumn<QString>("knob");
    QTest::addColumn<QString>("values");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown knob") << "solver.bogus" << "1" << "unknown setting 'solver.bogus'";
    QTest::newRow("no values") << "substeps" << "" << "the grid is empty: knob 'substeps' has no values";
    QTest::newRow("out of range") << "substeps" << "0" << "knob 'substeps=0': invalid value for setting 'substeps'";
    QTest::newRow("not a number") << "timeStep" << "fast" << "knob 'timeStep=fast'";
    QTest::newRow("bad choice") << "integrator" << "rk4" << "knob 'integrator=rk4'";
}

void TestSweep::badSpecNamesTheProblem() {
    QFETCH(QString, knob);
    QFETCH(QString, values);
    QFETCH(QString, message);
    accuracy::SweepSpec spec;
    accuracy::Knob k{knob.toStdString(), {}};
    if (!values.isEmpty()) k.values.push_back(values.toStdString());
    spec.knobs = {k};
    const std::optional<std::string> problem = accuracy::checkSpec(parse(kProjectile), spec);
    QVERIFY(problem);
    QVERIFY2(QString::fromStdString(*problem).contains(message), problem->c_str());

    spec.knobs = {{"substeps", {"1"}}, {"substeps", {"2"}}};
    QVERIFY(accuracy::checkSpec(parse(kProjectile), spec)->find("given twice") != std::string::npos);
    spec.knobs.clear();
    QVERIFY(accuracy::checkSpec(parse(kProjectile), spec)->find("the grid is empty") != std::string::npos);
    spec.knobs = {{"substeps", {"1"}}};
    spec.reference = {"solver.nothing=3"};
    QVERIFY(accuracy::checkSpec(parse(kProjectile), spec)->find("--reference solver.nothing=3") != std::string::npos);
}

void TestSweep::threadsGiveTheSameNumbers() {
    const simcore::Scene scene = sceneFile("pendulums.json");
    accuracy::SweepSpec spec;
    spec.knobs = {{"substeps", {"1", "2", "4"}}, {"solver.positionIterations", {"0", "1"}}};
    spec.seconds = 0.25;
    spec.reference = {"timeStep=0.008333334", "substeps=4"};
    const accuracy::Reference r = reference(scene, spec);
    const std::vector<accuracy::PointResult> one = sweep(scene, spec, r, 1);
    const std::vector<accuracy::PointResult> three = sweep(scene, spec, r, 3);
    QCOMPARE(one.size(), std::size_t(6));
    QCOMPARE(three.size(), one.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        QCOMPARE(three[i].point.id, one[i].point.id);
        QVERIFY(three[i].measures == one[i].measures);  // bit for bit
    }
    // The reference with its half-step check on a thread of its own (--jobs above 1).
    std::string error;
    const std::optional<accuracy::Reference> sideBySide = accuracy::runReference(scene, spec, error, nullptr, 2);
    QVERIFY2(sideBySide, error.c_str());
    QVERIFY(sideBySide->run.positions == r.run.positions);
    QVERIFY(sideBySide->run.orientations == r.run.orientations);
    QVERIFY(sideBySide->convergence == r.convergence);
}

void TestSweep::resumedPointsAreNotRunAgain() {
    const simcore::Scene scene = parse(kProjectile);
    const accuracy::SweepSpec spec = projectileSpec();
    const accuracy::Reference r = reference(scene, spec);
    const std::vector<accuracy::GridPoint> grid = accuracy::expandGrid(spec.knobs);
    accuracy::PointResult known;
    known.point = grid[2];
    known.msPerStep = 123.0;  // no run measures that: it shows the result was taken as found
    accuracy::SweepRunOptions options;
    options.jobs = 2;
    options.lookup = [&](const accuracy::GridPoint& p) -> std::optional<accuracy::PointResult> {
        if (p.id == known.point.id) return known;
        return std::nullopt;
    };
    std::vector<std::string> ran;
    options.finished = [&](const accuracy::PointResult& p) { ran.push_back(p.point.id); };
    std::size_t lastDone = 0;
    options.progress = [&](const accuracy::SweepProgress& p) {
        QCOMPARE(p.total, grid.size());
        QCOMPARE(p.done, lastDone + 1);
        lastDone = p.done;
    };
    const std::vector<accuracy::PointResult> points = accuracy::runSweep(scene, spec, grid, r, options);
    QCOMPARE(points.size(), grid.size());
    QCOMPARE(points[2].msPerStep, 123.0);
    QCOMPARE(ran.size(), grid.size() - 1);
    QVERIFY(std::find(ran.begin(), ran.end(), known.point.id) == ran.end());
    QCOMPARE(lastDone, grid.size());
}

void TestSweep::cancelStopsTheSweep() {
    const simcore::Scene scene = parse(kProjectile);
    const accuracy::SweepSpec spec = projectileSpec();
    const accuracy::Reference r = reference(scene, spec);
    std::atomic<bool> cancel{false};
    accuracy::SweepRunOptions options;
    options.cancel = &cancel;
    options.progress = [&](const accuracy::SweepProgress&) { cancel.store(true); };  // after the first point
    const std::vector<accuracy::PointResult> points =
        accuracy::runSweep(scene, spec, accuracy::expandGrid(spec.knobs), r, options);
    QCOMPARE(points.size(), std::size_t(1));
    // A run already under way stops at its next step.
    QVERIFY(!accuracy::runPoint(scene, spec, accuracy::expandGrid(spec.knobs)[0], r, &cancel));
    std::string error;
    QVERIFY(!accuracy::runReference(scene, spec, error, &cancel));
    QCOMPARE(error, std::string("cancelled"));
    error.clear();
    QVERIFY(!accuracy::runReference(scene, spec, error, &cancel, 2));
    QCOMPARE(error, std::string("cancelled"));
}

void TestSweep::fileRoundTripIsExact() {
    QTemporaryDir dir;
    const simcore::Scene scene = parse(kProjectile);
    const accuracy::SweepSpec spec = projectileSpec();
    const accuracy::Reference r = reference(scene, spec);
    const std::vector<accuracy::PointResult> points = sweep(scene, spec, r);
    const std::string key = accuracy::sweepKey(scene, spec);
    const std::filesystem::path base = dir.path().toStdString();
    QVERIFY(!accuracy::writeFileAtomically(base / "reference.json", accuracy::referenceJson(r, key).dump()));
    QVERIFY(!accuracy::writeFileAtomically(base / (points[1].point.id + ".json"), accuracy::pointJson(points[1], key).dump()));
    std::string error;
    const std::optional<accuracy::Reference> back = accuracy::readReference(base / "reference.json", key, error);
    QVERIFY2(back, error.c_str());
    QVERIFY(back->run.positions == r.run.positions && back->run.orientations == r.run.orientations);
    QVERIFY(back->run.energy == r.run.energy && back->convergence == r.convergence);
    const std::optional<accuracy::PointResult> p = accuracy::readPoint(base / (points[1].point.id + ".json"), key, error);
    QVERIFY2(p, error.c_str());
    QVERIFY(p->measures == points[1].measures);
    QCOMPARE(p->msPerStep, points[1].msPerStep);
    // Another sweep's key is refused; no temporary is left behind.
    QVERIFY(!accuracy::readReference(base / "reference.json", "0000000000000000", error));
    QVERIFY(QString::fromStdString(error).contains("another sweep"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);
}

void TestSweep::corruptPointFileIsRefused() {
    QTemporaryDir dir;
    const std::filesystem::path file = dir.path().toStdString() + "/0123456789abcdef.json";
    std::string error;
    for (const char* text : {"", "{\"format\": \"interplay.sweep-point\"", "[1, 2]",
                             R"({"format": "interplay.sweep-point", "version": 1, "sweep": "k", "id": "0123456789abcdef"})"}) {
        QVERIFY(!accuracy::writeFileAtomically(file, text));
        QVERIFY(!accuracy::readPoint(file, "k", error));
        QVERIFY2(QString::fromStdString(error).contains("0123456789abcdef.json: corrupt"), error.c_str());
    }
}

void TestSweep::recommendationPicksTheCheapestWithinTheLimit() {
    accuracy::SweepPlan plan;
    plan.scenePath = "scene.json";
    plan.spec.knobs = {{"substeps", {"1", "4", "8"}}};
    accuracy::Reference r;
    accuracy::SweepReport report;
    report.plan = &plan;
    report.reference = &r;
    auto point = [](std::string knob, double penetration, double msPerSecond) {
        accuracy::PointResult p;
        p.point.assignments = {std::move(knob)};
        p.measures[at(Measure::Penetration)] = penetration;
        p.msPerSimulatedSecond = msPerSecond;
        p.msPerStep = msPerSecond / 60.0;
        return p;
    };
    report.points = {point("substeps=1", 0.004, 1.0), point("substeps=4", 0.0009, 3.0), point("substeps=8", 0.0002, 6.0)};
    const std::string line = accuracy::recommendation(report, Measure::Penetration, 0.001);
    QVERIFY2(line.rfind("for deepest penetration <= 0.001 m: substeps=4 — 0.05 ms/step", 0) == 0, line.c_str());
    const std::string none = accuracy::recommendation(report, Measure::Penetration, 0.0001);
    QVERIFY2(none.find("no point reaches") == 0 && none.find("substeps=8") != std::string::npos, none.c_str());
    // A point beyond the product is the scene's settings with its one change.
    report.points.push_back(point("effects.friction=false", 0.0005, 0.5));
    const std::string extra = accuracy::recommendation(report, Measure::Penetration, 0.001);
    QVERIFY2(extra.find(": the scene's settings with effects.friction=false — ") != std::string::npos, extra.c_str());
}

QTEST_GUILESS_MAIN(TestSweep)
#include "test_sweep.moc"
