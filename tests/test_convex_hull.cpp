// ConvexHull::build: topology (Euler, closed edges, counts of known solids), geometry (every input
// point inside every face plane, outward unit normals, counter-clockwise faces), merging of
// coplanar triangles, rejection of degenerate inputs, and scale independence.
//
// Tolerances: the hull treats points within 1e-5 of the cloud's extent of a plane as on it (or 8
// float ulps of the coordinates' magnitude, when larger), so points may lie that far outside a
// face and merged faces may be that far from planar. The checks allow four times that.

#include "simcore/shapes/convex_hull.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

using namespace simcore;

using PointCloud = std::vector<Vec3>;
Q_DECLARE_METATYPE(PointCloud)

namespace {

// Small deterministic generator, so clouds are identical on every platform and standard library.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    float uniform() {  // [0, 1)
        state_ += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = state_;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return float(z >> 40) / float(1ull << 24);
    }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    Vec3 unitVector() {
        for (;;) {
            const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const float length2 = glm::dot(v, v);
            if (length2 > 1e-4f && length2 <= 1.0f) return v / std::sqrt(length2);
        }
    }
    Quat rotation() {
        const Vec3 axis = unitVector();
        return glm::angleAxis(uniform(0.0f, 2.0f * kPi), axis);
    }

private:
    std::uint64_t state_;
};

PointCloud boxCorners(const Vec3& half, const Vec3& offset = Vec3(0.0f)) {
    PointCloud points;
    for (float x : {-1.0f, 1.0f})
        for (float y : {-1.0f, 1.0f})
            for (float z : {-1.0f, 1.0f}) points.push_back(offset + Vec3(x, y, z) * half);
    return points;
}

PointCloud randomInBall(int count, std::uint64_t seed) {
    Random random(seed);
    PointCloud points;
    for (int i = 0; i < count; ++i) points.push_back(random.unitVector() * std::cbrt(random.uniform()));
    return points;
}

PointCloud randomOnSphere(int count, std::uint64_t seed, float radius = 1.0f) {
    Random random(seed);
    PointCloud points;
    for (int i = 0; i < count; ++i) points.push_back(radius * random.unitVector());
    return points;
}

PointCloud fibonacciSphere(int count) {
    PointCloud points;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double r = std::sqrt(1.0 - y * y);
        points.emplace_back(float(r * std::cos(golden * i)), float(y), float(r * std::sin(golden * i)));
    }
    return points;
}

// Points of an n x n x n lattice on the surface of the cube [-1, 1]^3: many coplanar points per
// face and collinear ones along the edges.
PointCloud cubeSurfaceGrid(int n) {
    PointCloud points;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                if (i != 0 && j != 0 && k != 0 && i != n - 1 && j != n - 1 && k != n - 1) continue;
                const float step = 2.0f / float(n - 1);
                points.emplace_back(-1.0f + step * i, -1.0f + step * j, -1.0f + step * k);
            }
    return points;
}

PointCloud transformed(PointCloud points, const Quat& rotation, const Vec3& offset, float scale = 1.0f) {
    for (Vec3& p : points) p = offset + rotation * (scale * p);
    return points;
}

PointCloud shuffled(PointCloud points, std::uint64_t seed) {
    Random random(seed);
    for (std::size_t i = points.size(); i > 1; --i) {
        std::swap(points[i - 1], points[std::size_t(random.uniform() * float(i)) % i]);
    }
    return points;
}

PointCloud prism(int sides, float halfHeight) {
    PointCloud points;
    for (int i = 0; i < sides; ++i) {
        const float a = 2.0f * kPi * float(i) / float(sides);
        for (float y : {-halfHeight, halfHeight}) points.emplace_back(std::cos(a), y, std::sin(a));
    }
    return points;
}

// Allowed distance off a plane: four times the hull's own tolerance (see the file comment).
float toleranceFor(const PointCloud& points) {
    Vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Vec3 size = hi - lo;
    const Vec3 magnitude = glm::max(glm::abs(lo), glm::abs(hi));
    const float extent = std::max({size.x, size.y, size.z});
    const float largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    return 4.0f * std::max(1e-5f * extent, 8.0f * std::numeric_limits<float>::epsilon() * largest);
}

