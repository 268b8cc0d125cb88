// Static triangle surfaces: TriangleMesh validation, adjacency and active edges, the BVH query and
// ray cast (both against brute force over every triangle), and the narrow phase of convex shapes
// against triangles (collideTriangleConvex): full manifolds, internal edges, one-sidedness; the
// height field against the mesh made of the same samples.

#include "support/allocation_counter.h"
#include "simcore/collision/collide_mesh.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/height_field.h"
#include "simcore/shapes/triangle_mesh.h"

#include <QtTest>

#include <cmath>
#include <optional>
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

// A rolling height field of rows x columns samples.
std::shared_ptr<const HeightField> rollingField(int rows, int columns, float cell, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> bump(-0.3f, 0.3f);
    std::vector<float> heights;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) heights.push_back(0.5f * (std::sin(0.3f * c) + std::cos(0.2f * r) + bump(random)));
    auto result = HeightField::build(rows, columns, cell, 2.0f, std::move(heights));
    return result.field;
}

// The same surface as a TriangleMesh, written from the layout documented in height_field.h.
std::shared_ptr<const TriangleMesh> meshOf(const HeightField& field) {
    std::vector<Vec3> vertices;
    for (int r = 0; r < field.rows(); ++r)
        for (int c = 0; c < field.columns(); ++c) vertices.push_back(field.sample(r, c));
    const int n = field.columns();
    auto at = [n](int r, int c) { return std::uint32_t(r * n + c); };
    std::vector<Indices> triangles;
    for (int r = 0; r + 1 < field.rows(); ++r)
        for (int c = 0; c + 1 < n; ++c) {
            triangles.push_back({at(r, c), at(r + 1, c), at(r + 1, c + 1)});
            triangles.push_back({at(r, c), at(r + 1, c + 1), at(r, c + 1)});
        }
    return TriangleMesh::build(std::move(vertices), std::move(triangles)).mesh;
}

const Vec3 kUp(0.0f, 1.0f, 0.0f);
constexpr float kSpeculative = 0.02f;  // m, a typical speculative margin

Transform at(const Vec3& position, const Quat& rotation = Quat(1, 0, 0, 0)) { return {position, rotation}; }
Quat yaw(float degrees) { return glm::angleAxis(degrees * kPi / 180.0f, kUp); }

// Manifolds of `shape` against every triangle of `mesh` (with each triangle's flags replaced by
// `forcedFlags` when given, to show what the active-edge flags prevent).
std::vector<ContactManifold> collideAll(const TriangleMesh& mesh, const Shape& shape, const Transform& t,
                                        std::optional<TriangleFeatureFlags> forcedFlags = std::nullopt) {
    std::vector<ContactManifold> manifolds;
    for (std::uint32_t i = 0; i < mesh.triangleCount(); ++i) {
        Triangle tri = mesh.triangle(i);
        if (forcedFlags) tri.flags = *forcedFlags;
        ContactManifold m;
        if (collideTriangleConvex(tri, shape, t, kSpeculative, m)) manifolds.push_back(m);
    }
    return manifolds;
}

float tiltDegrees(const Vec3& normal) { return std::acos(std::min(1.0f, glm::dot(normal, kUp))) * 180.0f / kPi; }

// Every manifold's invariants: unit normal, separation = dot(pointB - pointA, normal), within the
// speculative distance, finite.
void checkInvariants(const ContactManifold& m) {
    QVERIFY(m.pointCount >= 1 && m.pointCount <= kMaxManifoldPoints);
    QVERIFY(std::abs(glm::length(m.normal) - 1.0f) < 1e-5f);
    for (int k = 0; k < m.pointCount; ++k) {
        const ContactPoint& p = m.points[k];
        QVERIFY(isFinite(p.pointA) && isFinite(p.pointB) && isFinite(p.separation));
        QVERIFY(std::abs(glm::dot(p.pointB - p.pointA, m.normal) - p.separation) < 1e-5f);
        QVERIFY(p.separation <= kSpeculative + 1e-6f);
    }
}

float deepest(const ContactManifold& m) {
    float d = std::numeric_limits<float>::max();
    for (int k = 0; k < m.pointCount; ++k) d = std::min(d, m.points[k].separation);
    return d;
}

