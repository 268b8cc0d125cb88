// GJK distance and EPA penetration depth.
//
// Table: configurations with a closed-form answer (separated, touching, penetrating, deep,
// coincident, thin, huge, rotated), each also checked with A and B swapped and with the whole
// scene moved by a rigid transform. Scale sweep: one configuration scaled from 1 mm to 1 km must
// give proportional answers. Fuzz: random shape pairs, where every answer is checked against a
// certificate that does not trust the algorithm:
//   - separated: the closest points lie in their shapes, on the supporting planes of the normal,
//     and are `distance` apart along it; that proves `distance` is the true gap;
//   - penetrating: the shapes overlap along the normal by exactly `depth` (support functions),
//     no sampled direction needs less, moving B by a little more than depth separates (GJK) and
//     by a little less does not.
// Plus: warm-start cache, the boolean query, and no heap allocation in the queries.

#include "support/allocation_counter.h"
#include "support/geometry.h"
#include "simcore/collision/epa.h"
#include "simcore/collision/gjk.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/shape.h"

#include <QtTest>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

using namespace simcore;
using namespace test_support;

namespace {

// ---- Helpers -------------------------------------------------------------------------------------

// Overlap of A and B along n: how far B must move along n to separate.
float overlapAlong(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, const Vec3& n) {
    return extentAlong(a, ta, n) + extentAlong(b, tb, -n);
}

Shape scaled(const Shape& s, float k) {
    switch (s.type) {
        case ShapeType::Sphere: return Shape::sphere(s.radius * k);
        case ShapeType::Box: return Shape::box(s.halfExtents * k);
        case ShapeType::Capsule: return Shape::capsule(s.radius * k, s.halfHeight * k);
        case ShapeType::Cylinder: return Shape::cylinder(s.radius * k, s.halfHeight * k);
        case ShapeType::ConvexHull: {
            std::vector<Vec3> points = s.hull->vertices();
            for (Vec3& p : points) p *= k;
            return Shape::convexHull(buildHull(points));
        }
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // not convex: GJK never sees them
    }
    return s;
}

bool isFiniteQuery(const ContactQuery& q) {
    return isFinite(q.distance) && isFinite(q.depth) && isFinite(q.normal) && isFinite(q.pointA) && isFinite(q.pointB);
}

// ---- Table cases ---------------------------------------------------------------------------------

struct PairCase {
    Shape a;
    Transform ta;
    Shape b;
    Transform tb;
    float expectedSigned = 0.0f;  // gap if > 0, minus the depth if < 0
    Vec3 expectedNormal{0.0f};    // A to B; zero when the contact normal is not unique
    bool normalSignFree = false;  // either sign is right (symmetric configurations)
    float tolerance = 1e-5f;      // on the signed distance (m)
    float normalTolerance = 1e-4f;  // on |normal - expected|
};

}  // namespace

Q_DECLARE_METATYPE(PairCase)

class TestGjkEpa : public QObject {
    Q_OBJECT

private slots:
    void table_data();
    void table();
    void scaleSweep_data();
    void scaleSweep();
    void fuzz();
    void fuzzExtremeShapes();
    void nearContactFuzz();
    void warmStartCache();
    void intersectMatchesDistance();
    void noHeapAllocation();
    void nonFiniteInputGivesFiniteResult();
};

namespace {

const Vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);
constexpr float kSqrtHalf = 0.70710678f;

// Adds the case, and the same scene moved by an arbitrary rigid transform (the answer must not care).
void addCase(const char* name, const PairCase& c) {
    QTest::newRow(name) << c;
    const Transform scene = place(Vec3(3.7f, -12.25f, 41.5f), rotation(63.0f, Vec3(0.3f, -1.0f, 0.55f)));
    PairCase moved = c;
    moved.ta = compose(scene, c.ta);
    moved.tb = compose(scene, c.tb);
    moved.expectedNormal = scene.rotate(c.expectedNormal);
    // Coordinates of about 45 m: 8 ulps there are 3e-5 m.
    moved.tolerance = std::max(c.tolerance, 4e-5f);
    moved.normalTolerance = std::max(c.normalTolerance, 2e-4f);
    QTest::newRow((std::string(name) + " (moved)").c_str()) << moved;
}

PairCase pairCase(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float expected,
                  const Vec3& normal, float tolerance = 1e-5f) {
    PairCase c;
    c.a = a;
    c.ta = ta;
    c.b = b;
    c.tb = tb;
    c.expectedSigned = expected;
    c.expectedNormal = normal;
    c.tolerance = tolerance;
    return c;
}

}  // namespace

