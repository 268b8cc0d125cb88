// Contact manifolds (collideShapes).
//
// One table of hand-computed configurations, one row per pair type and situation (resting,
// penetrating by 1 cm, speculative gap, beyond the speculative distance, coincident). Every row is
// checked for: point count, normal (unit, expected direction), deepest separation (analytic,
// within 1e-4 m), expected points on A where they are known, area spanned by the points where the
// reduction matters, and invariants: separation == dot(pointB - pointA, normal), no point beyond
// the speculative distance, points on A's surface, nothing non-finite. Each row is also run with A
// and B swapped: same points, same separations, flipped normal.

#include "support/allocation_counter.h"
#include "support/geometry.h"
#include "simcore/collision/collide_shapes.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/shape.h"

#include "simcore/collision/epa.h"

#include <QtTest>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <vector>

using namespace simcore;
using namespace test_support;

namespace {

constexpr float kSeparationTolerance = 1e-4f;  // m
constexpr float kPointTolerance = 1e-4f;       // m

// Area of the convex polygon through the points, in the plane perpendicular to `normal`.
float spannedArea(const std::vector<Vec3>& points, const Vec3& normal) {
    if (points.size() < 3) return 0.0f;
    Vec3 centre(0.0f);
    for (const Vec3& p : points) centre += p;
    centre /= float(points.size());
    const Vec3 u = glm::normalize(glm::abs(normal.x) < 0.57f ? glm::cross(normal, Vec3(1, 0, 0)) : glm::cross(normal, Vec3(0, 1, 0)));
    const Vec3 v = glm::cross(normal, u);
    std::vector<std::pair<float, Vec3>> byAngle;
    for (const Vec3& p : points) byAngle.emplace_back(std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)), p);
    std::sort(byAngle.begin(), byAngle.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    float area = 0.0f;
    for (std::size_t i = 0; i < byAngle.size(); ++i) {
        const Vec3& p = byAngle[i].second;
        const Vec3& q = byAngle[(i + 1) % byAngle.size()].second;
        area += glm::dot(glm::cross(p - centre, q - centre), normal);
    }
    return 0.5f * std::abs(area);
}

struct Case {
    const char* name;
    Shape a;
    Transform ta;
    Shape b;
    Transform tb;
    float speculative = 0.02f;
    int minPoints = 0;
    int maxPoints = 0;
    bool checkNormal = true;  // false for coincident shapes, where any unit normal is right
    Vec3 normal{0.0f, 1.0f, 0.0f};
    float separation = 0.0f;  // of the deepest point
    bool allSameSeparation = false;
    std::vector<Vec3> pointsA{};  // expected points on A (each must be in the manifold); empty: not checked
    float minArea = 0.0f;         // area the points must span
};