std::shared_ptr<const ConvexHull> boxHull(const Vec3& h) {
    std::vector<Vec3> points;
    for (int k = 0; k < 8; ++k) points.emplace_back(k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z);
    return ConvexHull::build(points).hull;
}

}  // namespace

Q_DECLARE_METATYPE(Shape)
Q_DECLARE_METATYPE(Transform)
Q_DECLARE_METATYPE(Quat)

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
    void boxRestingOnSquareGetsFourPointsPerTriangle();
    void restingShapesGetFullManifolds_data();
    void restingShapesGetFullManifolds();
    void boxSlidingAcrossSeamKeepsFaceNormal_data();
    void boxSlidingAcrossSeamKeepsFaceNormal();
    void roundShapesCrossingSeamKeepFaceNormal_data();
    void roundShapesCrossingSeamKeepFaceNormal();
    void activeBoundaryEdgeKeepsItsNormal();
    void oneSidedWallIgnoresShapesBehind();
    void beyondSpeculativeDistanceGivesNothing();
    void collideAllocatesNothing();
    void heightFieldValidation_data();
    void heightFieldValidation();
    void heightFieldMatchesItsMesh();
    void heightFieldQueryAndRayMatchBruteForce();
    void heightFieldAndMeshGiveTheSameContacts();
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

void TestTriangleMesh::boxRestingOnSquareGetsFourPointsPerTriangle() {
    const auto mesh = flatSquare();
    const Shape box = Shape::box({0.2f, 0.2f, 0.2f});
    // Wholly over triangle 0 (x > z): four points at the bottom corners, 1 cm deep, face normal.
    {
        const auto manifolds = collideAll(*mesh, box, at({0.5f, 0.19f, -0.5f}));
        QCOMPARE(manifolds.size(), std::size_t(1));
        const ContactManifold& m = manifolds[0];
        checkInvariants(m);
        QCOMPARE(m.pointCount, 4);
        QVERIFY(glm::length(m.normal - kUp) < 1e-6f);
        std::set<std::pair<int, int>> corners;
        for (int k = 0; k < 4; ++k) {
            QVERIFY(std::abs(m.points[k].separation + 0.01f) < 1e-5f);
            QVERIFY(std::abs(m.points[k].pointA.y) < 1e-5f);  // on the triangle
            corners.insert({int(std::lround((m.points[k].pointB.x - 0.5f) / 0.2f)), int(std::lround((m.points[k].pointB.z + 0.5f) / 0.2f))});
        }
        QCOMPARE(corners, (std::set<std::pair<int, int>>{{-1, -1}, {-1, 1}, {1, -1}, {1, 1}}));
    }
    // Over the seam, turned 30 degrees: each triangle holds its share of the footprint, all flat.
    const auto manifolds = collideAll(*mesh, box, at({0.05f, 0.19f, 0.0f}, yaw(30.0f)));
    QCOMPARE(manifolds.size(), std::size_t(2));
    for (const ContactManifold& m : manifolds) {
        checkInvariants(m);
        QCOMPARE(m.pointCount, 4);
        QVERIFY(glm::length(m.normal - kUp) < 1e-6f);
        QVERIFY(std::abs(deepest(m) + 0.01f) < 1e-5f);
    }
}