// Tolerances: unit-sized scenes near the origin have coordinates of about 1 m, where a float ulp is
// 1.2e-7 m; GJK resolves distances to 1e-6 relative plus an ulp of the coordinates (8 ulps when
// touching), and EPA depths to 1e-4 relative plus 8 ulps. So 1e-5 m for flat features (they are
// found exactly; the check adds 1e-4 of the expected value for EPA), a little
// more for EPA on curved sides, and proportionally more for the 1 km box.
void TestGjkEpa::table_data() {
    QTest::addColumn<PairCase>("pair");
    const Transform origin = place(Vec3(0.0f));
    const Shape unitBox = Shape::box(Vec3(0.5f));

    // Spheres.
    addCase("sphere-sphere separated",
            pairCase(Shape::sphere(0.5f), origin, Shape::sphere(0.3f), place({1.2f, 1.6f, 0.0f}), 1.2f, {0.6f, 0.8f, 0.0f}));
    addCase("sphere-sphere penetrating",
            pairCase(Shape::sphere(0.5f), origin, Shape::sphere(0.3f), place({0.6f, 0, 0}), -0.2f, kX));
    {
        PairCase c = pairCase(Shape::sphere(0.5f), origin, Shape::sphere(0.3f), origin, -0.8f, Vec3(0.0f));
        addCase("sphere-sphere concentric", c);
    }

    // Boxes.
    addCase("box-box face-face", pairCase(unitBox, origin, unitBox, place({0, 1.25f, 0}), 0.25f, kY));
    addCase("box-box face-face offset", pairCase(unitBox, origin, unitBox, place({0.3f, 1.25f, -0.2f}), 0.25f, kY));
    addCase("box-box edge-edge crossed",
            pairCase(unitBox, place({0, 0, 0}, rotation(45, kZ)), unitBox, place({0, 1.5f, 0}, rotation(45, kX)),
                     1.5f - 4.0f * 0.5f * kSqrtHalf, kY));
    addCase("box-box parallel edges",
            pairCase(unitBox, place({0, 0, 0}, rotation(45, kZ)), unitBox, place({0, 1.5f, 0.2f}, rotation(45, kZ)),
                     1.5f - 4.0f * 0.5f * kSqrtHalf, kY));
    {
        // B's corner straight down onto A's top face.
        const Quat cornerDown = rotationBetween(Vec3(1, 1, 1), -kY);
        const float cornerDepth = 0.5f * std::sqrt(3.0f);
        addCase("box-box vertex-face",
                pairCase(unitBox, origin, unitBox, place({0.1f, 0.5f + cornerDepth + 0.1f, 0.05f}, cornerDown), 0.1f, kY));
        addCase("box-box vertex-face penetrating",
                pairCase(unitBox, origin, unitBox, place({0.1f, 0.5f + cornerDepth - 0.1f, 0.05f}, cornerDown), -0.1f, kY));
    }
    addCase("box-box face-face penetrating",
            pairCase(unitBox, origin, Shape::box({0.4f, 0.3f, 0.45f}), place({0.25f, 0.7f, -0.1f}), -0.1f, kY));

    // Touching: distance exactly 0 (coordinates exact in float, or to an ulp for the rotated ones).
    addCase("touching face-face aligned", pairCase(unitBox, origin, unitBox, place({0, 1, 0}), 0.0f, kY));
    addCase("touching face-face offset", pairCase(unitBox, origin, unitBox, place({0.3f, 1, 0.25f}), 0.0f, kY));
    addCase("touching edge on face",
            pairCase(unitBox, place({0, 0, 0}, rotation(45, kZ)), unitBox, place({0.1f, 0.5f + kSqrtHalf, 0}), 0.0f, kY));
    addCase("touching crossed edges",
            pairCase(unitBox, place({0, 0, 0}, rotation(45, kZ)), unitBox, place({0, 2 * kSqrtHalf, 0}, rotation(45, kX)),
                     0.0f, kY));
    // Coplanar faces, overlapping.
    addCase("coplanar faces penetrating aligned", pairCase(unitBox, origin, unitBox, place({0, 0.9f, 0}), -0.1f, kY));
    addCase("coplanar faces penetrating offset",
            pairCase(unitBox, origin, unitBox, place({0.25f, 0.9f, 0.25f}), -0.1f, kY));

    // Identical coincident shapes: the depth is the smallest full extent, along that axis (either sign).
    {
        const Shape slab = Shape::box({0.5f, 0.3f, 0.8f});
        const Transform t = place({0.2f, -0.1f, 0.3f}, rotation(30, {1, 2, 3}));
        PairCase c = pairCase(slab, t, slab, t, -0.6f, t.rotate(kY));
        c.normalSignFree = true;
        addCase("coincident boxes", c);
        PairCase cube = pairCase(unitBox, origin, unitBox, origin, -1.0f, Vec3(0.0f));
        addCase("coincident cubes", cube);
    }

    // Sphere against box: face, edge, vertex regions, penetrating and centre inside.
    addCase("box-sphere face", pairCase(unitBox, origin, Shape::sphere(0.5f), place({0, 1.2f, 0}), 0.2f, kY));
    addCase("box-sphere edge",
            pairCase(unitBox, origin, Shape::sphere(0.25f), place({0.8f, 0.8f, 0.1f}), 0.3f * std::sqrt(2.0f) - 0.25f,
                     glm::normalize(Vec3(1, 1, 0))));
    addCase("box-sphere vertex",
            pairCase(unitBox, origin, Shape::sphere(0.25f), place({0.8f, 0.8f, 0.8f}), 0.3f * std::sqrt(3.0f) - 0.25f,
                     glm::normalize(Vec3(1, 1, 1))));
    addCase("box-sphere penetrating",
            pairCase(unitBox, origin, Shape::sphere(0.25f), place({0.1f, 0.65f, 0.0f}), -0.1f, kY));
    addCase("deep: sphere centre inside box",
            pairCase(Shape::box({1.0f, 0.5f, 2.0f}), origin, Shape::sphere(0.2f), place({0.3f, 0.35f, -0.5f}), -0.35f, kY));
    addCase("deep: sphere centre inside box (A is the sphere)",
            pairCase(Shape::sphere(0.2f), place({0.3f, 0.35f, -0.5f}), Shape::box({1.0f, 0.5f, 2.0f}), origin, -0.35f, -kY));
    addCase("deep: sphere centre inside rotated box",
            pairCase(Shape::box({1.0f, 0.5f, 2.0f}), place({0, 0, 0}, rotation(37, {1, 1, 0})), Shape::sphere(0.2f),
                     place(rotation(37, {1, 1, 0}) * Vec3(-0.8f, 0.1f, 0.4f)), -0.4f, rotation(37, {1, 1, 0}) * -kX));

    // Capsules.
    addCase("capsule-capsule parallel",
            pairCase(Shape::capsule(0.2f, 0.5f), origin, Shape::capsule(0.2f, 0.5f), place({0.6f, 0.3f, 0}), 0.2f, kX));
    addCase("capsule-capsule crossed",
            pairCase(Shape::capsule(0.2f, 0.5f), origin, Shape::capsule(0.2f, 0.5f), place({0.5f, 0.2f, 0}, rotation(90, kX)),
                     0.1f, kX));
    addCase("capsule-capsule crossed penetrating",
            pairCase(Shape::capsule(0.2f, 0.5f), origin, Shape::capsule(0.2f, 0.5f), place({0.3f, 0.2f, 0}, rotation(90, kX)),
                     -0.1f, kX));
    addCase("capsule-capsule end to end",
            pairCase(Shape::capsule(0.2f, 0.5f), origin, Shape::capsule(0.3f, 0.4f), place({0, 1.5f, 0}), 0.1f, kY));
    {
        PairCase c = pairCase(Shape::capsule(0.2f, 0.5f), origin, Shape::capsule(0.2f, 0.5f),
                              place({0, 0.2f, 0}, rotation(90, kX)), -0.4f, kX);
        c.normalSignFree = true;  // the cores cross: +x and -x need the same push
        addCase("capsule-capsule cores crossing", c);
    }
    addCase("capsule-box deep (segment inside box)",
            pairCase(Shape::box({1.0f, 1.0f, 1.0f}), origin, Shape::capsule(0.1f, 0.3f), place({0.2f, 0.0f, 0.75f}),
                     -0.35f, kZ));

    // Cylinders.
    addCase("cylinder-box side",
            pairCase(Shape::cylinder(0.5f, 0.5f), origin, unitBox, place({1.2f, 0.1f, 0}), 0.2f, kX));
    addCase("cylinder-box cap",
            pairCase(Shape::cylinder(0.5f, 0.5f), origin, unitBox, place({0.2f, 1.3f, 0.1f}), 0.3f, kY));
    addCase("cylinder-box rim on face",
            pairCase(Shape::cylinder(0.5f, 0.5f), place({0, 0, 0}, rotation(30, kZ)), unitBox,
                     place({0, 0.5f * std::cos(glm::radians(30.0f)) + 0.5f * std::sin(glm::radians(30.0f)) + 0.5f + 0.1f, 0}),
                     0.1f, kY));
    {
        PairCase c = pairCase(Shape::cylinder(0.5f, 0.5f), origin, unitBox, place({0.9f, 0.1f, 0}), -0.1f, kX);
        c.tolerance = 2e-5f;  // EPA against the curved side: 1e-4 relative of 0.1 m
        c.normalTolerance = 1e-2f;
        addCase("cylinder-box side penetrating", c);
    }
    addCase("cylinder-box cap penetrating",
            pairCase(Shape::cylinder(0.5f, 0.5f), origin, unitBox, place({0.2f, 0.85f, 0.1f}), -0.15f, kY));

    // Hulls (built by Quickhull).
    addCase("hull-box vertex on face",
            pairCase(unitBox, origin, octahedron(0.5f), place({0.1f, 1.2f, 0}), 0.2f, kY));
    addCase("hull-box vertex penetrating",
            pairCase(unitBox, origin, octahedron(0.5f), place({0.1f, 0.9f, 0}), -0.1f, kY));
    {
        const Shape wedge = Shape::convexHull(
            buildHull({{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0, 0.5f, -0.5f}, {0, 0.5f, 0.5f}}));
        addCase("box-hull face-face penetrating",
                pairCase(wedge, origin, unitBox, place({0.1f, -0.45f, 0}), -0.05f, -kY));
    }

    // Very thin: a 1 mm plate against a unit box.
    {
        const Shape plate = Shape::box({0.4f, 0.0005f, 0.4f});
        addCase("thin plate above box", pairCase(unitBox, origin, plate, place({0.05f, 0.5f + 0.0005f + 0.0002f, 0}), 0.0002f, kY));
        addCase("thin plate half into box", pairCase(unitBox, origin, plate, place({0.05f, 0.5f, 0}), -0.0005f, kY));
        addCase("thin plate inside box", pairCase(unitBox, origin, plate, place({0.05f, 0.4996f, 0}), -0.0009f, kY));
        addCase("box on thin plate edge",
                pairCase(plate, origin, unitBox, place({0.5f + 0.4f - 0.0003f, 0, 0}), -0.0003f, kX));
    }

    // Very large: a 1 km box and a 10 cm sphere. Coordinates of 500-700 m: 8 ulps are 5e-4 m.
    {
        const Shape ground = Shape::box(Vec3(500.0f));
        addCase("1 km box, sphere above", pairCase(ground, origin, Shape::sphere(0.1f), place({12, 500.5f, -3}), 0.4f, kY, 2e-3f));
        addCase("1 km box, sphere penetrating",
                pairCase(ground, origin, Shape::sphere(0.1f), place({12, 500.05f, -3}), -0.05f, kY, 2e-3f));
        addCase("1 km box, sphere centre inside",
                pairCase(ground, origin, Shape::sphere(0.1f), place({12, 499.8f, -3}), -0.3f, kY, 2e-3f));
        addCase("1 km box, small box above",
                pairCase(ground, origin, Shape::box(Vec3(0.05f)), place({-40, 500.25f, 7}), 0.2f, kY, 2e-3f));
    }

    // Rotated configurations (beyond the moved copies every row gets).
    {
        const Quat tilt = rotation(20, kZ);
        // Turning both boxes about the contact normal keeps the faces parallel.
        addCase("rotated about contact normal",
                pairCase(unitBox, place({0, 0, 0}, rotation(33, kY)), unitBox, place({0.2f, 1.1f, 0}, rotation(-71, kY)), 0.1f, kY));
        // A's top edge after tilting by 20 degrees about z: highest corner at 0.5 (cos + sin).
        const float top = 0.5f * (std::cos(glm::radians(20.0f)) + std::sin(glm::radians(20.0f)));
        addCase("tilted box under flat box",
                pairCase(unitBox, place({0, 0, 0}, tilt), unitBox, place({0.0f, top + 0.5f + 0.05f, 0}), 0.05f, kY));
        addCase("tilted box corner into flat box",
                pairCase(unitBox, place({0, 0, 0}, tilt), unitBox, place({0.0f, top + 0.5f - 0.05f, 0}), -0.05f, kY));
    }
}