std::vector<Case> makeCases() {
    const Shape ground = Shape::box(Vec3(2.0f, 0.5f, 2.0f));
    const Shape smallGround = Shape::box(Vec3(1.0f, 0.5f, 1.0f));
    const Shape unitBox = Shape::box(Vec3(0.5f));
    const Shape unitHull = boxHull(Vec3(0.5f));
    const Shape groundHull = boxHull(Vec3(2.0f, 0.5f, 2.0f));
    const Shape ball = Shape::sphere(0.5f);
        const Shape lyingCapsule = Shape::capsule(0.25f, 0.5f);
    const Shape longCapsule = Shape::capsule(0.2f, 1.0f);
    const Shape cylinder = Shape::cylinder(0.5f, 0.5f);
    const Transform at0 = place(Vec3(0.0f));
    const Quat alongX = rotation(90.0f, Vec3(0, 0, 1));  // capsule/cylinder axis (local Y) onto X
    const Quat alongZ = rotation(90.0f, Vec3(1, 0, 0));
    const float s2 = std::sqrt(2.0f);
    const float s3 = std::sqrt(3.0f);
    const std::vector<Vec3> topCorners{{-0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}};

    std::vector<Case> cases;
    // Boxes.
    cases.push_back({"box on box, touching", ground, at0, unitBox, place(Vec3(0, 1.0f, 0)), 0.02f, 4, 4, true,
                     Vec3(0, 1, 0), 0.0f, true, topCorners});
    cases.push_back({"box on box, 1 cm deep", ground, at0, unitBox, place(Vec3(0, 0.99f, 0)), 0.02f, 4, 4, true,
                     Vec3(0, 1, 0), -0.01f, true, topCorners});
    cases.push_back({"box above box, speculative gap", ground, at0, unitBox, place(Vec3(0, 1.05f, 0)), 0.1f, 4, 4,
                     true, Vec3(0, 1, 0), 0.05f, true, topCorners});
    cases.push_back({"box above box, beyond speculative", ground, at0, unitBox, place(Vec3(0, 1.2f, 0)), 0.1f, 0, 0});
    cases.push_back({"box rotated 45 about Y on box: octagon reduced to 4", unitBox, at0, unitBox,
                     place(Vec3(0, 0.99f, 0), rotation(45.0f, Vec3(0, 1, 0))), 0.02f, 4, 4, true, Vec3(0, 1, 0),
                     -0.01f, true, {}, 0.585f});
    cases.push_back({"box on its edge", ground, at0, unitBox,
                     place(Vec3(0, 0.5f + 0.5f * s2 - 0.01f, 0), rotation(45.0f, Vec3(0, 0, 1))), 0.02f, 2, 2, true,
                     Vec3(0, 1, 0), -0.01f, true, {{0, 0.5f, -0.5f}, {0, 0.5f, 0.5f}}});
    cases.push_back({"box on its corner", ground, at0, unitBox,
                     place(Vec3(0, 0.5f + 0.5f * s3 - 0.01f, 0), rotationBetween(Vec3(1, 1, 1), Vec3(0, -1, 0))),
                     0.02f, 1, 1, true, Vec3(0, 1, 0), -0.01f, true, {{0, 0.5f, 0}}});
    cases.push_back({"box edge across box edge", unitBox, place(Vec3(0), rotation(45.0f, Vec3(0, 0, 1))), unitBox,
                     place(Vec3(0, s2 - 0.01f, 0), rotation(45.0f, Vec3(1, 0, 0))), 0.02f, 1, 1, true, Vec3(0, 1, 0),
                     -0.01f, true, {{0, 0.5f * s2, 0}}});
    cases.push_back({"coincident boxes", unitBox, at0, unitBox, at0, 0.02f, 1, 4, false, Vec3(0), -1.0f, true});
    // Spheres.
    cases.push_back({"sphere on box face", smallGround, at0, ball, place(Vec3(0, 0.99f, 0)), 0.02f, 1, 1, true,
                     Vec3(0, 1, 0), -0.01f, true, {{0, 0.5f, 0}}});
    cases.push_back({"sphere on box edge", smallGround, at0, ball,
                     place(Vec3(1, 0.5f, 0) + 0.49f * glm::normalize(Vec3(1, 1, 0))), 0.02f, 1, 1, true,
                     glm::normalize(Vec3(1, 1, 0)), -0.01f, true, {{1, 0.5f, 0}}});
    cases.push_back({"sphere on box corner", smallGround, at0, ball,
                     place(Vec3(1, 0.5f, 1) + 0.49f * glm::normalize(Vec3(1, 1, 1))), 0.02f, 1, 1, true,
                     glm::normalize(Vec3(1, 1, 1)), -0.01f, true, {{1, 0.5f, 1}}});
    cases.push_back({"sphere centre inside box", smallGround, at0, ball, place(Vec3(0.8f, 0.2f, 0)), 0.02f, 1, 1,
                     true, Vec3(1, 0, 0), -0.7f, true, {{1, 0.2f, 0}}});
    cases.push_back({"sphere-sphere overlap", ball, at0, Shape::sphere(0.3f), place(Vec3(0.7f, 0, 0)), 0.02f, 1, 1,
                     true, Vec3(1, 0, 0), -0.1f, true, {{0.5f, 0, 0}}});
    cases.push_back({"sphere-sphere speculative gap", ball, at0, Shape::sphere(0.3f), place(Vec3(0.85f, 0, 0)), 0.1f,
                     1, 1, true, Vec3(1, 0, 0), 0.05f, true, {{0.5f, 0, 0}}});
    cases.push_back({"sphere-sphere beyond speculative", ball, at0, Shape::sphere(0.3f), place(Vec3(1.0f, 0, 0)),
                     0.1f, 0, 0});
    cases.push_back({"coincident spheres", ball, at0, ball, at0, 0.02f, 1, 1, false, Vec3(0), -1.0f, true});
    // Capsules.
    cases.push_back({"capsule lying on box", ground, at0, lyingCapsule, place(Vec3(0, 0.74f, 0), alongX), 0.02f, 2, 2,
                     true, Vec3(0, 1, 0), -0.01f, true, {{-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}}});
    cases.push_back({"capsules crossed", longCapsule, place(Vec3(0), alongX), longCapsule,
                     place(Vec3(0, 0.39f, 0), alongZ), 0.02f, 1, 1, true, Vec3(0, 1, 0), -0.01f, true,
                     {{0, 0.2f, 0}}});
    cases.push_back({"capsules parallel", longCapsule, place(Vec3(0), alongX), longCapsule,
                     place(Vec3(0.5f, 0.39f, 0), alongX), 0.02f, 2, 2, true, Vec3(0, 1, 0), -0.01f, true,
                     {{-0.5f, 0.2f, 0}, {1.0f, 0.2f, 0}}});
    cases.push_back({"sphere on capsule", longCapsule, place(Vec3(0), alongX), Shape::sphere(0.3f),
                     place(Vec3(0.3f, 0.49f, 0)), 0.02f, 1, 1, true, Vec3(0, 1, 0), -0.01f, true, {{0.3f, 0.2f, 0}}});
    cases.push_back({"capsule lying on hull", groundHull, at0, lyingCapsule, place(Vec3(0, 0.74f, 0), alongX), 0.02f, 2,
                     2, true, Vec3(0, 1, 0), -0.01f, true, {{-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}}});
    // Hulls.
    cases.push_back({"box-shaped hull on box", ground, at0, unitHull, place(Vec3(0, 0.99f, 0)), 0.02f, 4, 4, true,
                     Vec3(0, 1, 0), -0.01f, true, topCorners});
    cases.push_back({"box on box-shaped hull", groundHull, at0, unitBox, place(Vec3(0, 0.99f, 0)), 0.02f, 4, 4, true,
                     Vec3(0, 1, 0), -0.01f, true, topCorners});
    cases.push_back({"hull rotated 45 about Y on hull", unitHull, at0, unitHull,
                     place(Vec3(0, 0.99f, 0), rotation(45.0f, Vec3(0, 1, 0))), 0.02f, 4, 4, true, Vec3(0, 1, 0),
                     -0.01f, true, {}, 0.585f});
    cases.push_back({"hull on its edge on hull", groundHull, at0, unitHull,
                     place(Vec3(0, 0.5f + 0.5f * s2 - 0.01f, 0), rotation(45.0f, Vec3(0, 0, 1))), 0.02f, 2, 2, true,
                     Vec3(0, 1, 0), -0.01f, true, {{0, 0.5f, -0.5f}, {0, 0.5f, 0.5f}}});
    // Cylinders.
    cases.push_back({"cylinder standing on box", ground, at0, cylinder, place(Vec3(0, 0.99f, 0)), 0.02f, 3, 4, true,
                     Vec3(0, 1, 0), -0.01f, true, {}, 0.45f});
    cases.push_back({"cylinder standing on hull", groundHull, at0, cylinder, place(Vec3(0, 0.99f, 0)), 0.02f, 3, 4,
                     true, Vec3(0, 1, 0), -0.01f, true, {}, 0.45f});
    cases.push_back({"cylinder lying on box", ground, at0, cylinder, place(Vec3(0, 0.99f, 0), alongX), 0.02f, 2, 2,
                     true, Vec3(0, 1, 0), -0.01f, true, {{-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}}});
    cases.push_back({"cylinder standing on cylinder", cylinder, at0, Shape::cylinder(0.3f, 0.2f),
                     place(Vec3(0.1f, 0.69f, 0)), 0.02f, 3, 4, true, Vec3(0, 1, 0), -0.01f, true, {}, 0.15f});
    cases.push_back({"sphere on cylinder", cylinder, at0, ball, place(Vec3(0, 0.99f, 0)), 0.02f, 1, 1, true,
                     Vec3(0, 1, 0), -0.01f, true, {{0, 0.5f, 0}}});
    return cases;
}