void TestTriangleMesh::restingShapesGetFullManifolds_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<Transform>("pose");  // its height is set so the lowest point is 1 cm deep
    QTest::addColumn<int>("points");
    const Quat onSide = glm::angleAxis(0.5f * kPi, Vec3(0, 0, 1));
    const Quat onEdge = glm::angleAxis(0.25f * kPi, Vec3(0, 0, 1));
    const Vec3 diagonal = glm::normalize(Vec3(1, 1, 1));
    const Quat onCorner = glm::angleAxis(std::acos(glm::dot(diagonal, kUp)), glm::normalize(glm::cross(diagonal, kUp)));
    QTest::newRow("sphere") << Shape::sphere(0.3f) << at({0.5f, 0, -0.4f}) << 1;
    QTest::newRow("box on an edge") << Shape::box({0.2f, 0.2f, 0.2f}) << at({0.5f, 0, -0.4f}, onEdge) << 2;
    QTest::newRow("box on a corner") << Shape::box({0.2f, 0.2f, 0.2f}) << at({0.5f, 0, -0.4f}, onCorner) << 1;
    QTest::newRow("hull box flat") << Shape::convexHull(boxHull({0.2f, 0.1f, 0.2f})) << at({0.5f, 0, -0.5f}, yaw(10.0f)) << 4;
    QTest::newRow("capsule lying") << Shape::capsule(0.1f, 0.2f) << at({0.5f, 0, -0.4f}, onSide) << 2;
    QTest::newRow("capsule standing") << Shape::capsule(0.1f, 0.2f) << at({0.5f, 0, -0.4f}) << 1;
    QTest::newRow("cylinder standing") << Shape::cylinder(0.15f, 0.2f) << at({0.6f, 0, -0.5f}) << 4;
    QTest::newRow("cylinder lying") << Shape::cylinder(0.15f, 0.2f) << at({0.5f, 0, -0.4f}, onSide) << 2;
}

void TestTriangleMesh::restingShapesGetFullManifolds() {
    QFETCH(Shape, shape);
    QFETCH(Transform, pose);
    QFETCH(int, points);
    const Vec3 localDown = pose.rotateInverse(-kUp);
    pose.position.y = -pose.rotate(support(shape, localDown)).y - 0.01f;
    const auto mesh = flatSquare();
    const auto manifolds = collideAll(*mesh, shape, pose);
    QCOMPARE(manifolds.size(), std::size_t(1));  // wholly over triangle 0
    const ContactManifold& m = manifolds[0];
    checkInvariants(m);
    QCOMPARE(m.pointCount, points);
    QVERIFY2(tiltDegrees(m.normal) < 1e-3f, qPrintable(QString::number(tiltDegrees(m.normal))));
    QVERIFY2(std::abs(deepest(m) + 0.01f) < 2e-5f, qPrintable(QString::number(deepest(m))));
}

void TestTriangleMesh::boxSlidingAcrossSeamKeepsFaceNormal_data() {
    QTest::addColumn<float>("yawDegrees");
    QTest::addColumn<float>("pitchDegrees");  // a slight nose-down tilt, as a sliding box has
    QTest::newRow("square on") << 0.0f << 0.0f;
    QTest::newRow("turned 30") << 30.0f << 0.0f;
    QTest::newRow("edge along the seam") << 45.0f << 0.0f;
    QTest::newRow("tilted 2 degrees") << 10.0f << 2.0f;
}

void TestTriangleMesh::boxSlidingAcrossSeamKeepsFaceNormal() {
    QFETCH(float, yawDegrees);
    QFETCH(float, pitchDegrees);
    const auto mesh = flatSquare();
    const Shape box = Shape::box({0.2f, 0.2f, 0.2f});
    const Quat rotation = glm::angleAxis(pitchDegrees * kPi / 180.0f, Vec3(1, 0, 0)) * yaw(yawDegrees);
    float worstTilt = 0.0f, worstUnflagged = 0.0f;
    const int steps = 400;
    for (int s = 0; s <= steps; ++s) {
        // Across the diagonal seam, from over triangle 0 to over triangle 1, 5 mm deep.
        const float f = float(s) / steps;
        Transform pose = at(Vec3(0.45f - 0.9f * f, 0.0f, -0.45f + 0.9f * f), rotation);
        const float bottom = -glm::dot(support(box, glm::conjugate(rotation) * -kUp), glm::conjugate(rotation) * -kUp);
        pose.position.y = -bottom - 0.005f;
        const auto manifolds = collideAll(*mesh, box, pose);
        QVERIFY(!manifolds.empty());
        float deepestHere = 0.0f;
        for (const ContactManifold& m : manifolds) {
            checkInvariants(m);
            worstTilt = std::max(worstTilt, tiltDegrees(m.normal));
            deepestHere = std::min(deepestHere, deepest(m));
        }
        QVERIFY2(std::abs(deepestHere + 0.005f) < 1e-4f, qPrintable(QString::number(deepestHere)));
        for (const ContactManifold& m : collideAll(*mesh, box, pose, kAllFeaturesActive))
            worstUnflagged = std::max(worstUnflagged, tiltDegrees(m.normal));
    }
    QVERIFY2(worstTilt < 1.0f, qPrintable(QString("tilt %1 degrees").arg(worstTilt)));
    // The same slide with every edge treated as active would bump: the test can fail.
    QVERIFY2(worstUnflagged > 5.0f || (pitchDegrees == 0.0f && yawDegrees == 0.0f),
             qPrintable(QString("unflagged tilt %1 degrees").arg(worstUnflagged)));
}