void TestGjkEpa::table() {
    QFETCH(PairCase, pair);
    const float tolerance = pair.tolerance + 1e-4f * std::abs(pair.expectedSigned);

    for (int swapped = 0; swapped < 2; ++swapped) {
        const Shape& a = swapped ? pair.b : pair.a;
        const Shape& b = swapped ? pair.a : pair.b;
        const Transform& ta = swapped ? pair.tb : pair.ta;
        const Transform& tb = swapped ? pair.ta : pair.tb;
        const Vec3 expectedNormal = swapped ? -pair.expectedNormal : pair.expectedNormal;
        const QString which = swapped ? "B,A: " : "A,B: ";

        const ContactQuery q = penetrationOrDistance(a, ta, b, tb);
        QVERIFY2(isFiniteQuery(q), qPrintable(which + "non-finite result"));
        QVERIFY2(std::abs(glm::length(q.normal) - 1.0f) < 1e-5f, qPrintable(which + "normal not unit"));
        QVERIFY2(std::abs(q.signedDistance() - pair.expectedSigned) <= tolerance,
                 qPrintable(which + QString("signed distance %1, expected %2").arg(q.signedDistance(), 0, 'g', 9).arg(pair.expectedSigned, 0, 'g', 9)));
        QCOMPARE(q.gjkStatus, GjkStatus::Converged);
        if (q.penetrating) QCOMPARE(q.epaStatus, EpaStatus::Converged);
        // Far below the caps (64 and 120): these are the easy cases.
        QVERIFY2(q.gjkIterations <= 16 && q.epaIterations <= 32,
                 qPrintable(which + QString("%1 GJK, %2 EPA iterations").arg(q.gjkIterations).arg(q.epaIterations)));
        if (glm::length(expectedNormal) > 0.0f) {
            const float error = pair.normalSignFree
                                    ? std::min(glm::length(q.normal - expectedNormal), glm::length(q.normal + expectedNormal))
                                    : glm::length(q.normal - expectedNormal);
            QVERIFY2(error <= pair.normalTolerance,
                     qPrintable(which + QString("normal (%1 %2 %3) off by %4").arg(q.normal.x).arg(q.normal.y).arg(q.normal.z).arg(error)));
        }

        // The two points are on the surfaces, and the supporting planes along the normal hold them.
        const float surfaceTolerance = tolerance + 1e-5f * std::max(sizeOf(a), sizeOf(b));
        QVERIFY2(std::abs(outsideBy(a, ta, q.pointA)) <= surfaceTolerance, qPrintable(which + "pointA off A's surface"));
        QVERIFY2(std::abs(outsideBy(b, tb, q.pointB)) <= surfaceTolerance, qPrintable(which + "pointB off B's surface"));
        QVERIFY2(std::abs(glm::dot(q.normal, q.pointA) - extentAlong(a, ta, q.normal)) <= surfaceTolerance,
                 qPrintable(which + "pointA not extreme along the normal"));
        QVERIFY2(std::abs(glm::dot(-q.normal, q.pointB) - extentAlong(b, tb, -q.normal)) <= surfaceTolerance,
                 qPrintable(which + "pointB not extreme against the normal"));
        QVERIFY2(glm::length((q.pointB - q.pointA) - q.signedDistance() * q.normal) <= surfaceTolerance,
                 qPrintable(which + "pointB - pointA is not signedDistance * normal"));

        // Penetrating: the shapes overlap along the normal by exactly the depth.
        if (q.penetrating) {
            const float along = overlapAlong(a, ta, b, tb, q.normal);
            QVERIFY2(std::abs(along - q.depth) <= surfaceTolerance,
                     qPrintable(which + QString("overlap along the normal %1, depth %2").arg(along).arg(q.depth)));
        }

        // GJK alone agrees.
        const GjkResult g = gjkDistance(a, ta, b, tb);
        QCOMPARE(g.status, GjkStatus::Converged);
        QCOMPARE(g.overlap, q.penetrating);
        QVERIFY(std::abs(g.distance - std::max(pair.expectedSigned, 0.0f)) <= tolerance);
        QVERIFY(isFinite(g.pointA) && isFinite(g.pointB) && isFinite(g.normal));
        QCOMPARE(gjkIntersect(a, ta, b, tb), g.overlap);

        // EPA entry point agrees.
        const EpaResult e = epaPenetration(a, ta, b, tb);
        if (q.penetrating) {
            QCOMPARE(e.status, EpaStatus::Converged);
            QVERIFY(std::abs(e.depth - q.depth) <= 1e-6f * (1.0f + q.depth));
        } else {
            QCOMPARE(e.status, EpaStatus::Separated);
        }

        // Moving B by the depth (a hair more / less) along the normal just separates / not yet.
        if (q.penetrating && q.depth > 10.0f * pair.tolerance) {
            Transform out = tb;
            out.position += (q.depth + 10.0f * pair.tolerance) * q.normal;
            QVERIFY2(!gjkDistance(a, ta, b, out).overlap, qPrintable(which + "depth + margin does not separate"));
            Transform in = tb;
            in.position += (q.depth - 10.0f * pair.tolerance) * q.normal;
            QVERIFY2(gjkDistance(a, ta, b, in).overlap, qPrintable(which + "depth - margin already separates"));
        }
    }
}