const std::vector<Case>& cases() {
    static const std::vector<Case> all = makeCases();
    return all;
}

}  // namespace

class TestCollideShapes : public QObject {
    Q_OBJECT

private:
    // Invariants every manifold must satisfy.
    static void checkInvariants(const ContactManifold& m, const Shape& a, const Transform& ta, float speculative) {
        QVERIFY(isFinite(m.normal));
        QVERIFY2(std::abs(glm::length(m.normal) - 1.0f) < 1e-4f, "normal not unit");
        QVERIFY(m.pointCount >= 0 && m.pointCount <= kMaxManifoldPoints);
        for (int i = 0; i < m.pointCount; ++i) {
            const ContactPoint& p = m.points[i];
            QVERIFY(isFinite(p.pointA) && isFinite(p.pointB) && isFinite(p.separation));
            QVERIFY2(p.separation <= speculative + 1e-5f, "point beyond the speculative distance");
            QVERIFY2(std::abs(glm::dot(p.pointB - p.pointA, m.normal) - p.separation) < kSeparationTolerance,
                     "separation is not dot(pointB - pointA, normal)");
            // A capsule lying on a face (up to ~6 degrees of tilt) gets its segment points pushed out
            // by the radius along the face normal, which sits up to 0.5% of the radius inside it.
            const float inside = a.type == ShapeType::Capsule ? 1e-3f + 0.006f * a.radius : 1e-3f;
            const float outside = outsideBy(a, ta, p.pointA);
            QVERIFY2(outside < 1e-3f && outside > -inside, qPrintable(QStringLiteral("pointA %1 from A's surface").arg(outside)));
        }
    }

private slots:
    void pairs_data() {
        QTest::addColumn<int>("index");
        for (std::size_t i = 0; i < cases().size(); ++i) QTest::newRow(cases()[i].name) << int(i);
    }