Vec3 faceVertex(const ConvexHull& hull, const HullFace& face, std::uint32_t k) {
    return hull.vertices()[hull.faceVertexIndices()[face.firstIndex + k % face.vertexCount]];
}

bool faceWalks(const ConvexHull& hull, std::uint32_t faceIndex, std::uint32_t a, std::uint32_t b) {
    const HullFace& face = hull.faces()[faceIndex];
    for (std::uint32_t k = 0; k < face.vertexCount; ++k) {
        if (hull.faceVertexIndices()[face.firstIndex + k] == a &&
            hull.faceVertexIndices()[face.firstIndex + (k + 1) % face.vertexCount] == b) {
            return true;
        }
    }
    return false;
}

// Every structural and geometric property a built hull must have; returns the first violation.
QString hullDefect(const ConvexHull& hull, const PointCloud& points) {
    const float tol = toleranceFor(points);
    const auto& vertices = hull.vertices();
    const auto& faces = hull.faces();
    const auto& edges = hull.edges();
    const auto& indices = hull.faceVertexIndices();

    const long euler = long(vertices.size()) - long(edges.size()) + long(faces.size());
    if (euler != 2) return QString("V - E + F = %1").arg(euler);

    // Hull vertices are input points, each used by at least three faces.
    const std::set<std::tuple<float, float, float>> input = [&] {
        std::set<std::tuple<float, float, float>> s;
        for (const Vec3& p : points) s.emplace(p.x, p.y, p.z);
        return s;
    }();
    std::vector<int> facesAtVertex(vertices.size(), 0);
    for (const Vec3& v : vertices) {
        if (!input.contains({v.x, v.y, v.z})) return "a hull vertex is not an input point";
    }

    Vec3 centroid(0.0f);
    for (const Vec3& v : vertices) centroid += v;
    centroid /= float(vertices.size());

    std::size_t corners = 0;
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        const HullFace& face = faces[f];
        if (face.vertexCount < 3) return QString("face %1 has %2 vertices").arg(f).arg(face.vertexCount);
        if (face.firstIndex + face.vertexCount > indices.size()) return "face indices out of range";
        corners += face.vertexCount;
        if (std::abs(glm::length(face.normal) - 1.0f) > 1e-5f) return QString("face %1 normal is not unit").arg(f);
        if (glm::dot(face.normal, centroid) - face.offset >= 0.0f) {
            return QString("face %1 normal points inwards").arg(f);
        }
        // Counter-clockwise seen from outside: the loop's own (Newell) normal agrees.
        Vec3 loopNormal(0.0f);
        for (std::uint32_t k = 0; k < face.vertexCount; ++k) {
            const std::uint32_t index = indices[face.firstIndex + k];
            if (index >= vertices.size()) return "face vertex index out of range";
            ++facesAtVertex[index];
            loopNormal += glm::cross(faceVertex(hull, face, k) - centroid, faceVertex(hull, face, k + 1) - centroid);
            const float off = glm::dot(face.normal, faceVertex(hull, face, k)) - face.offset;
            if (std::abs(off) > tol) return QString("face %1 vertex is %2 off its plane").arg(f).arg(off);
        }
        if (glm::dot(glm::normalize(loopNormal), face.normal) < 0.99f) {
            return QString("face %1 is not counter-clockwise about its normal").arg(f);
        }
        for (const Vec3& p : points) {
            const float out = glm::dot(face.normal, p) - face.offset;
            if (out > tol) return QString("an input point is %1 outside face %2").arg(out).arg(f);
        }
    }
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        if (facesAtVertex[v] < 3) return QString("vertex %1 is on %2 faces").arg(v).arg(facesAtVertex[v]);
    }

    // Each edge once, walked a -> b by face A and b -> a by face B.
    if (corners != 2 * edges.size()) return "face corners do not match twice the edge count";
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const HullEdge& e : edges) {
        if (e.a >= vertices.size() || e.b >= vertices.size()) return "edge vertex out of range";
        if (!seen.emplace(std::min(e.a, e.b), std::max(e.a, e.b)).second) return "an edge is listed twice";
        if (e.faceA == e.faceB) return "an edge has the same face on both sides";
        if (!faceWalks(hull, e.faceA, e.a, e.b) || !faceWalks(hull, e.faceB, e.b, e.a)) {
            return "an edge does not match its faces";
        }
    }
    return {};
}

}  // namespace