// ---- Scale sweep ---------------------------------------------------------------------------------

void TestGjkEpa::scaleSweep_data() {
    QTest::addColumn<int>("configuration");
    QTest::addColumn<float>("scale");
    const char* names[] = {"box-box edge-edge gap", "box-box penetrating", "sphere-box deep", "capsule-cylinder gap",
                           "hull-box penetrating", "capsule-capsule penetrating"};
    for (int c = 0; c < 6; ++c) {
        for (float s : {1e-3f, 1e-2f, 1e-1f, 1.0f, 1e1f, 1e2f, 1e3f}) {
            QTest::newRow(qPrintable(QString("%1 x%2").arg(names[c]).arg(double(s)))) << c << s;
        }
    }
}

namespace {

struct Scene {
    Shape a;
    Transform ta;
    Shape b;
    Transform tb;
};

Scene sweepScene(int configuration) {
    const Shape unitBox = Shape::box(Vec3(0.5f));
    const Quat q1 = rotation(27, {1, 2, 0.5f});
    const Quat q2 = rotation(-52, {0.3f, 1, -2});
    switch (configuration) {
        case 0: return {unitBox, place({0.1f, 0.2f, 0.3f}, q1), Shape::box({0.3f, 0.6f, 0.2f}), place({1.1f, 1.2f, 0.4f}, q2)};
        case 1: return {unitBox, place({0.1f, 0.2f, 0.3f}, q1), Shape::box({0.3f, 0.6f, 0.2f}), place({0.6f, 0.7f, 0.4f}, q2)};
        case 2: return {Shape::box({1.0f, 0.4f, 0.7f}), place({0, 0, 0}, q1), Shape::sphere(0.3f), place(q1 * Vec3(0.5f, 0.1f, -0.2f))};
        case 3: return {Shape::capsule(0.2f, 0.6f), place({0, 0, 0}, q2), Shape::cylinder(0.4f, 0.3f), place({0.9f, 0.3f, 0.2f}, q1)};
        case 4:
            return {Shape::convexHull(buildHull({{0.5f, 0.1f, 0.0f}, {-0.4f, 0.3f, 0.2f}, {0.1f, -0.5f, 0.3f}, {0.0f, 0.2f, -0.6f},
                                                 {0.3f, 0.4f, 0.4f}, {-0.2f, -0.3f, -0.3f}})),
                    place({0, 0, 0}, q2), unitBox, place({0.5f, 0.6f, 0.1f}, q1)};
        default: return {Shape::capsule(0.25f, 0.5f), place({0, 0, 0}, q1), Shape::capsule(0.2f, 0.3f), place({0.3f, 0.1f, 0.2f}, q2)};
    }
}

Scene scaledScene(const Scene& s, float k) {
    // The scene sits 2 units from the world origin at every scale, so coordinates scale too.
    const Vec3 offset(2.0f, -1.0f, 1.0f);
    return {scaled(s.a, k), place((s.ta.position + offset) * k, s.ta.rotation), scaled(s.b, k),
            place((s.tb.position + offset) * k, s.tb.rotation)};
}

}  // namespace