    void pairs() {
        QFETCH(int, index);
        const Case& c = cases()[std::size_t(index)];

        ContactManifold m;
        const bool touching = collideShapes(c.a, c.ta, c.b, c.tb, c.speculative, m);
        QCOMPARE(touching, m.pointCount > 0);
        checkInvariants(m, c.a, c.ta, c.speculative);
        if (QTest::currentTestFailed()) return;
        QVERIFY2(m.pointCount >= c.minPoints && m.pointCount <= c.maxPoints,
                 qPrintable(QStringLiteral("%1 points, expected %2..%3").arg(m.pointCount).arg(c.minPoints).arg(c.maxPoints)));
        if (m.pointCount == 0) return;

        if (c.checkNormal) {
            QVERIFY2(glm::length(m.normal - c.normal) < 1e-4f,
                     qPrintable(QStringLiteral("normal (%1, %2, %3)").arg(m.normal.x).arg(m.normal.y).arg(m.normal.z)));
        }
        float deepest = std::numeric_limits<float>::max();
        for (int i = 0; i < m.pointCount; ++i) deepest = std::min(deepest, m.points[i].separation);
        QVERIFY2(std::abs(deepest - c.separation) < kSeparationTolerance,
                 qPrintable(QStringLiteral("deepest separation %1, expected %2").arg(deepest).arg(c.separation)));
        if (c.allSameSeparation) {
            for (int i = 0; i < m.pointCount; ++i) {
                QVERIFY(std::abs(m.points[i].separation - c.separation) < kSeparationTolerance);
            }
        }
        for (const Vec3& expected : c.pointsA) {
            bool found = false;
            for (int i = 0; i < m.pointCount; ++i) found = found || glm::length(m.points[i].pointA - expected) < kPointTolerance;
            QVERIFY2(found, qPrintable(QStringLiteral("no point at (%1, %2, %3)").arg(expected.x).arg(expected.y).arg(expected.z)));
        }
        std::vector<Vec3> points;
        for (int i = 0; i < m.pointCount; ++i) points.push_back(m.points[i].pointA);
        if (c.minArea > 0.0f) {
            const float area = spannedArea(points, m.normal);
            QVERIFY2(area >= c.minArea, qPrintable(QStringLiteral("area %1 < %2").arg(area).arg(c.minArea)));
        }

        // Swapped: same contacts, flipped normal, A's and B's points exchanged.
        ContactManifold swapped;
        QCOMPARE(collideShapes(c.b, c.tb, c.a, c.ta, c.speculative, swapped), touching);
        checkInvariants(swapped, c.b, c.tb, c.speculative);
        QCOMPARE(swapped.pointCount, m.pointCount);
        if (c.checkNormal) {  // coincident shapes have no preferred direction to flip
            QVERIFY2(glm::length(swapped.normal + m.normal) < 1e-3f, "swapping A and B does not flip the normal");
        }
        float swappedDeepest = std::numeric_limits<float>::max();
        for (int i = 0; i < swapped.pointCount; ++i) swappedDeepest = std::min(swappedDeepest, swapped.points[i].separation);
        QVERIFY(std::abs(swappedDeepest - deepest) < kSeparationTolerance);
    }

