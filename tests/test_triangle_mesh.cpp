// Static triangle surfaces: TriangleMesh validation, adjacency and active edges, the BVH query and
// ray cast (both against brute force over every triangle).

#include "support/allocation_counter.h"
#include "simcore/shapes/triangle_mesh.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <set>
#include <vector>

using namespace simcore;
using namespace test_support;

namespace {

using Indices = TriangleMesh::Indices;

// A flat square [-1, 1]^2 at y = 0, facing +y, split along the diagonal from (-1, -1) to (1, 1).
std::shared_ptr<const TriangleMesh> flatSquare(float halfSize = 1.0f) {
    const float h = halfSize;
    auto result = TriangleMesh::build({{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}}, {{0, 2, 1}, {0, 3, 2}});
    return result.mesh;
}

// A rolling terrain of (n x n) cells, two triangles each, facing +y.
std::shared_ptr<const TriangleMesh> terrain(int n, float cell, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> bump(-0.3f, 0.3f);
    std::vector<Vec3> vertices;
    for (int r = 0; r <= n; ++r)
        for (int c = 0; c <= n; ++c)
            vertices.emplace_back(c * cell, std::sin(0.3f * c) + std::cos(0.2f * r) + bump(random), r * cell);
    std::vector<Indices> triangles;
    auto at = [n](int r, int c) { return std::uint32_t(r * (n + 1) + c); };
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            triangles.push_back({at(r, c), at(r + 1, c), at(r + 1, c + 1)});
            triangles.push_back({at(r, c), at(r + 1, c + 1), at(r, c + 1)});
        }
    return TriangleMesh::build(std::move(vertices), std::move(triangles)).mesh;
}

Aabb boundsOf(const Triangle& t) {
    Aabb box;
    for (const Vec3& v : t.vertices) box.grow(v);
    return box;
}

}  // namespace

class TestTriangleMesh : public QObject {
    Q_OBJECT
private slots:
    void validationNamesWhatIsWrong_data();
    void validationNamesWhatIsWrong();
    void normalsFollowCounterClockwiseFront();
    void flatSeamIsInactiveBoundaryActive();
    void creaseActiveOnlyWhenConvexAndSharp_data();
    void creaseActiveOnlyWhenConvexAndSharp();
    void unsharedVerticesAreWeldedForAdjacency();
    void bvhQueryMatchesBruteForce();
    void bvhQueryAllocatesNothing();
    void rayCastMatchesBruteForce();
    void rayCastIsTwoSidedAndRejectsBadRays();
};

void TestTriangleMesh::validationNamesWhatIsWrong_data() {
    QTest::addColumn<QVector<float>>("coordinates");  // x, y, z per vertex
    QTest::addColumn<QVector<uint>>("indices");        // three per triangle
    QTest::addColumn<QString>("expected");              // part of the message
    const float inf = std::numeric_limits<float>::infinity();
    const QVector<float> unit{0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("no triangles") << unit << QVector<uint>{} << "no triangles";
    QTest::newRow("index out of range") << unit << QVector<uint>{0, 1, 3} << "triangle 0 uses vertex 3, but the mesh has 3";
    QTest::newRow("vertex twice") << unit << QVector<uint>{0, 2, 1, 0, 1, 1} << "triangle 1 uses a vertex twice";
    QTest::newRow("collinear") << QVector<float>{0, 0, 0, 1, 0, 0, 2, 0, 0} << QVector<uint>{0, 1, 2}
                               << "triangle 0 is degenerate";
    QTest::newRow("coincident") << QVector<float>{1, 1, 1, 1, 1, 1, 0, 0, 1} << QVector<uint>{0, 1, 2}
                                << "triangle 0 is degenerate";
    QTest::newRow("sliver") << QVector<float>{0, 0, 0, 1, 0, 0, 0.5f, 1e-8f, 0} << QVector<uint>{0, 1, 2}
                            << "triangle 0 is degenerate";
    QTest::newRow("nan vertex") << QVector<float>{0, 0, 0, 1, 0, 0, 0, std::nanf(""), 1} << QVector<uint>{0, 1, 2}
                                << "vertex 2 is not finite";
    QTest::newRow("infinite vertex") << QVector<float>{0, 0, 0, inf, 0, 0, 0, 0, 1} << QVector<uint>{0, 1, 2}
                                     << "vertex 1 is not finite";
    QTest::newRow("vertex too far") << QVector<float>{0, 0, 0, 2e6f, 0, 0, 0, 0, 1} << QVector<uint>{0, 1, 2}
                                    << "vertex 1 (2e+06, 0, 0) is beyond 1000000 m";
}

void TestTriangleMesh::validationNamesWhatIsWrong() {
    QFETCH(QVector<float>, coordinates);
    QFETCH(QVector<uint>, indices);
    QFETCH(QString, expected);
    std::vector<Vec3> vertices;
    for (int i = 0; i + 2 < coordinates.size(); i += 3) vertices.emplace_back(coordinates[i], coordinates[i + 1], coordinates[i + 2]);
    std::vector<Indices> triangles;
    for (int i = 0; i + 2 < indices.size(); i += 3) triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
    const auto result = TriangleMesh::build(vertices, triangles);
    QVERIFY(!result.mesh);
    QVERIFY2(QString::fromStdString(result.error).contains(expected), result.error.c_str());
}

void TestTriangleMesh::normalsFollowCounterClockwiseFront() {
    const auto mesh = flatSquare();
    QVERIFY(mesh);
    QCOMPARE(mesh->triangleCount(), std::size_t(2));
    for (std::uint32_t t = 0; t < 2; ++t) {
        const Triangle tri = mesh->triangle(t);
        QVERIFY(glm::length(tri.normal - Vec3(0, 1, 0)) < 1e-6f);
    }
    // Reversing the winding turns the front over.
    const auto flipped = TriangleMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 1, 2}}).mesh;
    QVERIFY(glm::length(flipped->triangle(0).normal - Vec3(0, -1, 0)) < 1e-6f);
    QVERIFY(glm::length(mesh->bounds().min - Vec3(-1, 0, -1)) < 1e-6f);
    QVERIFY(glm::length(mesh->bounds().max - Vec3(1, 0, 1)) < 1e-6f);
}