void TestGjkEpa::scaleSweep() {
    QFETCH(int, configuration);
    QFETCH(float, scale);
    const Scene base = sweepScene(configuration);
    const Scene unit = scaledScene(base, 1.0f);
    const Scene big = scaledScene(base, scale);
    const ContactQuery reference = penetrationOrDistance(unit.a, unit.ta, unit.b, unit.tb);
    const ContactQuery q = penetrationOrDistance(big.a, big.ta, big.b, big.tb);
    QVERIFY(isFiniteQuery(q));
    QCOMPARE(q.gjkStatus, GjkStatus::Converged);
    if (q.penetrating) QCOMPARE(q.epaStatus, EpaStatus::Converged);
    QCOMPARE(q.penetrating, reference.penetrating);
    // Both runs resolve to ~1e-4 relative (EPA) and a few ulps of the coordinates; the scaled copy
    // is the same float problem up to the rounding of the scaled inputs.
    const float expected = reference.signedDistance() * scale;
    QVERIFY2(std::abs(q.signedDistance() - expected) <= 2e-4f * std::abs(expected) + 4e-6f * scale,
             qPrintable(QString("%1 vs %2").arg(q.signedDistance(), 0, 'g', 9).arg(expected, 0, 'g', 9)));
    QVERIFY(glm::length(q.normal - reference.normal) <= 1e-3f);
    QVERIFY(glm::length(q.pointA / scale - reference.pointA) <= 1e-3f);
}

// ---- Fuzz ----------------------------------------------------------------------------------------

namespace {

Quat randomRotation(std::mt19937& rng) {
    std::normal_distribution<float> n;
    const Quat q(n(rng), n(rng), n(rng), n(rng));
    return glm::normalize(q);
}

Shape randomShape(std::mt19937& rng) {
    std::uniform_real_distribution<float> size(0.05f, 1.0f);
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: return Shape::sphere(size(rng));
        case 1: return Shape::box({size(rng), size(rng), size(rng)});
        case 2: return Shape::capsule(size(rng), size(rng));
        case 3: return Shape::cylinder(size(rng), size(rng));
        default: {
            std::vector<Vec3> points;
            const Vec3 extent(size(rng), size(rng), size(rng));
            std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
            const int count = std::uniform_int_distribution<int>(6, 24)(rng);
            for (int i = 0; i < count; ++i) points.push_back(Vec3(unit(rng), unit(rng), unit(rng)) * extent);
            auto built = ConvexHull::build(points);
            return built.hull ? Shape::convexHull(built.hull) : Shape::box(extent);
        }
    }
}

// GJK_EPA_FUZZ_PAIRS / GJK_EPA_FUZZ_SEED widen the search when hunting for rare failures.
int fuzzPairs(int standard) {
    return qEnvironmentVariableIsSet("GJK_EPA_FUZZ_PAIRS") ? qEnvironmentVariableIntValue("GJK_EPA_FUZZ_PAIRS") : standard;
}
void seedFromEnvironment(std::mt19937& rng) {
    if (qEnvironmentVariableIsSet("GJK_EPA_FUZZ_SEED")) rng.seed(std::uint32_t(qEnvironmentVariableIntValue("GJK_EPA_FUZZ_SEED")));
}

