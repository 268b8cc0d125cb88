// The run's series (app/simulation/run_series.h), without a window: energy samples of a ball in
// free fall against the closed form, penetration and joint error samples against the World's own
// queries at the same steps, the ring's bound, and the samples a run resumed from an earlier frame
// drops, as the timeline drops its frames.

#include "app/simulation/run_series.h"
#include "app/simulation/simulation_controller.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/world.h"

#include <QtTest>

#include <cmath>

using namespace interplay;
using namespace simcore;

namespace {

Scene loadShippedScene(const char* name) {
    SceneLoadResult loaded = loadSceneFile(std::string(INTERPLAY_SOURCE_DIR) + "/scenes/" + name);
    if (!loaded.ok()) qFatal("cannot load scenes/%s", name);
    return *loaded.scene;
}

}  // namespace

class TestRunSeries : public QObject {
    Q_OBJECT

private slots:
    void freeFallEnergyFollowsTheClosedForm();
    void penetrationAndJointErrorAreTheWorldsQueries();
    void ringKeepsTheNewestSamples();
    void nearestFindsTheClosestTime();
    void resumingFromAnEarlierFrameDropsTheLaterSamples();
    void aNewWorldStartsAnEmptySeries();
};

void TestRunSeries::freeFallEnergyFollowsTheClosedForm() {
    World world;  // no ground: nothing but gravity acts
    BodyCreationSettings ball;
    ball.shape = Shape::sphere(0.25f);
    ball.position = Vec3(0.0f, 20.0f, 0.0f);
    ball.mass = 2.0f;
    world.createBody(ball);
    const double m = 2.0, g = -double(world.settings().gravity.y), y0 = 20.0;
    const double substep = double(world.settings().timeStep) / world.settings().substeps;

    RunSeries series;
    for (int i = 0; i < 120; ++i) {
        world.step();
        series.record(world);
    }
    QCOMPARE(series.size(), std::size_t(120));
    const double initialEnergy = m * g * y0;
    for (std::size_t i = 0; i < series.size(); ++i) {
        const RunSample& s = series[i];
        QCOMPARE(s.step, std::uint64_t(i + 1));
        // Symplectic Euler gives v = g t exactly; the velocity is a float summed once per substep,
        // each sum off by at most half an ulp, so kinetic energy is within 2 n 2^-24 relative.
        const double kinetic = 0.5 * m * g * g * s.time * s.time;
        const double substeps = s.time / substep;
        QVERIFY2(std::abs(s.kineticEnergy - kinetic) <= 2.0 * substeps * 0x1p-24 * kinetic + 1e-9,
                 qPrintable(QString("step %1: kinetic %2 J, closed form %3 J").arg(s.step).arg(s.kineticEnergy).arg(kinetic)));
        // Total energy: the integrator moves by the new velocity, so each substep h loses
        // m g^2 h^2 / 2, a drift of m g^2 h t / 2 by time t (0.8 J at 2 s here); the position is a
        // float below 20 m (ulp at most 2e-6 m) rounded once per substep: m g n 1e-6 bounds that.
        const double drift = 0.5 * m * g * g * substep * s.time;
        const double rounding = m * g * substeps * 1e-6;
        const double change = s.totalEnergy() - initialEnergy;
        QVERIFY2(std::abs(change) <= drift + rounding,
                 qPrintable(QString("step %1: total %2 J, initially %3 J").arg(s.step).arg(s.totalEnergy()).arg(initialEnergy)));
        // And the change is that loss, not some other error of the same size.
        QVERIFY2(std::abs(change + drift) <= rounding,
                 qPrintable(QString("step %1: total energy changed by %2 J, the integrator loses %3 J").arg(s.step).arg(change).arg(drift)));
        QCOMPARE(s.maxPenetration, 0.0);
        QCOMPARE(s.jointError, 0.0);
    }
}