void TestTriangleMesh::flatSeamIsInactiveBoundaryActive() {
    const auto mesh = flatSquare();
    // Triangle 0 = (0, 2, 1): edge 0 (0-2) is the diagonal; triangle 1 = (0, 3, 2): edge 2 (2-0).
    QCOMPARE(mesh->neighbour(0, 0), 1u);
    QCOMPARE(mesh->neighbour(1, 2), 0u);
    QVERIFY(!isEdgeActive(mesh->triangle(0).flags, 0));
    QVERIFY(!isEdgeActive(mesh->triangle(1).flags, 2));
    QVERIFY(isEdgeActive(mesh->triangle(0).flags, 1));
    QVERIFY(isEdgeActive(mesh->triangle(1).flags, 0));
    QCOMPARE(mesh->neighbour(0, 1), TriangleMesh::kNoNeighbour);
    // Every vertex of the square lies on the boundary, so all are active.
    for (std::uint32_t t = 0; t < 2; ++t)
        for (int v = 0; v < 3; ++v) QVERIFY(isVertexActive(mesh->triangle(t).flags, v));
}

void TestTriangleMesh::creaseActiveOnlyWhenConvexAndSharp_data() {
    QTest::addColumn<float>("foldDegrees");  // > 0: the far half bends down (a ridge), < 0: up (a valley)
    QTest::addColumn<bool>("active");
    QTest::newRow("flat") << 0.0f << false;
    QTest::newRow("ridge 3 degrees (under 5)") << 3.0f << false;
    QTest::newRow("ridge 10 degrees") << 10.0f << true;
    QTest::newRow("ridge 90 degrees") << 90.0f << true;
    QTest::newRow("valley 10 degrees") << -10.0f << false;
    QTest::newRow("valley 60 degrees") << -60.0f << false;
}

void TestTriangleMesh::creaseActiveOnlyWhenConvexAndSharp() {
    QFETCH(float, foldDegrees);
    QFETCH(bool, active);
    // Two triangles sharing the edge along z at x = 0; the second one's far vertex folds about it.
    const float a = foldDegrees * kPi / 180.0f;
    const Vec3 far(std::cos(a), -std::sin(a), 0.5f);
    const auto mesh = TriangleMesh::build({{0, 0, 0}, {0, 0, 1}, {-1, 0, 0.5f}, far}, {{0, 2, 1}, {0, 1, 3}}).mesh;
    QVERIFY(mesh);
    QCOMPARE(mesh->neighbour(0, 2), 1u);  // edge 2 of triangle 0 runs 1 -> 0
    QCOMPARE(isEdgeActive(mesh->triangle(0).flags, 2), active);
    QCOMPARE(isEdgeActive(mesh->triangle(1).flags, 0), active);
}

void TestTriangleMesh::unsharedVerticesAreWeldedForAdjacency() {
    // The flat square as an STL file stores it: three vertices of its own per triangle.
    const auto mesh = TriangleMesh::build({{-1, 0, -1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}},
                                          {{0, 1, 2}, {3, 4, 5}}).mesh;
    QCOMPARE(mesh->neighbour(0, 0), 1u);
    QVERIFY(!isEdgeActive(mesh->triangle(0).flags, 0));
}