std::vector<Vec3> sampleDirections(int count) {
    // Fibonacci sphere: evenly spread, deterministic.
    std::vector<Vec3> directions;
    const float golden = kPi * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(count);
        const float r = std::sqrt(1.0f - y * y);
        directions.emplace_back(r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i)));
    }
    return directions;
}

}  // namespace

namespace {

struct FuzzPair {
    Shape a;
    Transform ta;
    Shape b;
    Transform tb;
};

// Unit-sized shapes (5 cm to 2 m) within 8 m of the origin, B within 1.5 m of A.
FuzzPair unitPair(std::mt19937& rng) {
    std::uniform_real_distribution<float> offset(-1.5f, 1.5f);
    std::uniform_real_distribution<float> place5(-5.0f, 5.0f);
    FuzzPair p;
    p.a = randomShape(rng);
    p.b = randomShape(rng);
    p.ta = place({place5(rng), place5(rng), place5(rng)}, randomRotation(rng));
    p.tb = place(p.ta.position + Vec3(offset(rng), offset(rng), offset(rng)), randomRotation(rng));
    return p;
}

// The same at a random scale from 1 cm to 100 m, with each dimension shrunk by up to 30 times
// (plates, needles, discs), the pair up to 5 scale units from the origin and B within 0.6 of A.
FuzzPair extremePair(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float scale = std::pow(10.0f, 2.0f * unit(rng));
    const auto squash = [&] { return scale * std::pow(30.0f, -0.5f * (unit(rng) + 1.0f)); };
    const auto shape = [&] {
        const Shape s = randomShape(rng);
        switch (s.type) {
            case ShapeType::Sphere: return Shape::sphere(squash());
            case ShapeType::Box: return Shape::box({squash(), squash(), squash()});
            case ShapeType::Capsule: return Shape::capsule(squash(), squash());
            case ShapeType::Cylinder: return Shape::cylinder(squash(), squash());
            case ShapeType::ConvexHull: return scaled(s, squash());
            case ShapeType::Compound:
            case ShapeType::Mesh:
            case ShapeType::HeightField: break;  // randomShape makes convex shapes only
        }
        return s;
    };
    FuzzPair p;
    p.a = shape();
    p.b = shape();
    p.ta = place(5.0f * scale * Vec3(unit(rng), unit(rng), unit(rng)), randomRotation(rng));
    p.tb = place(p.ta.position + 0.6f * scale * Vec3(unit(rng), unit(rng), unit(rng)), randomRotation(rng));
    return p;
}

struct FuzzStats {
    int separated = 0, penetrating = 0, epaRuns = 0;
    long gjkIterationSum = 0, epaIterationSum = 0;
    int gjkIterationMax = 0, epaIterationMax = 0;
    int gjkNotConverged = 0, epaNotConverged = 0;
    float worstSeparated = 0.0f, worstPenetrating = 0.0f;  // relative to each pair's tolerance
};

// Checks one query against its certificate (see the top of the file). `margin` is the push, beyond
// the depth, that must separate the shapes.
void checkFuzzPair(const FuzzPair& p, int index, const std::vector<Vec3>& directions, float margin, FuzzStats& stats) {
    const Shape& a = p.a;
    const Shape& b = p.b;
    const Transform& ta = p.ta;
    const Transform& tb = p.tb;
    const float size = std::max(sizeOf(a), sizeOf(b));
    const QString where = QString("pair %1 (%2, %3)").arg(index).arg(shapeTypeName(a.type).data()).arg(shapeTypeName(b.type).data());

    const ContactQuery q = penetrationOrDistance(a, ta, b, tb);
    QVERIFY2(isFiniteQuery(q), qPrintable(where + ": non-finite"));
    QVERIFY2(q.distance >= 0.0f && q.depth >= 0.0f, qPrintable(where));
    QVERIFY2(std::abs(glm::length(q.normal) - 1.0f) < 1e-5f, qPrintable(where + ": normal not unit"));
    stats.gjkIterationSum += q.gjkIterations;
    stats.gjkIterationMax = std::max(stats.gjkIterationMax, q.gjkIterations);
    if (q.gjkStatus != GjkStatus::Converged) ++stats.gjkNotConverged;

    // GJK and EPA resolve to 8 float ulps of the coordinates (1e-6 relative; 2e-6 allowed here),
    // and EPA depths to 1e-4 relative on curved sides (2e-4 allowed).
    const float coordinates = std::max(glm::length(ta.position), glm::length(tb.position)) + size;
    const float tolerance = 2e-6f * coordinates + 2e-4f * q.depth;
    if (!q.penetrating) {
        ++stats.separated;
        // Certificate of the gap: points in their shapes, on the separating planes, distance apart.
        const float errors[] = {
            outsideBy(a, ta, q.pointA),
            outsideBy(b, tb, q.pointB),
            std::abs(glm::dot(q.normal, q.pointA) - extentAlong(a, ta, q.normal)),
            std::abs(glm::dot(-q.normal, q.pointB) - extentAlong(b, tb, -q.normal)),
            glm::length(q.pointB - q.pointA - q.distance * q.normal),
        };
        for (float e : errors) {
            stats.worstSeparated = std::max(stats.worstSeparated, e / tolerance);
            QVERIFY2(e <= tolerance, qPrintable(where + QString(": separated certificate off by %1").arg(e)));
        }
        return;
    }
    ++stats.penetrating;
    if (q.epaUsed) {
        ++stats.epaRuns;
        stats.epaIterationSum += q.epaIterations;
        stats.epaIterationMax = std::max(stats.epaIterationMax, q.epaIterations);
    }
    if (q.epaStatus != EpaStatus::Converged) ++stats.epaNotConverged;
    // The shapes overlap along the normal by exactly the depth...
    const float along = overlapAlong(a, ta, b, tb, q.normal);
    stats.worstPenetrating = std::max(stats.worstPenetrating, std::abs(along - q.depth) / tolerance);
    QVERIFY2(std::abs(along - q.depth) <= tolerance,
             qPrintable(where + QString(": overlap along normal %1, depth %2").arg(along).arg(q.depth)));
    // ...and no other direction separates with less.
    float leastOverlap = std::numeric_limits<float>::infinity();
    for (const Vec3& d : directions) leastOverlap = std::min(leastOverlap, overlapAlong(a, ta, b, tb, d));
    QVERIFY2(leastOverlap >= q.depth - tolerance,
             qPrintable(where + QString(": direction with overlap %1 < depth %2").arg(leastOverlap).arg(q.depth)));
    QVERIFY2(outsideBy(a, ta, q.pointA) <= tolerance && outsideBy(b, tb, q.pointB) <= tolerance,
             qPrintable(where + QString(": deepest points outside their shapes by %1, %2 (tolerance %3)").arg(outsideBy(a, ta, q.pointA)).arg(outsideBy(b, tb, q.pointB)).arg(tolerance)));
    // Moving B by a margin more than the depth separates; by 0.1% less does not.
    Transform out = tb;
    out.position += (q.depth + margin) * q.normal;
    QVERIFY2(!gjkDistance(a, ta, b, out).overlap, qPrintable(where + ": depth + margin does not separate"));
    if (q.depth > margin) {
        Transform in = tb;
        in.position += q.depth * (1.0f - 1e-3f) * q.normal;
        QVERIFY2(gjkDistance(a, ta, b, in).overlap, qPrintable(where + ": 0.999 depth separates"));
    }
}

void reportFuzz(const char* name, const FuzzStats& s, int pairs) {
    qInfo("%s: %d separated, %d penetrating (%d through EPA); GJK iterations mean %.2f max %d; "
          "EPA iterations mean %.2f max %d; worst certificate error %.2f (separated), %.2f (penetrating) "
          "of the tolerance",
          name, s.separated, s.penetrating, s.epaRuns, double(s.gjkIterationSum) / pairs, s.gjkIterationMax,
          s.epaRuns ? double(s.epaIterationSum) / s.epaRuns : 0.0, s.epaIterationMax, double(s.worstSeparated),
          double(s.worstPenetrating));
}

}  // namespace