    // Random pairs of every type combination, overlapping or (half of them) near touching:
    // invariants hold both ways round, the manifold exists when GJK/EPA says the shapes are within
    // the speculative distance, and for shallow contacts (the resting regime) its deepest point agrees with the GJK/EPA signed
    // distance. Loosely: SAT keeps a face axis up to 5% + 2.5 mm worse than the best edge axis and
    // A's face up to 2% + 0.5 mm worse than B's (stability over exactness). Deep overlaps are not
    // compared: clipping may drop the deepest vertex when it lies outside the reference face.
    void randomPairs() {
        std::mt19937 rng(12345);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        const auto size = [&] { return 0.2f + 0.6f * unit(rng); };
        const auto direction = [&] {
            const Vec3 v(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
            return lengthSquared(v) > 1e-4f ? glm::normalize(v) : Vec3(0, 1, 0);
        };
        const auto randomShape = [&](int type) {
            switch (type) {
                case 0: return Shape::sphere(size());
                case 1: return Shape::box(Vec3(size(), size(), size()));
                case 2: return Shape::capsule(size() * 0.5f, size());
                case 3: return Shape::cylinder(size(), size());
                default: {
                    std::vector<Vec3> points;
                    for (int i = 0; i < 12; ++i) points.push_back(direction() * size());
                    return Shape::convexHull(ConvexHull::build(points).hull);  // null if degenerate: skipped
                }
            }
        };
        const float speculative = 0.02f;
        int mismatches = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            const Shape a = randomShape(trial % 5);
            const Shape b = randomShape((trial / 5) % 5);
            if ((a.type == ShapeType::ConvexHull && !a.hull) || (b.type == ShapeType::ConvexHull && !b.hull)) continue;
            const Transform ta = place(direction() * 0.1f, glm::angleAxis(unit(rng) * 6.28f, direction()));
            Transform tb = place(direction() * (0.3f + 0.8f * unit(rng)), glm::angleAxis(unit(rng) * 6.28f, direction()));
            if (trial % 2 == 1) {
                // Half the trials are moved to the resting regime: within a few cm of touching.
                const ContactQuery start = penetrationOrDistance(a, ta, b, tb);
                tb.position += start.normal * (0.07f * unit(rng) - 0.03f - start.signedDistance());
            }
            ContactManifold m, swapped;
            const bool touching = collideShapes(a, ta, b, tb, speculative, m);
            const bool touchingSwapped = collideShapes(b, tb, a, ta, speculative, swapped);
            checkInvariants(m, a, ta, speculative);
            checkInvariants(swapped, b, tb, speculative);
            if (QTest::currentTestFailed()) {
                qWarning("trial %d: types %d %d", trial, int(a.type), int(b.type));
                return;
            }
            const float signedDistance = penetrationOrDistance(a, ta, b, tb).signedDistance();
            if (std::abs(signedDistance - speculative) < 2e-3f) continue;  // too close to call
            float deepest = std::numeric_limits<float>::max();
            for (int i = 0; i < m.pointCount; ++i) deepest = std::min(deepest, m.points[i].separation);
            QCOMPARE(touchingSwapped, touching);
            // No contact is missed. For separated polyhedra the best SAT axis only bounds the gap
            // from below, so a pair slightly beyond the speculative distance may still be reported,
            // with a separation no larger than the true gap.
            if (signedDistance < speculative) QVERIFY2(touching, qPrintable(QStringLiteral("trial %1 missed").arg(trial)));
            if (touching && signedDistance >= speculative) QVERIFY(deepest <= signedDistance + kSeparationTolerance);
            if (!touching || signedDistance < -0.05f) continue;
            if (std::abs(deepest - signedDistance) > 0.075f * std::abs(signedDistance) + 0.01f) {
                ++mismatches;
                qWarning("trial %d: types %d %d: deepest %f, signed distance %f, %d points", trial, int(a.type),
                         int(b.type), deepest, signedDistance, m.pointCount);
                for (int i = 0; i < m.pointCount; ++i) qWarning("  id %08x sep %f", m.points[i].featureId, m.points[i].separation);
            }
        }
        QCOMPARE(mismatches, 0);
    }