void TestTriangleMesh::bvhQueryMatchesBruteForce() {
    const auto mesh = terrain(100, 1.0f, 7);  // 20 000 triangles
    QCOMPARE(mesh->triangleCount(), std::size_t(20000));
    QVERIFY(mesh->bvhDepth() <= TriangleMesh::kMaxDepth);
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(-10.0f, 110.0f), height(-3.0f, 4.0f), size(0.01f, 8.0f);
    std::size_t totalFound = 0;
    for (int q = 0; q < 500; ++q) {
        const Vec3 centre(position(random), height(random), position(random));
        const Aabb box = Aabb::fromCenterHalfExtents(centre, Vec3(size(random), size(random), size(random)));
        std::set<std::uint32_t> expected;
        for (std::uint32_t t = 0; t < mesh->triangleCount(); ++t)
            if (boundsOf(mesh->triangle(t)).overlaps(box)) expected.insert(t);
        std::vector<std::uint32_t> found;
        mesh->forEachTriangleOverlapping(box, [&](std::uint32_t t) { found.push_back(t); });
        const std::set<std::uint32_t> foundSet(found.begin(), found.end());
        QCOMPARE(found.size(), foundSet.size());  // each triangle once
        QVERIFY(foundSet == expected);
        totalFound += found.size();
    }
    QVERIFY(totalFound > 1000);  // the boxes did meet the terrain
}

void TestTriangleMesh::bvhQueryAllocatesNothing() {
    const auto mesh = terrain(50, 1.0f, 3);
    std::uint32_t buffer[256];
    int count = 0;
    startCountingAllocations();
    mesh->forEachTriangleOverlapping(Aabb::fromCenterHalfExtents({25, 0, 25}, {2, 5, 2}), [&](std::uint32_t t) {
        if (count < 256) buffer[count++] = t;
    });
    const auto hit = mesh->rayCast({25.5f, 10, 25.5f}, {0, -20, 0});
    QCOMPARE(stopCountingAllocations(), std::size_t(0));
    QVERIFY(count >= 32);  // 4 x 4 cells at least
    QVERIFY(hit.has_value());
}

void TestTriangleMesh::rayCastMatchesBruteForce() {
    const auto mesh = terrain(60, 0.5f, 5);
    std::mt19937 random(13);
    std::uniform_real_distribution<float> position(-5.0f, 35.0f), height(-4.0f, 6.0f), unit(-1.0f, 1.0f);
    int hits = 0;
    for (int q = 0; q < 2000; ++q) {
        const Vec3 origin(position(random), height(random), position(random));
        const Vec3 direction = 40.0f * Vec3(unit(random), unit(random), unit(random));
        std::optional<SurfaceRayHit> expected;
        for (std::uint32_t t = 0; t < mesh->triangleCount(); ++t) {
            auto hit = rayCastTriangle(mesh->triangle(t), origin, direction, 1.0f);
            if (hit && (!expected || hit->fraction < expected->fraction)) {
                hit->triangle = t;
                expected = hit;
            }
        }
        const auto found = mesh->rayCast(origin, direction);
        QCOMPARE(found.has_value(), expected.has_value());
        if (!found) continue;
        ++hits;
        QCOMPARE(found->fraction, expected->fraction);
        QVERIFY(std::abs(glm::dot(found->normal, direction)) > 0.0f && glm::dot(found->normal, direction) <= 0.0f);
    }
    QVERIFY(hits > 300);
}

void TestTriangleMesh::rayCastIsTwoSidedAndRejectsBadRays() {
    const auto mesh = flatSquare();
    const auto fromAbove = mesh->rayCast({0.2f, 1, 0.3f}, {0, -2, 0});
    QVERIFY(fromAbove && fromAbove->frontFace);
    QCOMPARE(fromAbove->fraction, 0.5f);
    QVERIFY(glm::length(fromAbove->normal - Vec3(0, 1, 0)) < 1e-6f);
    const auto fromBelow = mesh->rayCast({0.2f, -1, 0.3f}, {0, 2, 0});
    QVERIFY(fromBelow && !fromBelow->frontFace);
    QVERIFY(glm::length(fromBelow->normal - Vec3(0, -1, 0)) < 1e-6f);
    QVERIFY(!mesh->rayCast({0.2f, 1, 0.3f}, {0, -0.5f, 0}));  // stops short
    QVERIFY(!mesh->rayCast({2.0f, 1, 0.3f}, {0, -2, 0}));     // beside the square
    QVERIFY(!mesh->rayCast({0, 1, 0}, {0, 0, 0}));
    QVERIFY(!mesh->rayCast({0, std::nanf(""), 0}, {0, -2, 0}));
    QVERIFY(!mesh->rayCast({0, 1, 0}, {0, -2, 0}, -1.0f));
}

QTEST_APPLESS_MAIN(TestTriangleMesh)
#include "test_triangle_mesh.moc"