void TestTriangleMesh::roundShapesCrossingSeamKeepFaceNormal_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<Quat>("rotation");
    const Quat lying = glm::angleAxis(0.5f * kPi, Vec3(0, 0, 1));
    QTest::newRow("sphere") << Shape::sphere(0.5f) << Quat(1, 0, 0, 0);
    QTest::newRow("capsule lying") << Shape::capsule(0.2f, 0.3f) << lying;
    QTest::newRow("capsule lying across") << Shape::capsule(0.2f, 0.3f) << yaw(60.0f) * lying;
    QTest::newRow("cylinder lying") << Shape::cylinder(0.2f, 0.3f) << yaw(30.0f) * lying;
    QTest::newRow("cylinder standing") << Shape::cylinder(0.2f, 0.3f) << Quat(1, 0, 0, 0);
    QTest::newRow("hull") << Shape::convexHull(boxHull({0.2f, 0.15f, 0.25f})) << yaw(20.0f);
}

void TestTriangleMesh::roundShapesCrossingSeamKeepFaceNormal() {
    QFETCH(Shape, shape);
    QFETCH(Quat, rotation);
    const auto mesh = flatSquare();
    const Vec3 localDown = glm::conjugate(rotation) * -kUp;
    const float lowest = (rotation * support(shape, localDown)).y;
    float worstTilt = 0.0f, worstUnflagged = 0.0f;
    for (int s = 0; s <= 400; ++s) {
        // Across the diagonal seam, 1 cm deep.
        const float f = float(s) / 400.0f;
        const Transform pose = at({0.3f - 0.6f * f, -lowest - 0.01f, -0.3f + 0.6f * f}, rotation);
        const auto manifolds = collideAll(*mesh, shape, pose);
        QVERIFY(!manifolds.empty());
        float deepestHere = 0.0f;
        for (const ContactManifold& m : manifolds) {
            checkInvariants(m);
            worstTilt = std::max(worstTilt, tiltDegrees(m.normal));
            deepestHere = std::min(deepestHere, deepest(m));
        }
        QVERIFY2(std::abs(deepestHere + 0.01f) < 1e-4f, qPrintable(QString::number(deepestHere)));
        for (const ContactManifold& m : collideAll(*mesh, shape, pose, kAllFeaturesActive))
            worstUnflagged = std::max(worstUnflagged, tiltDegrees(m.normal));
    }
    QVERIFY2(worstTilt < 1.0f, qPrintable(QString("tilt %1 degrees").arg(worstTilt)));
    // The same crossing with every edge treated as active would bump: the test can fail.
    QVERIFY2(worstUnflagged > 5.0f, qPrintable(QString("unflagged tilt %1 degrees").arg(worstUnflagged)));
}

void TestTriangleMesh::activeBoundaryEdgeKeepsItsNormal() {
    // A sphere beside the square's outer edge x = 1, its centre 0.2 m out and 0.1 m up: the edge
    // normal points from the edge to the centre.
    const auto mesh = flatSquare();
    const auto manifolds = collideAll(*mesh, Shape::sphere(0.25f), at({1.2f, 0.1f, -0.3f}));
    QCOMPARE(manifolds.size(), std::size_t(1));
    const ContactManifold& m = manifolds[0];
    checkInvariants(m);
    const Vec3 expected = glm::normalize(Vec3(0.2f, 0.1f, 0.0f));
    QVERIFY(glm::length(m.normal - expected) < 1e-5f);
    QVERIFY(std::abs(m.points[0].separation - (glm::length(Vec3(0.2f, 0.1f, 0)) - 0.25f)) < 1e-5f);
    // A box leaning over the same edge gets it too (edge against edge, not the face).
    const auto boxManifolds = collideAll(*mesh, Shape::box({0.2f, 0.2f, 0.2f}),
                                         at({1.19f, 0.0f, -0.3f}, glm::angleAxis(0.25f * kPi, Vec3(0, 0, 1))));
    QCOMPARE(boxManifolds.size(), std::size_t(1));
    checkInvariants(boxManifolds[0]);
    QVERIFY2(tiltDegrees(boxManifolds[0].normal) > 30.0f, qPrintable(QString::number(tiltDegrees(boxManifolds[0].normal))));
}