    // Feature ids identify the touching features, so a small slide keeps every id.
    void featureIdsStableUnderSmallMotion() {
        const Shape ground = Shape::box(Vec3(2.0f, 0.5f, 2.0f));
        const Shape box = Shape::box(Vec3(0.5f));
        ContactManifold before, after;
        QVERIFY(collideShapes(ground, place(Vec3(0)), box, place(Vec3(0, 0.99f, 0)), 0.02f, before));
        QVERIFY(collideShapes(ground, place(Vec3(0)), box,
                              place(Vec3(0.003f, 0.991f, -0.002f), rotation(1.0f, Vec3(0, 1, 0))), 0.02f, after));
        QCOMPARE(after.pointCount, before.pointCount);
        std::vector<std::uint32_t> idsBefore, idsAfter;
        for (int i = 0; i < before.pointCount; ++i) idsBefore.push_back(before.points[i].featureId);
        for (int i = 0; i < after.pointCount; ++i) idsAfter.push_back(after.points[i].featureId);
        std::sort(idsBefore.begin(), idsBefore.end());
        std::sort(idsAfter.begin(), idsAfter.end());
        QVERIFY(idsBefore == idsAfter);
        QVERIFY(std::adjacent_find(idsBefore.begin(), idsBefore.end()) == idsBefore.end());  // distinct
    }

    // The narrow phase runs for every pair every step: it must not touch the heap.
    void noHeapAllocation() {
        test_support::startCountingAllocations();
        for (const Case& c : cases()) {
            ContactManifold m;
            collideShapes(c.a, c.ta, c.b, c.tb, c.speculative, m);
            collideShapes(c.b, c.tb, c.a, c.ta, c.speculative, m);
        }
        const std::size_t allocations = test_support::stopCountingAllocations();
        QCOMPARE(allocations, std::size_t(0));
    }

    // The whole scene moved by a rigid transform gives the same manifold, moved.
    void rigidMotionInvariance() {
        const Shape ground = Shape::box(Vec3(2.0f, 0.5f, 2.0f));
        const Shape box = Shape::box(Vec3(0.5f));
        const Quat q = rotation(37.0f, Vec3(1, 2, 3));
        const Vec3 shift(3.0f, -1.0f, 2.0f);
        ContactManifold moved;
        QVERIFY(collideShapes(ground, place(shift, q), box, place(shift + q * Vec3(0, 0.99f, 0), q), 0.02f, moved));
        QCOMPARE(moved.pointCount, 4);
        QVERIFY(glm::length(moved.normal - q * Vec3(0, 1, 0)) < 1e-4f);
        for (int i = 0; i < moved.pointCount; ++i) QVERIFY(std::abs(moved.points[i].separation + 0.01f) < kSeparationTolerance);
    }
};

QTEST_APPLESS_MAIN(TestCollideShapes)
#include "test_collide_shapes.moc"