class TestConvexHull : public QObject {
    Q_OBJECT

private slots:
    void boxCornersGiveSixQuads();
    void knownSolidsHaveExpectedCounts_data();
    void knownSolidsHaveExpectedCounts();
    void hullInvariantsHold_data();
    void hullInvariantsHold();
    void randomCloudsSatisfyEuler();
    void degenerateInputsAreRejected_data();
    void degenerateInputsAreRejected();
    void duplicateAndInteriorPointsAreDropped();
    void pointsOnTheSurfaceAreAllKept();
    void supportIsTheFarthestInputPoint();
};

void TestConvexHull::boxCornersGiveSixQuads() {
    const Vec3 half(0.5f, 1.0f, 2.0f);
    const auto result = ConvexHull::build(boxCorners(half));
    QVERIFY2(result.hull, qPrintable(QString::fromStdString(result.error)));
    const ConvexHull& hull = *result.hull;
    QCOMPARE(hull.vertices().size(), std::size_t(8));
    QCOMPARE(hull.faces().size(), std::size_t(6));
    QCOMPARE(hull.edges().size(), std::size_t(12));
    for (const HullFace& face : hull.faces()) {
        QCOMPARE(face.vertexCount, 4u);
        // Axis-aligned outward normal, plane at the half extent along it.
        int axis = 0;
        for (int i = 1; i < 3; ++i) {
            if (std::abs(face.normal[i]) > std::abs(face.normal[axis])) axis = i;
        }
        QVERIFY(std::abs(std::abs(face.normal[axis]) - 1.0f) < 1e-6f);
        QVERIFY(std::abs(face.offset - half[axis]) < 1e-6f);
    }
    QVERIFY2(hullDefect(hull, boxCorners(half)).isEmpty(), qPrintable(hullDefect(hull, boxCorners(half))));
}

void TestConvexHull::knownSolidsHaveExpectedCounts_data() {
    QTest::addColumn<PointCloud>("points");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("faces");
    QTest::addColumn<int>("edges");

    Random random(7);
    const Quat tilt = random.rotation();
    PointCloud cornersRepeated;
    for (int copy = 0; copy < 5; ++copy) {
        for (const Vec3& p : boxCorners(Vec3(1.0f))) cornersRepeated.push_back(p);
    }

    QTest::newRow("tetrahedron") << PointCloud{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}} << 4 << 4 << 6;
    QTest::newRow("box corners") << boxCorners(Vec3(1.0f, 2.0f, 3.0f)) << 8 << 6 << 12;
    QTest::newRow("box corners repeated") << shuffled(cornersRepeated, 1) << 8 << 6 << 12;
    QTest::newRow("cube surface grid 11^3") << cubeSurfaceGrid(11) << 8 << 6 << 12;
    QTest::newRow("cube surface grid shuffled") << shuffled(cubeSurfaceGrid(21), 2) << 8 << 6 << 12;
    QTest::newRow("cube surface grid rotated") << transformed(shuffled(cubeSurfaceGrid(9), 3), tilt, Vec3(0.3f, -2.0f, 5.0f)) << 8 << 6 << 12;
    QTest::newRow("cube grid scale 1e-3") << transformed(cubeSurfaceGrid(7), Quat(1, 0, 0, 0), Vec3(0.0f), 1e-3f) << 8 << 6 << 12;
    QTest::newRow("cube grid scale 1e3") << transformed(cubeSurfaceGrid(7), Quat(1, 0, 0, 0), Vec3(0.0f), 1e3f) << 8 << 6 << 12;
    QTest::newRow("octahedron") << PointCloud{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}} << 6 << 8 << 12;
    QTest::newRow("hexagonal prism") << prism(6, 0.5f) << 12 << 8 << 18;
    QTest::newRow("64-gon prism") << shuffled(prism(64, 1.0f), 4) << 128 << 66 << 192;

    // Square pyramid whose base is a 11 x 11 grid: only the base corners survive.
    PointCloud pyramid{{0.0f, 1.0f, 0.0f}};
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) pyramid.emplace_back(-1.0f + 0.2f * i, 0.0f, -1.0f + 0.2f * j);
    QTest::newRow("pyramid over grid") << pyramid << 5 << 5 << 8;
}

