// The longest of the hard cases, kept out of the sanitizer run by its ctest label "long": a
// pyramid of base 20 (2870 cubes, scenes/bench/pyramid20.json) resting exactly must stand for 10 s
// at the defaults with every cube within 2 cm of where it started, and a tower of 40 unit cubes
// for 30 s with its top cube within 2 cm sideways and 10 cm of its height (issue 12), also awake.

#include "simcore/world/world.h"

#include "support/worlds.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace simcore;
using namespace test_support;

class TestLongStability : public QObject {
    Q_OBJECT

private slots:
    void pyramidOfBase20Stands10s();
    void towerOf40Stands30s();
    void awakeTowerOf40Stands30s();
};

// With friction solved in the pushing passes too, the upper layers bounced from the first step and
// a slow sideways creep toppled the pyramid at the defaults (1.19 m in 10 s; 8 substeps held it to
// 9 mm). Friction in the relax passes only holds it at the defaults: measured 5 mm, most of it the
// soft contacts' compression under 20 layers.
void TestLongStability::pyramidOfBase20Stands10s() {
    World world(awakeSettings());
    addGround(world);
    std::vector<BodyId> cubes;
    for (const Vec3& centre : squarePyramidCentres(20)) cubes.push_back(world.createBody(cube(centre)));
    QCOMPARE(cubes.size(), std::size_t{2870});
    std::vector<Vec3> start;
    for (BodyId id : cubes) start.push_back(world.position(id));
    float worst = 0.0f;
    for (int i = 0, n = stepsFor(world, 10.0f); i < n; ++i) {
        world.step();
        if (i % 30 != 29) continue;  // twice a second: a failing pyramid creeps for seconds first
        for (std::size_t c = 0; c < cubes.size(); ++c) worst = std::max(worst, glm::length(world.position(cubes[c]) - start[c]));
    }
    qInfo("pyramid of base 20, defaults: worst drift %.4f m", worst);
    QVERIFY2(worst < 0.02f, qPrintable(QString("a cube moved %1 m").arg(worst)));
}

namespace {

// How far the top cube of a tower of 40 unit cubes on the ground strays over 30 s: its largest
// offset sideways and up or down from where it started.
struct TopCubeExcursion {
    float sideways = 0.0f, height = 0.0f;
};

TopCubeExcursion towerOf40TopExcursion(const WorldSettings& settings) {
    World world(settings);
    addGround(world);
    BodyId top;
    for (const Vec3& centre : towerCentres(40)) top = world.createBody(cube(centre));
    const Vec3 start = world.position(top);
    TopCubeExcursion excursion;
    for (int i = 0, n = stepsFor(world, 30.0f); i < n; ++i) {
        world.step();
        const Vec3 offset = world.position(top) - start;
        excursion.sideways = std::max(excursion.sideways, std::hypot(offset.x, offset.z));
        excursion.height = std::max(excursion.height, std::abs(offset.y));
    }
    return excursion;
}

}  // namespace

// At the defaults, sleep included. It sinks by the soft contacts' compression, about 0.14 mm per
// cube above each contact where the spring is not stiffened, and further while the load first
// reaches the bottom: 16.4 cm before loaded contacts were stiffened (ContactSolver::kStiffLoad),
// 8.1 cm since.
void TestLongStability::towerOf40Stands30s() {
    const TopCubeExcursion top = towerOf40TopExcursion(WorldSettings{});
    qInfo("tower of 40, defaults: top cube at most %.4f m sideways, %.4f m off its height", top.sideways, top.height);
    QVERIFY2(top.sideways < 0.02f, qPrintable(QString("the top cube moved %1 m sideways").arg(top.sideways)));
    QVERIFY2(top.height < 0.10f, qPrintable(QString("the top cube is %1 m off its height").arg(top.height)));
}

// The same tower with sleeping off, so that nothing but the contacts holds it for 30 s. Its
// joints are soft springs, and the weight above each tips a leaning cube further: while kept
// manifolds turned their points with their bodies, towers of 28 cubes and more buckled within
// 10 s (40 fell at 8.7 s). Box3D's tower of 40 stands awake at its defaults (3.5 cm sideways).
void TestLongStability::awakeTowerOf40Stands30s() {
    const TopCubeExcursion top = towerOf40TopExcursion(awakeSettings());
    qInfo("tower of 40, awake: top cube at most %.4f m sideways", top.sideways);
    QVERIFY2(top.sideways < 0.02f, qPrintable(QString("the top cube moved %1 m sideways").arg(top.sideways)));
}

QTEST_APPLESS_MAIN(TestLongStability)
#include "test_long_stability.moc"