void TestRunSeries::penetrationAndJointErrorAreTheWorldsQueries() {
    // The ragdoll falls onto the ground: contacts overlap and its joints stretch on impact.
    BuiltWorld built = buildWorld(loadShippedScene("ragdoll.json"));
    RunSeries series;
    double deepest = 0.0, worstJoint = 0.0;
    for (int i = 0; i < 180; ++i) {
        built.world.step();
        series.record(built.world);
        const RunSample& s = series.back();
        QCOMPARE(s.step, built.world.stepCount());
        QCOMPARE(s.time, built.world.simulatedTime());
        QCOMPARE(s.maxPenetration, double(built.world.lastStepProfile().maxPenetration));
        QCOMPARE(s.jointError, double(built.world.worstJointError().position));
        QCOMPARE(s.kineticEnergy, built.world.kineticEnergy());
        QCOMPARE(s.potentialEnergy, built.world.potentialEnergy());
        QCOMPARE(s.totalMs, built.world.lastStepProfile().totalMs);
        QVERIFY(s.stageMs == built.world.lastStepProfile().stageMs);
        deepest = std::max(deepest, s.maxPenetration);
        worstJoint = std::max(worstJoint, s.jointError);
    }
    // Both measures were exercised, not zero throughout.
    QVERIFY2(deepest > 0.0, "no contact overlapped in three seconds of the ragdoll");
    QVERIFY2(worstJoint > 0.0, "no joint stretched in three seconds of the ragdoll");
}

void TestRunSeries::ringKeepsTheNewestSamples() {
    World world;
    world.createBody(BodyCreationSettings{});
    RunSeries series(50);
    for (int i = 0; i < 120; ++i) {
        world.step();
        series.record(world);
        QVERIFY(series.size() <= 50);
    }
    QCOMPARE(series.size(), std::size_t(50));
    QCOMPARE(series.front().step, std::uint64_t(71));
    QCOMPARE(series.back().step, std::uint64_t(120));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RunSeries(0));
}

void TestRunSeries::nearestFindsTheClosestTime() {
    World world;
    world.createBody(BodyCreationSettings{});
    RunSeries series;
    QVERIFY(!series.nearest(1.0));
    for (int i = 0; i < 10; ++i) {
        world.step();
        series.record(world);
    }
    const double dt = world.settings().timeStep;
    QCOMPARE(*series.nearest(-5.0), std::size_t(0));
    QCOMPARE(*series.nearest(100.0), std::size_t(9));
    QCOMPARE(*series.nearest(3.4 * dt), std::size_t(2));  // sample 2 is at 3 dt
    QCOMPARE(*series.nearest(3.6 * dt), std::size_t(3));
}

void TestRunSeries::resumingFromAnEarlierFrameDropsTheLaterSamples() {
    SimulationController simulation;
    QString error;
    QVERIFY2(simulation.setScene(loadShippedScene("ragdoll.json"), &error), qPrintable(error));
    simulation.stepFrames(40);
    const RunSeries& series = simulation.series();
    QCOMPARE(series.size(), std::size_t(40));
    std::vector<RunSample> recorded;
    for (std::size_t i = 0; i < series.size(); ++i) recorded.push_back(series[i]);

    // Scrubbing back keeps the samples (Step goes on through the recorded frames) ...
    QVERIFY(simulation.showFrame(15));
    QCOMPARE(simulation.world()->stepCount(), std::uint64_t(15));
    QCOMPARE(series.size(), std::size_t(40));
    simulation.stepOnce();  // shows frame 16, recorded
    QCOMPARE(series.size(), std::size_t(40));

    // ... and running on from the frame drops those after it, as the timeline drops its frames.
    simulation.stepFrames(10);
    QCOMPARE(simulation.timeline().frameCount(), std::size_t(27));  // steps 0 to 26
    QCOMPARE(series.size(), std::size_t(26));
    for (std::size_t i = 0; i < series.size(); ++i) {
        QCOMPARE(series[i].step, std::uint64_t(i + 1));
        // The resumed run is the recorded run bit for bit, so its samples are the same values.
        QCOMPARE(series[i].kineticEnergy, recorded[i].kineticEnergy);
        QCOMPARE(series[i].jointError, recorded[i].jointError);
    }
}

void TestRunSeries::aNewWorldStartsAnEmptySeries() {
    SimulationController simulation;
    QVERIFY(simulation.setScene(loadShippedScene("ragdoll.json")));
    simulation.stepFrames(5);
    QCOMPARE(simulation.series().size(), std::size_t(5));
    simulation.reset();
    QVERIFY(simulation.series().empty());
    simulation.stepFrames(3);
    QVERIFY(simulation.setScene(loadShippedScene("pendulums.json")));
    QVERIFY(simulation.series().empty());
}

QTEST_GUILESS_MAIN(TestRunSeries)
#include "test_run_series.moc"