void TestTriangleMesh::oneSidedWallIgnoresShapesBehind() {
    // A wall in the plane x = 0 facing +x.
    const auto wall = TriangleMesh::build({{0, -1, -1}, {0, -1, 1}, {0, 1, 1}, {0, 1, -1}}, {{0, 2, 1}, {0, 3, 2}}).mesh;
    QVERIFY(glm::length(wall->triangle(0).normal - Vec3(1, 0, 0)) < 1e-6f);
    const Shape sphere = Shape::sphere(0.5f);
    // In front, 0.1 m from the wall: pushed out along +x by 0.4 m.
    const auto front = collideAll(*wall, sphere, at({0.1f, 0.2f, 0.1f}));
    QVERIFY(!front.empty());
    for (const ContactManifold& m : front) {
        checkInvariants(m);
        QVERIFY(glm::length(m.normal - Vec3(1, 0, 0)) < 1e-6f);
        QVERIFY(std::abs(deepest(m) + 0.4f) < 1e-5f);
    }
    // Its centre behind the wall, however deep: no contact (one-sided, documented in collide_mesh.h).
    for (float x : {-0.01f, -0.1f, -0.45f})
        QVERIFY(collideAll(*wall, sphere, at({x, 0.2f, 0.1f})).empty());
    QVERIFY(collideAll(*wall, Shape::box({0.3f, 0.3f, 0.3f}), at({-0.1f, 0.0f, 0.0f})).empty());
}

void TestTriangleMesh::beyondSpeculativeDistanceGivesNothing() {
    const auto mesh = flatSquare();
    QVERIFY(collideAll(*mesh, Shape::box({0.2f, 0.2f, 0.2f}), at({0.5f, 0.2f + kSpeculative + 1e-3f, -0.5f})).empty());
    const auto near = collideAll(*mesh, Shape::box({0.2f, 0.2f, 0.2f}), at({0.5f, 0.2f + 0.5f * kSpeculative, -0.5f}));
    QCOMPARE(near.size(), std::size_t(1));
    QVERIFY(std::abs(deepest(near[0]) - 0.5f * kSpeculative) < 1e-5f);
    QVERIFY(collideAll(*mesh, Shape::sphere(0.2f), at({3.0f, 0.1f, 0.0f})).empty());
}

void TestTriangleMesh::collideAllocatesNothing() {
    const auto mesh = flatSquare();
    const Triangle tri = mesh->triangle(0);
    const Shape shapes[] = {Shape::sphere(0.3f), Shape::box({0.2f, 0.2f, 0.2f}), Shape::capsule(0.1f, 0.2f),
                            Shape::cylinder(0.2f, 0.2f), Shape::convexHull(boxHull({0.2f, 0.2f, 0.2f}))};
    int touching = 0;
    startCountingAllocations();
    for (const Shape& shape : shapes) {
        ContactManifold m;
        touching += collideTriangleConvex(tri, shape, at({0.5f, 0.15f, -0.5f}, yaw(20.0f)), kSpeculative, m);
    }
    QCOMPARE(stopCountingAllocations(), std::size_t(0));
    QCOMPARE(touching, 5);
    // A non-finite pose gives no contact instead of NaN points.
    const float nan = std::nanf("");
    for (const Shape& shape : shapes) {
        ContactManifold m;
        QVERIFY(!collideTriangleConvex(tri, shape, at({nan, 0.1f, 0.0f}), kSpeculative, m));
        QVERIFY(!collideTriangleConvex(tri, shape, at({0.5f, 0.1f, -0.5f}, Quat(nan, 0, 0, 0)), kSpeculative, m));
        QCOMPARE(m.pointCount, 0);
    }
}