void TestGjkEpa::fuzz() {
    std::mt19937 rng(20240611u);
    seedFromEnvironment(rng);
    const std::vector<Vec3> directions = sampleDirections(400);
    const int pairs = fuzzPairs(5000);
    FuzzStats stats;
    for (int i = 0; i < pairs; ++i) {
        checkFuzzPair(unitPair(rng), i, directions, 1e-3f, stats);
        if (QTest::currentTestFailed()) return;
    }
    reportFuzz("fuzz", stats, pairs);
    QCOMPARE(stats.gjkNotConverged, 0);
    QCOMPARE(stats.epaNotConverged, 0);
    QVERIFY(stats.separated > pairs / 5 && stats.penetrating > pairs / 5);
}

void TestGjkEpa::fuzzExtremeShapes() {
    std::mt19937 rng(424242u);
    seedFromEnvironment(rng);
    const std::vector<Vec3> directions = sampleDirections(400);
    const int pairs = fuzzPairs(5000) * 2 / 5;
    FuzzStats stats;
    for (int i = 0; i < pairs; ++i) {
        const FuzzPair p = extremePair(rng);
        // A thousandth of the pair's size, like the millimetre of the unit fuzz.
        checkFuzzPair(p, i, directions, 1e-3f * std::max(sizeOf(p.a), sizeOf(p.b)), stats);
        if (QTest::currentTestFailed()) return;
    }
    reportFuzz("extreme fuzz", stats, pairs);
    QCOMPARE(stats.gjkNotConverged, 0);
    QCOMPARE(stats.epaNotConverged, 0);
}

// Random pairs moved along their normal to just apart, touching and just overlapping: the hardest
// inputs for both algorithms (the origin on or next to C's surface).
void TestGjkEpa::nearContactFuzz() {
    std::mt19937 rng(99u);
    seedFromEnvironment(rng);
    std::uniform_real_distribution<float> offset(-1.5f, 1.5f);
    std::uniform_real_distribution<float> place5(-5.0f, 5.0f);
    const int pairs = fuzzPairs(5000) * 2 / 5;
    int checked = 0;
    for (int i = 0; i < pairs; ++i) {
        const Shape a = randomShape(rng);
        const Shape b = randomShape(rng);
        const Transform ta = place({place5(rng), place5(rng), place5(rng)}, randomRotation(rng));
        const Transform tb = place(ta.position + Vec3(offset(rng), offset(rng), offset(rng)), randomRotation(rng));
        const ContactQuery q = penetrationOrDistance(a, ta, b, tb);
        const float d = q.signedDistance();
        // Error of the first answer, carried into the moved configuration (see fuzz()).
        const float tolerance = 2.0f * (2e-5f + 2e-4f * std::max(q.depth, 0.0f));
        for (const float target : {1e-2f, 1e-4f, 1e-6f, 0.0f, -1e-6f, -1e-4f, -1e-2f}) {
            // Along the normal the signed distance changes one for one while the shapes are apart,
            // and while backing out of a penetration (the deepest points stay the deepest). Pushed
            // deeper than before, all that is certain is |signed distance| <= the push: another
            // direction may become cheaper, and sharp vertices of C = A - B may even slip past
            // each other and stay apart.
            const bool exact = target >= 0.0f || target >= d;
            Transform moved = tb;
            moved.position += (target - d) * q.normal;
            const ContactQuery m = penetrationOrDistance(a, ta, b, moved);
            const QString where = QString("pair %1 (%2, %3), target %4").arg(i).arg(shapeTypeName(a.type).data())
                                      .arg(shapeTypeName(b.type).data()).arg(double(target));
            QVERIFY2(isFiniteQuery(m), qPrintable(where));
            QCOMPARE(m.gjkStatus, GjkStatus::Converged);
            if (m.penetrating) QVERIFY2(m.epaStatus == EpaStatus::Converged, qPrintable(where));
            const bool expected = exact ? std::abs(m.signedDistance() - target) <= tolerance
                                        : std::abs(m.signedDistance()) <= -target + tolerance;
            QVERIFY2(expected, qPrintable(where + QString(": signed distance %1").arg(double(m.signedDistance()), 0, 'g', 6)));
            // The reported normal really separates (or overlaps) the shapes by the reported amount.
            // (It need not equal the first normal: near contact, a vertex-like feature of C makes
            // the direction sensitive to the last ulps of the closest points.)
            const float along = overlapAlong(a, ta, b, moved, m.normal);
            QVERIFY2(std::abs(along + m.signedDistance()) <= tolerance,
                     qPrintable(where + QString(": overlap %1 along the normal").arg(double(along))));
            if (target > tolerance) QVERIFY2(!m.penetrating, qPrintable(where));
            if (target < -tolerance && exact) QVERIFY2(m.penetrating, qPrintable(where));
            ++checked;
        }
    }
    QCOMPARE(checked, 7 * pairs);
}