void TestConvexHull::knownSolidsHaveExpectedCounts() {
    QFETCH(PointCloud, points);
    QFETCH(int, vertices);
    QFETCH(int, faces);
    QFETCH(int, edges);

    const auto result = ConvexHull::build(points);
    QVERIFY2(result.hull, qPrintable(QString::fromStdString(result.error)));
    QCOMPARE(int(result.hull->vertices().size()), vertices);
    QCOMPARE(int(result.hull->faces().size()), faces);
    QCOMPARE(int(result.hull->edges().size()), edges);
    const QString defect = hullDefect(*result.hull, points);
    QVERIFY2(defect.isEmpty(), qPrintable(defect));
}

void TestConvexHull::hullInvariantsHold_data() {
    QTest::addColumn<PointCloud>("points");

    Random random(11);
    QTest::newRow("random in ball 100") << randomInBall(100, 1);
    QTest::newRow("random in ball 2000") << randomInBall(2000, 2);
    QTest::newRow("random on sphere 1000") << randomOnSphere(1000, 3);
    QTest::newRow("fibonacci sphere 2000") << fibonacciSphere(2000);
    QTest::newRow("sphere scale 1e-3") << randomOnSphere(1000, 4, 1e-3f);
    QTest::newRow("sphere scale 1e3") << randomOnSphere(1000, 5, 1e3f);
    QTest::newRow("sphere far from origin") << transformed(randomOnSphere(500, 6), Quat(1, 0, 0, 0), Vec3(100.0f, -50.0f, 20.0f));
    QTest::newRow("rotated cylinder, 5 rings") << [&] {
        PointCloud points;
        for (int i = 0; i < 48; ++i) {
            const float a = 2.0f * kPi * float(i) / 48.0f;
            for (int ring = 0; ring < 5; ++ring) points.emplace_back(std::cos(a), -1.0f + 0.5f * ring, std::sin(a));
        }
        return transformed(shuffled(points, 7), random.rotation(), Vec3(0.0f));
    }();
    QTest::newRow("noisy cube grid") << [&] {
        PointCloud points = cubeSurfaceGrid(9);
        for (Vec3& p : points) p += 3e-5f * Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        return points;
    }();
    QTest::newRow("random on box faces") << [&] {
        PointCloud points;
        for (int i = 0; i < 2000; ++i) {
            Vec3 p(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
            p[i % 3] = (i / 3) % 2 ? 1.0f : -1.0f;
            points.push_back(p);
        }
        return points;
    }();
}

void TestConvexHull::hullInvariantsHold() {
    QFETCH(PointCloud, points);
    const auto result = ConvexHull::build(points);
    QVERIFY2(result.hull, qPrintable(QString::fromStdString(result.error)));
    const QString defect = hullDefect(*result.hull, points);
    QVERIFY2(defect.isEmpty(), qPrintable(defect));
}

void TestConvexHull::randomCloudsSatisfyEuler() {
    // Many small clouds of varied size and shape: a quick net for rare topological failures.
    Random random(2024);
    for (int trial = 0; trial < 200; ++trial) {
        const int count = 4 + int(random.uniform() * 300.0f);
        const Vec3 stretch(random.uniform(0.1f, 3.0f), random.uniform(0.1f, 3.0f), random.uniform(0.1f, 3.0f));
        PointCloud points;
        for (int i = 0; i < count; ++i) {
            Vec3 p(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
            if (trial % 2) p = glm::round(p * 3.0f) / 3.0f;  // lattice points: coplanar and collinear subsets
            points.push_back(stretch * p);
        }
        const auto result = ConvexHull::build(points);
        if (!result.hull) {
            // Tiny lattice clouds can genuinely be flat; nothing else may fail.
            QVERIFY2(count < 12 && result.error.find("no volume") != std::string::npos,
                     qPrintable(QString("trial %1: %2").arg(trial).arg(QString::fromStdString(result.error))));
            continue;
        }
        const QString defect = hullDefect(*result.hull, points);
        QVERIFY2(defect.isEmpty(), qPrintable(QString("trial %1: %2").arg(trial).arg(defect)));
    }
}

void TestConvexHull::degenerateInputsAreRejected_data() {
    QTest::addColumn<PointCloud>("points");
    QTest::addColumn<QString>("error");

    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();

    PointCloud coplanarGrid;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) coplanarGrid.emplace_back(float(i), 2.0f, float(j));
    PointCloud tiltedPlane;  // the plane x + y + z = 1, coplanar up to float rounding
    Random random(5);
    for (int i = 0; i < 50; ++i) {
        const float x = random.uniform(-1, 1), y = random.uniform(-1, 1);
        tiltedPlane.emplace_back(x, y, 1.0f - x - y);
    }
    PointCloud collinear;
    for (int i = 0; i < 10; ++i) collinear.emplace_back(1.0f + 0.5f * i, 2.0f - 0.25f * i, 3.0f + i);

    QTest::newRow("no points") << PointCloud{} << "a convex hull needs at least 4 points, got 0";
    QTest::newRow("3 points") << PointCloud{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}} << "a convex hull needs at least 4 points, got 3";
    QTest::newRow("coplanar grid") << coplanarGrid << "the points are coplanar: the hull has no volume";
    QTest::newRow("tilted plane") << tiltedPlane << "the points are coplanar: the hull has no volume";
    QTest::newRow("collinear") << collinear << "the points are collinear: the hull has no volume";
    QTest::newRow("all duplicates") << PointCloud(6, Vec3(1.5f, -2.0f, 0.25f)) << "all points are coincident: the hull has no volume";
    QTest::newRow("NaN") << PointCloud{{0, 0, 0}, {1, 0, 0}, {0, nan, 0}, {0, 0, 1}} << "point 2 has a non-finite coordinate";
    QTest::newRow("infinity") << PointCloud{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {inf, 0, 0}} << "point 5 has a non-finite coordinate";
}