void TestTriangleMesh::heightFieldValidation_data() {
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("columns");
    QTest::addColumn<float>("cellSize");
    QTest::addColumn<float>("heightScale");
    QTest::addColumn<QVector<float>>("heights");
    QTest::addColumn<QString>("expected");
    const QVector<float> four{0, 0, 0, 0};
    QTest::newRow("one row") << 1 << 4 << 1.0f << 1.0f << four << "at least 2 rows and 2 columns, got 1 x 4";
    QTest::newRow("too many") << 2000 << 2000 << 1.0f << 1.0f << four << "more than 2000000 triangles";
    QTest::newRow("wrong count") << 2 << 3 << 1.0f << 1.0f << four << "needs 6 heights, got 4";
    QTest::newRow("zero cell") << 2 << 2 << 0.0f << 1.0f << four << "cell size must be positive";
    QTest::newRow("nan cell") << 2 << 2 << std::nanf("") << 1.0f << four << "cell size must be positive";
    QTest::newRow("too wide") << 2 << 2 << 2e6f << 1.0f << four << "within 1000000 m";
    QTest::newRow("negative scale") << 2 << 2 << 1.0f << -1.0f << four << "height scale must be finite and positive";
    QTest::newRow("nan height") << 2 << 2 << 1.0f << 1.0f << QVector<float>{0, 0, std::nanf(""), 0}
                                << "height (row 1, column 0) is not finite";
    QTest::newRow("too high") << 2 << 2 << 1.0f << 10.0f << QVector<float>{0, 2e5f, 0, 0}
                              << "height (row 0, column 1) is beyond 1000000 m once scaled";
}

void TestTriangleMesh::heightFieldValidation() {
    QFETCH(int, rows);
    QFETCH(int, columns);
    QFETCH(float, cellSize);
    QFETCH(float, heightScale);
    QFETCH(QVector<float>, heights);
    QFETCH(QString, expected);
    const auto result = HeightField::build(rows, columns, cellSize, heightScale, {heights.begin(), heights.end()});
    QVERIFY(!result.field);
    QVERIFY2(QString::fromStdString(result.error).contains(expected), result.error.c_str());
}

void TestTriangleMesh::heightFieldMatchesItsMesh() {
    const auto field = rollingField(41, 61, 0.5f, 3);
    QVERIFY(field);
    QCOMPARE(field->triangleCount(), std::size_t(2 * 40 * 60));
    const auto mesh = meshOf(*field);
    QCOMPARE(mesh->triangleCount(), field->triangleCount());
    int inactive = 0;
    for (std::uint32_t t = 0; t < field->triangleCount(); ++t) {
        const Triangle a = field->triangle(t), b = mesh->triangle(t);
        for (int k = 0; k < 3; ++k) QCOMPARE(a.vertices[k], b.vertices[k]);
        QCOMPARE(a.normal, b.normal);
        QVERIFY(a.normal.y > 0.0f);  // the front faces up
        QCOMPARE(int(a.flags), int(b.flags));
        for (int e = 0; e < 3; ++e) inactive += !isEdgeActive(a.flags, e);
    }
    QVERIFY(inactive > 1000);  // the gentle terrain has many smooth seams
    QCOMPARE(field->bounds().min, mesh->bounds().min);
    QCOMPARE(field->bounds().max, mesh->bounds().max);
}

