// The longest of the hard cases, kept out of the sanitizer run by its ctest label "long": a
// pyramid of base 20 (2870 cubes, scenes/bench/pyramid20.json) resting exactly must stand for 10 s
// at the defaults with every cube within 2 cm of where it started.

#include "simcore/world/world.h"

#include "support/worlds.h"

#include <QtTest>

#include <algorithm>
#include <vector>

using namespace simcore;
using namespace test_support;

class TestLongStability : public QObject {
    Q_OBJECT

private slots:
    void pyramidOfBase20Stands10s();
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

QTEST_APPLESS_MAIN(TestLongStability)
#include "test_long_stability.moc"