// ---- Cache, boolean query, allocation, bad input -------------------------------------------------

void TestGjkEpa::warmStartCache() {
    // A box sliding and turning past a hull: the cached simplex from the previous frame must give
    // the same answers as a cold start, in no more iterations overall.
    const Shape hull = octahedron(0.6f);
    const Shape box = Shape::box({0.4f, 0.2f, 0.3f});
    GjkCache cache;
    int coldIterations = 0, warmIterations = 0;
    for (int frame = 0; frame < 200; ++frame) {
        const float t = float(frame) / 200.0f;
        const Transform ta = place({0, 0, 0}, rotation(10.0f * t, kY));
        const Transform tb = place({-2.0f + 4.0f * t, 0.7f - 0.5f * std::sin(3.0f * t), 0.1f}, rotation(90.0f * t, {1, 1, 0}));
        const GjkResult cold = gjkDistance(hull, ta, box, tb);
        const GjkResult warm = gjkDistance(hull, ta, box, tb, &cache);
        QCOMPARE(warm.status, GjkStatus::Converged);
        QCOMPARE(warm.overlap, cold.overlap);
        QVERIFY(std::abs(warm.distance - cold.distance) <= 1e-5f);
        const ContactQuery warmQuery = penetrationOrDistance(hull, ta, box, tb, &cache);
        const ContactQuery coldQuery = penetrationOrDistance(hull, ta, box, tb);
        QVERIFY(std::abs(warmQuery.signedDistance() - coldQuery.signedDistance()) <= 1e-4f);
        coldIterations += cold.iterations;
        warmIterations += warm.iterations;
    }
    qInfo("cache: %d iterations cold, %d warm over 200 frames", coldIterations, warmIterations);
    QVERIFY(warmIterations <= coldIterations);
}

void TestGjkEpa::intersectMatchesDistance() {
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> offset(-1.5f, 1.5f);
    for (int i = 0; i < 2000; ++i) {
        const Shape a = randomShape(rng);
        const Shape b = randomShape(rng);
        const Transform ta = place({0, 0, 0}, randomRotation(rng));
        const Transform tb = place({offset(rng), offset(rng), offset(rng)}, randomRotation(rng));
        const GjkResult g = gjkDistance(a, ta, b, tb);
        QCOMPARE(gjkIntersect(a, ta, b, tb), g.overlap);
    }
}

void TestGjkEpa::noHeapAllocation() {
    const Shape hull = octahedron(0.5f);
    const Shape box = Shape::box({0.5f, 0.3f, 0.4f});
    const Shape cylinder = Shape::cylinder(0.4f, 0.5f);
    const Shape capsule = Shape::capsule(0.3f, 0.4f);
    const Transform ta = place({0, 0, 0}, rotation(20, {1, 0, 1}));
    GjkCache cache;
    test_support::startCountingAllocations();
    float sink = 0.0f;
    for (float x = -1.5f; x <= 1.5f; x += 0.05f) {
        const Transform tb = place({x, 0.3f, -0.1f}, rotation(40.0f * x, {0, 1, 1}));
        sink += penetrationOrDistance(hull, ta, box, tb, &cache).signedDistance();
        sink += penetrationOrDistance(cylinder, ta, box, tb).signedDistance();
        sink += penetrationOrDistance(capsule, ta, cylinder, tb).signedDistance();
        sink += epaPenetration(box, ta, box, tb).depth;
        sink += gjkIntersect(capsule, ta, hull, tb) ? 1.0f : 0.0f;
    }
    const std::size_t allocations = test_support::stopCountingAllocations();
    QVERIFY(isFinite(sink));
    QCOMPARE(allocations, std::size_t(0));
}

void TestGjkEpa::nonFiniteInputGivesFiniteResult() {
    const Shape box = Shape::box(Vec3(0.5f));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Transform bad = place({nan, 0, 0});
    const GjkResult g = gjkDistance(box, place({0, 0, 0}), box, bad);
    QCOMPARE(g.status, GjkStatus::Degenerate);
    QVERIFY(isFinite(g.distance) && isFinite(g.normal) && isFinite(g.pointA) && isFinite(g.pointB));
    const ContactQuery q = penetrationOrDistance(box, place({0, 0, 0}), box, bad);
    QVERIFY(isFiniteQuery(q));
    QCOMPARE(q.gjkStatus, GjkStatus::Degenerate);
}

QTEST_APPLESS_MAIN(TestGjkEpa)
#include "test_gjk_epa.moc"