void TestConvexHull::degenerateInputsAreRejected() {
    QFETCH(PointCloud, points);
    QFETCH(QString, error);
    const auto result = ConvexHull::build(points);
    QVERIFY(!result.hull);
    QCOMPARE(QString::fromStdString(result.error), error);
}

void TestConvexHull::duplicateAndInteriorPointsAreDropped() {
    PointCloud points;
    for (int copy = 0; copy < 3; ++copy) {
        for (const Vec3& p : boxCorners(Vec3(2.0f, 1.0f, 0.5f))) points.push_back(p);
    }
    for (const Vec3& p : randomInBall(300, 9)) points.push_back(p * Vec3(1.9f, 0.9f, 0.45f));
    points = shuffled(points, 10);

    const auto result = ConvexHull::build(points);
    QVERIFY2(result.hull, qPrintable(QString::fromStdString(result.error)));
    const ConvexHull& hull = *result.hull;
    QCOMPARE(hull.vertices().size(), std::size_t(8));
    QCOMPARE(hull.faces().size(), std::size_t(6));
    for (const Vec3& v : hull.vertices()) {
        QCOMPARE(glm::abs(v), Vec3(2.0f, 1.0f, 0.5f));
    }
    // The input is kept exactly, duplicates and interior points included.
    QCOMPARE(hull.sourcePoints().size(), points.size());
    QVERIFY(hull.sourcePoints() == points);
    const QString defect = hullDefect(hull, points);
    QVERIFY2(defect.isEmpty(), qPrintable(defect));
}

void TestConvexHull::pointsOnTheSurfaceAreAllKept() {
    // Points of a Fibonacci sphere are all extreme, and far enough apart to clear the tolerance.
    const PointCloud points = fibonacciSphere(2000);
    const auto result = ConvexHull::build(points);
    QVERIFY(result.hull);
    QCOMPARE(result.hull->vertices().size(), points.size());
}

void TestConvexHull::supportIsTheFarthestInputPoint() {
    const PointCloud points = randomInBall(500, 12);
    const auto result = ConvexHull::build(points);
    QVERIFY(result.hull);
    const float tol = toleranceFor(points);
    for (const Vec3& direction : fibonacciSphere(300)) {
        const Vec3 s = result.hull->support(2.5f * direction);
        float farthest = -std::numeric_limits<float>::max();
        for (const Vec3& p : points) farthest = std::max(farthest, glm::dot(p, direction));
        QVERIFY(std::abs(glm::dot(s, direction) - farthest) <= tol);
        QVERIFY(std::find(result.hull->vertices().begin(), result.hull->vertices().end(), s) !=
                result.hull->vertices().end());
    }
}

QTEST_APPLESS_MAIN(TestConvexHull)
#include "test_convex_hull.moc"