void TestTriangleMesh::heightFieldQueryAndRayMatchBruteForce() {
    const auto field = rollingField(101, 101, 1.0f, 9);  // 20 000 triangles
    std::mt19937 random(17);
    std::uniform_real_distribution<float> position(-10.0f, 110.0f), height(-3.0f, 4.0f), size(0.01f, 8.0f), unit(-1, 1);
    std::size_t found = 0;
    for (int q = 0; q < 300; ++q) {
        const Aabb box = Aabb::fromCenterHalfExtents({position(random), height(random), position(random)},
                                                     {size(random), size(random), size(random)});
        std::set<std::uint32_t> expected;
        for (std::uint32_t t = 0; t < field->triangleCount(); ++t)
            if (boundsOf(field->triangle(t)).overlaps(box)) expected.insert(t);
        std::vector<std::uint32_t> visited;
        field->forEachTriangleOverlapping(box, [&](std::uint32_t t) { visited.push_back(t); });
        QCOMPARE(visited.size(), std::set<std::uint32_t>(visited.begin(), visited.end()).size());
        QVERIFY(std::set<std::uint32_t>(visited.begin(), visited.end()) == expected);
        found += visited.size();
    }
    QVERIFY(found > 1000);
    int hits = 0;
    for (int q = 0; q < 1000; ++q) {
        const Vec3 origin(position(random), height(random), position(random));
        const Vec3 direction = 60.0f * Vec3(unit(random), unit(random), unit(random));
        std::optional<float> expected;
        for (std::uint32_t t = 0; t < field->triangleCount(); ++t)
            if (auto hit = rayCastTriangle(field->triangle(t), origin, direction, 1.0f))
                if (!expected || hit->fraction < *expected) expected = hit->fraction;
        const auto hit = field->rayCast(origin, direction);
        QCOMPARE(hit.has_value(), expected.has_value());
        if (!hit) continue;
        ++hits;
        QCOMPARE(hit->fraction, *expected);
    }
    QVERIFY(hits > 200);
    // Straight down onto a sample's cell.
    const auto down = field->rayCast({10.5f, 50, 20.5f}, {0, -100, 0});
    QVERIFY(down && down->frontFace && down->normal.y > 0.0f);
}

void TestTriangleMesh::heightFieldAndMeshGiveTheSameContacts() {
    const auto field = rollingField(41, 41, 0.5f, 21);
    const auto mesh = meshOf(*field);
    const Shape shapes[] = {Shape::sphere(0.4f), Shape::box({0.5f, 0.3f, 0.4f}), Shape::capsule(0.2f, 0.4f)};
    std::mt19937 random(23);
    std::uniform_real_distribution<float> position(2.0f, 18.0f), unit(-1.0f, 1.0f);
    int manifolds = 0;
    for (int q = 0; q < 300; ++q) {
        const Shape& shape = shapes[q % 3];
        Transform pose = at({position(random), 0, position(random)},
                            glm::normalize(Quat(unit(random), unit(random), unit(random), unit(random))));
        const auto under = field->rayCast(pose.position + Vec3(0, 50, 0), {0, -100, 0});
        QVERIFY(under);
        pose.position.y = under->point.y + 0.3f * unit(random) + 0.3f;
        Aabb box = worldBounds(shape, pose);
        box.min -= Vec3(kSpeculative);
        box.max += Vec3(kSpeculative);
        std::vector<std::uint32_t> fromField, fromMesh;
        field->forEachTriangleOverlapping(box, [&](std::uint32_t t) { fromField.push_back(t); });
        mesh->forEachTriangleOverlapping(box, [&](std::uint32_t t) { fromMesh.push_back(t); });
        std::sort(fromField.begin(), fromField.end());
        std::sort(fromMesh.begin(), fromMesh.end());
        QVERIFY(fromField == fromMesh);
        for (std::uint32_t t : fromField) {
            ContactManifold a, b;
            const bool touchA = collideTriangleConvex(field->triangle(t), shape, pose, kSpeculative, a);
            const bool touchB = collideTriangleConvex(mesh->triangle(t), shape, pose, kSpeculative, b);
            QCOMPARE(touchA, touchB);
            if (!touchA) continue;
            ++manifolds;
            QCOMPARE(a.normal, b.normal);
            QCOMPARE(a.pointCount, b.pointCount);
            for (int k = 0; k < a.pointCount; ++k) {
                QCOMPARE(a.points[k].pointA, b.points[k].pointA);
                QCOMPARE(a.points[k].separation, b.points[k].separation);
                QCOMPARE(a.points[k].featureId, b.points[k].featureId);
            }
        }
    }
    QVERIFY(manifolds > 200);
}

QTEST_APPLESS_MAIN(TestTriangleMesh)
#include "test_triangle_mesh.moc"
