// Ray casts against single shapes.
//
// Table: hand-computed hits on every feature of every shape type (faces, caps, curved sides,
// hemispherical ends, grazing rays), each also checked with the whole scene moved by a rigid
// transform and with the direction rescaled; and misses (parallel outside a face, beyond
// maxFraction, pointing away, passing a corner the bounding box would not rule out). Every hit is
// checked to be finite, on the ray, on the surface (the normal's supporting plane passes through
// it), with a unit outward normal.
// Random: rays against random shapes compared with a brute-force march along the ray that only
// uses a point-containment test written here; a box-shaped hull must give the box's hits.
// Plus: origins inside or on the surface, degenerate input, and no heap allocation.

#include "support/allocation_counter.h"
#include "support/geometry.h"
#include "simcore/collision/ray_cast.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/shape.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace simcore;
using namespace test_support;

namespace {

// ---- Helpers -------------------------------------------------------------------------------------

const Vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);
constexpr float kSqrtHalf = 0.70710678f;

RayCastInput ray(const Vec3& origin, const Vec3& direction, float maxFraction = 1.0f) {
    return {origin, direction, maxFraction};
}

// Square base [-1, 1]^2 at y = 0, apex at (0, 2, 0).
Shape pyramid() { return Shape::convexHull(buildHull({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 2, 0}})); }

// Containment, written independently of the ray code: the reference the march relies on.
bool contains(const Shape& shape, const Transform& t, const Vec3& world) {
    const Vec3 p = t.applyInverse(world);
    switch (shape.type) {
        case ShapeType::Sphere: return glm::dot(p, p) <= shape.radius * shape.radius;
        case ShapeType::Box:
            return std::abs(p.x) <= shape.halfExtents.x && std::abs(p.y) <= shape.halfExtents.y &&
                   std::abs(p.z) <= shape.halfExtents.z;
        case ShapeType::Capsule: {
            const Vec3 axisPoint(0.0f, std::clamp(p.y, -shape.halfHeight, shape.halfHeight), 0.0f);
            const Vec3 offset = p - axisPoint;
            return glm::dot(offset, offset) <= shape.radius * shape.radius;
        }
        case ShapeType::Cylinder:
            return std::abs(p.y) <= shape.halfHeight && p.x * p.x + p.z * p.z <= shape.radius * shape.radius;
        case ShapeType::ConvexHull:
            for (const HullFace& f : shape.hull->faces()) {
                if (glm::dot(f.normal, p) > f.offset) return false;
            }
            return true;
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // not convex: cast in test_compound and test_mesh_bodies
    }
    return false;
}

bool isFiniteHit(const RayCastHit& hit) { return isFinite(hit.fraction) && isFinite(hit.point) && isFinite(hit.normal); }

// Checks what every hit must satisfy; returns an empty string or the first failure.
std::string hitDefect(const Shape& shape, const Transform& t, const RayCastInput& r, const RayCastHit& hit,
                      float tolerance, bool grazing) {
    if (!isFiniteHit(hit)) return "non-finite hit";
    if (hit.fraction < 0.0f || hit.fraction > r.maxFraction) return "fraction outside [0, maxFraction]";
    if (glm::length(hit.point - (r.origin + hit.fraction * r.direction)) > tolerance) return "point not on the ray";
    if (std::abs(glm::length(hit.normal) - 1.0f) > 1e-5f) return "normal not unit";
    const float facing = glm::dot(hit.normal, glm::normalize(r.direction));
    if (grazing ? facing > 1e-3f : !(facing < 0.0f)) return "normal not against the ray";
    // Supporting plane through the hit: true for the outward normal at any point of a convex surface.
    if (std::abs(glm::dot(hit.normal, hit.point) - extentAlong(shape, t, hit.normal)) > tolerance) {
        return "point not on the normal's supporting plane";
    }
    if (std::abs(outsideBy(shape, t, hit.point)) > tolerance) return "point not on the surface";
    if (shape.type == ShapeType::Sphere &&
        std::abs(glm::length(hit.point - t.position) - shape.radius) > tolerance) {
        return "point not at the radius from the centre";
    }
    return {};
}

// ---- Table cases ---------------------------------------------------------------------------------

struct RayCase {
    Shape shape;
    Transform transform;
    RayCastInput ray;
    bool hit = false;
    float fraction = 0.0f;
    Vec3 normal{0.0f};        // world
    bool grazing = false;     // tangent ray: the normal is perpendicular to it
    bool movable = true;      // survives the rounding of a scene transform (not on a boundary)
    float tolerance = 1e-5f;  // m, on the hit point and the fraction times |direction|
};

}  // namespace

Q_DECLARE_METATYPE(RayCase)

class TestRayCast : public QObject {
    Q_OBJECT

private slots:
    void hits_data();
    void hits();
    void misses_data();
    void misses();
    void originInsideOrOnSurface();
    void degenerateInput();
    void randomAgainstMarch();
    void boxHullMatchesBox();
    void noHeapAllocation();
};

namespace {

RayCase hitCase(const Shape& shape, const Transform& t, const RayCastInput& r, float fraction, const Vec3& normal) {
    RayCase c;
    c.shape = shape;
    c.transform = t;
    c.ray = r;
    c.hit = true;
    c.fraction = fraction;
    c.normal = glm::normalize(normal);
    return c;
}

RayCase grazingCase(const Shape& shape, const Transform& t, const RayCastInput& r, float fraction, const Vec3& normal) {
    RayCase c = hitCase(shape, t, r, fraction, normal);
    c.grazing = true;
    c.movable = false;
    return c;
}

RayCase missCase(const Shape& shape, const Transform& t, const RayCastInput& r) {
    RayCase c;
    c.shape = shape;
    c.transform = t;
    c.ray = r;
    return c;
}

// Adds the case, and unless it sits on a boundary (a tangent ray, or a hit exactly at maxFraction:
// neither survives the rounding of a rotation), the same scene moved by an arbitrary rigid
// transform: the answer must not care.
void addCase(const char* name, const RayCase& c) {
    QTest::newRow(name) << c;
    if (!c.movable) return;
    const Transform scene = place(Vec3(3.7f, -12.25f, 21.5f), rotation(63.0f, Vec3(0.3f, -1.0f, 0.55f)));
    RayCase moved = c;
    moved.transform = compose(scene, c.transform);
    moved.ray.origin = scene.apply(c.ray.origin);
    moved.ray.direction = scene.rotate(c.ray.direction);
    moved.normal = scene.rotate(c.normal);
    // Coordinates of about 25 m: a few ulps there are 1e-5 m.
    moved.tolerance = std::max(c.tolerance, 3e-5f);
    QTest::newRow((std::string(name) + " (moved)").c_str()) << moved;
}

const Transform kOrigin = place(Vec3(0.0f));

}  // namespace

void TestRayCast::hits_data() {
    QTest::addColumn<RayCase>("c");
    const Shape sphere = Shape::sphere(1.0f);
    const Shape box = Shape::box({1.0f, 0.5f, 2.0f});
    const Shape capsule = Shape::capsule(0.5f, 1.0f);
    const Shape cylinder = Shape::cylinder(0.5f, 1.0f);

    // Spheres.
    addCase("sphere centre-on", hitCase(sphere, kOrigin, ray({-3, 0, 0}, {4, 0, 0}), 0.5f, -kX));
    addCase("sphere off-centre", hitCase(sphere, kOrigin, ray({-5, 0.6f, 0}, {10, 0, 0}), 0.42f, {-0.8f, 0.6f, 0}));
    addCase("sphere translated", hitCase(Shape::sphere(0.5f), place({2, 3, 4}), ray({2, 3, 10}, -kZ, 10), 5.5f, kZ));
    addCase("sphere diagonal", hitCase(sphere, kOrigin, ray({6, 8, 0}, {-0.6f, -0.8f, 0}, 20), 9.0f, {0.6f, 0.8f, 0}));
    addCase("sphere grazing", grazingCase(sphere, kOrigin, ray({-5, 1, 0}, kX, 10), 5.0f, kY));
    {
        RayCase atLimit = hitCase(sphere, kOrigin, ray({-3, 0, 0}, kX, 2), 2.0f, -kX);
        atLimit.movable = false;
        addCase("sphere hit exactly at maxFraction", atLimit);
    }

    // Boxes: the entering slab's face.
    addCase("box +x face", hitCase(box, kOrigin, ray({5, 0.2f, -1}, -kX, 10), 4.0f, kX));
    addCase("box -y face", hitCase(box, kOrigin, ray({0.3f, -3, 1.5f}, {0, 2, 0}, 2), 1.25f, -kY));
    addCase("box +z face oblique", hitCase(box, kOrigin, ray({0, 0, 5}, {0.2f, 0.1f, -1}, 5), 3.0f, kZ));
    {
        // Cube turned 45 degrees about z: a diamond |x'| + |y'| <= sqrt(2) in the xy plane.
        const Transform diamond = place({10, 0, 0}, rotation(45, kZ));
        addCase("box rotated face", hitCase(Shape::box(Vec3(1.0f)), diamond, ray({0, 0.3f, 0}, kX, 20),
                                            10.3f - std::sqrt(2.0f), {-kSqrtHalf, kSqrtHalf, 0}));
    }
    addCase("box rotated and translated",
            hitCase(box, place({1, 2, 3}, rotation(90, kX)), ray({1.5f, 2.2f, 10}, -kZ, 10), 6.5f, kZ));
    addCase("box grazing along top face", grazingCase(box, kOrigin, ray({-5, 0.5f, 0}, kX, 10), 4.0f, -kX));

    // Capsules (segment along local y).
    addCase("capsule side", hitCase(capsule, kOrigin, ray({-3, 0.4f, 0}, kX, 5), 2.5f, -kX));
    addCase("capsule top pole", hitCase(capsule, kOrigin, ray({0, 5, 0}, -kY, 5), 3.5f, kY));
    addCase("capsule top hemisphere oblique",
            hitCase(capsule, kOrigin, ray({-3, 1.3f, 0}, kX, 5), 2.6f, {-0.8f, 0.6f, 0}));
    addCase("capsule bottom hemisphere",
            hitCase(capsule, kOrigin, ray({0, -1.4f, -4}, {0, 0, 2}, 5), 1.85f, {0, -0.8f, -0.6f}));
    {
        // Lying along world x: local y goes to -x.
        const Transform lying = place({0, 0, 5}, rotation(90, kZ));
        addCase("capsule lying, end", hitCase(capsule, lying, ray({3, 0, 5}, -kX, 5), 1.5f, kX));
        addCase("capsule lying, side", hitCase(capsule, lying, ray({0.7f, 4, 5}, -kY, 5), 3.5f, kY));
    }
    addCase("capsule grazing side", grazingCase(capsule, kOrigin, ray({-3, 0, 0.5f}, kX, 5), 3.0f, kZ));

    // Cylinders (axis along local y).
    addCase("cylinder side", hitCase(cylinder, kOrigin, ray({0.3f, 0.2f, -4}, kZ, 5), 3.6f, {0.6f, 0, -0.8f}));
    addCase("cylinder top cap", hitCase(cylinder, kOrigin, ray({0.2f, 3, 0.1f}, {0, -0.5f, 0}, 5), 4.0f, kY));
    addCase("cylinder bottom cap oblique", hitCase(cylinder, kOrigin, ray({0, -3, 0}, {0.1f, 1, 0}, 5), 2.0f, -kY));
    addCase("cylinder side past the cap plane",
            hitCase(cylinder, kOrigin, ray({-2, 1.5f, 0}, {1, -0.5f, 0}, 5), 1.5f, -kX));
    // Near the rim, the feature entered last decides the normal.
    addCase("cylinder side just below the rim",
            hitCase(cylinder, kOrigin, ray({-2.5f, 1.998f, 0}, {1, -0.5f, 0}, 5), 2.0f, -kX));
    addCase("cylinder cap just inside the rim",
            hitCase(cylinder, kOrigin, ray({-1.498f, 3, 0}, {0.5f, -1, 0}, 5), 2.0f, kY));
    addCase("cylinder rotated cap",
            hitCase(cylinder, place({1, 2, 3}, rotation(90, kX)), ray({1.2f, 2.1f, 10}, -kZ, 10), 6.0f, kZ));
    addCase("cylinder grazing side", grazingCase(cylinder, kOrigin, ray({-3, 0.5f, 0.5f}, kX, 5), 3.0f, kZ));

    // Convex hulls.
    addCase("octahedron face",
            hitCase(octahedron(1.0f), kOrigin, ray({0.2f, 0.1f, 5}, -kZ, 10), 4.3f, {1, 1, 1}));
    addCase("pyramid base", hitCase(pyramid(), kOrigin, ray({0, -3, 0.2f}, kY, 5), 3.0f, -kY));
    addCase("pyramid slanted face", hitCase(pyramid(), kOrigin, ray({-3, 0.5f, 0}, kX, 5), 2.25f, {-2, 1, 0}));
    addCase("pyramid translated and rotated",
            hitCase(pyramid(), place({0, 0, 4}, rotation(180, kX)), ray({0, 5, 4.2f}, -kY, 10), 5.0f, kY));
}

void TestRayCast::hits() {
    QFETCH(RayCase, c);
    // Also with the direction rescaled: the fraction must scale inversely, nothing else may change.
    for (const float scale : {1.0f, 0.01f, 37.0f}) {
        RayCastInput r = c.ray;
        r.direction *= scale;
        r.maxFraction /= scale;
        const QString which = QStringLiteral("direction x%1: ").arg(scale);
        const std::optional<RayCastHit> hit = rayCastShape(c.shape, c.transform, r);
        QVERIFY2(hit.has_value(), qPrintable(which + "missed"));
        const float expectedFraction = c.fraction / scale;
        const float distanceError = std::abs(hit->fraction - expectedFraction) * glm::length(r.direction);
        QVERIFY2(distanceError <= c.tolerance,
                 qPrintable(which + QStringLiteral("fraction %1, expected %2").arg(hit->fraction).arg(expectedFraction)));
        const Vec3 expectedPoint = c.ray.origin + c.fraction * c.ray.direction;
        QVERIFY2(glm::length(hit->point - expectedPoint) <= c.tolerance, qPrintable(which + "wrong point"));
        QVERIFY2(glm::length(hit->normal - c.normal) <= 1e-5f + c.tolerance,
                 qPrintable(which + QStringLiteral("normal (%1, %2, %3)")
                                        .arg(hit->normal.x).arg(hit->normal.y).arg(hit->normal.z)));
        const std::string defect = hitDefect(c.shape, c.transform, r, *hit, c.tolerance, c.grazing);
        QVERIFY2(defect.empty(), qPrintable(which + QString::fromStdString(defect)));
    }
    if (!c.grazing) {
        // Stopping just short of the hit misses it.
        RayCastInput shortRay = c.ray;
        shortRay.maxFraction = c.fraction - 1e-3f / glm::length(c.ray.direction);
        QVERIFY(!rayCastShape(c.shape, c.transform, shortRay));
    }
}

void TestRayCast::misses_data() {
    QTest::addColumn<RayCase>("c");
    const Shape sphere = Shape::sphere(1.0f);
    const Shape box = Shape::box({1.0f, 0.5f, 2.0f});
    const Shape capsule = Shape::capsule(0.5f, 1.0f);
    const Shape cylinder = Shape::cylinder(0.5f, 1.0f);
    const Shape hull = octahedron(1.0f);

    addCase("sphere pointing away", missCase(sphere, kOrigin, ray({-3, 0, 0}, -kX, 10)));
    addCase("sphere beyond maxFraction", missCase(sphere, kOrigin, ray({-3, 0, 0}, kX, 1.99f)));
    addCase("sphere passing just outside", missCase(sphere, kOrigin, ray({-3, 1.01f, 0}, kX, 10)));

    addCase("box parallel to face, outside", missCase(box, kOrigin, ray({-5, 0.51f, 0}, kX, 10)));
    addCase("box pointing away", missCase(box, kOrigin, ray({5, 0, 0}, kX, 10)));
    addCase("box beyond maxFraction", missCase(box, kOrigin, ray({5, 0, 0}, -kX, 3.99f)));
    addCase("box passing a corner", missCase(box, kOrigin, ray({-2, 0, 0}, {1, 1, 0}, 10)));
    addCase("box behind the origin", missCase(box, kOrigin, ray({0, 0, 5}, {0, 0, 1}, 100)));

    addCase("capsule parallel to axis, outside", missCase(capsule, kOrigin, ray({0.51f, -5, 0}, kY, 10)));
    addCase("capsule above top pole", missCase(capsule, kOrigin, ray({-3, 1.51f, 0}, kX, 10)));
    // The infinite cylinder is crossed (radial distance 0.25) but above the segment; the end sphere
    // is passed at 0.515.
    addCase("capsule past the hemisphere", missCase(capsule, kOrigin, ray({-3, 1.45f, 0.25f}, kX, 10)));
    addCase("capsule beyond maxFraction", missCase(capsule, kOrigin, ray({0, 5, 0}, -kY, 3.49f)));

    addCase("cylinder parallel to axis, outside", missCase(cylinder, kOrigin, ray({0.51f, -5, 0}, kY, 10)));
    addCase("cylinder above the cap", missCase(cylinder, kOrigin, ray({-3, 1.01f, 0}, kX, 10)));
    // Side interval and slab interval of the line are disjoint: it passes the rim outside.
    addCase("cylinder passing the rim", missCase(cylinder, kOrigin, ray({-3.6f, -1.9f, 0}, {1, 1, 0}, 10)));
    addCase("cylinder pointing away", missCase(cylinder, kOrigin, ray({0, 3, 0}, kY, 10)));

    // Inside the octahedron's bounding box, outside the octahedron.
    addCase("octahedron inside its bounds", missCase(hull, kOrigin, ray({0.6f, 0.6f, 5}, -kZ, 10)));
    addCase("octahedron beyond maxFraction", missCase(hull, kOrigin, ray({0.2f, 0.1f, 5}, -kZ, 4.29f)));
    addCase("pyramid parallel to base, below", missCase(pyramid(), kOrigin, ray({-3, -0.01f, 0}, kX, 10)));
    addCase("pyramid pointing away", missCase(pyramid(), kOrigin, ray({-3, 0.5f, 0}, -kX, 10)));
}

void TestRayCast::misses() {
    QFETCH(RayCase, c);
    QVERIFY(!rayCastShape(c.shape, c.transform, c.ray));
}

void TestRayCast::originInsideOrOnSurface() {
    const Transform t = place({0.5f, -1, 2}, rotation(35, {1, 2, -1}));
    const std::vector<Shape> shapes = {Shape::sphere(0.7f), Shape::box({0.5f, 0.3f, 0.8f}), Shape::capsule(0.4f, 0.6f),
                                       Shape::cylinder(0.4f, 0.6f), octahedron(0.8f), pyramid()};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (const Shape& shape : shapes) {
        const QString name = QString::fromLatin1(shapeTypeName(shape.type).data());
        // Interior points (scaled copies of support points towards the shape's interior point):
        // never a hit, in any direction.
        const Vec3 inner = shape.type == ShapeType::ConvexHull ? 0.25f * (support(shape, kY) + support(shape, -kY))
                                                               : Vec3(0.0f);
        for (int i = 0; i < 200; ++i) {
            const Vec3 towards = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
            const Vec3 local = inner + 0.9f * (support(shape, towards) - inner) * (0.5f + 0.5f * std::abs(unit(rng)));
            const Vec3 origin = t.apply(local);
            QVERIFY(contains(shape, t, origin));
            const Vec3 direction = Vec3(unit(rng), unit(rng), unit(rng));
            QVERIFY2(!rayCastShape(shape, t, ray(origin, direction, 100)), qPrintable(name + ": hit from inside"));
        }
        // On the surface: heading in hits at fraction 0, heading out does not.
        const Vec3 outward = glm::normalize(Vec3(0.3f, 1.0f, 0.2f));
        const Vec3 surfacePoint = t.apply(support(shape, t.rotateInverse(outward)));
        const std::optional<RayCastHit> in = rayCastShape(shape, t, ray(surfacePoint + 1e-3f * outward, -outward, 1));
        QVERIFY2(in && in->fraction <= 1.1e-3f && glm::dot(in->normal, outward) > 0.0f,
                 qPrintable(name + ": entering from the surface"));
        QVERIFY2(!rayCastShape(shape, t, ray(surfacePoint + 1e-4f * outward, outward, 10)),
                 qPrintable(name + ": leaving from just outside"));
    }
    // Exactly on an axis-aligned face: fraction 0 inwards, nothing outwards.
    const Shape box = Shape::box({1.0f, 0.5f, 2.0f});
    const std::optional<RayCastHit> atFace = rayCastShape(box, kOrigin, ray({1, 0.1f, 0.2f}, -kX, 1));
    QVERIFY(atFace);
    QCOMPARE(atFace->fraction, 0.0f);
    QCOMPARE(atFace->normal, kX);
    QVERIFY(!rayCastShape(box, kOrigin, ray({1, 0.1f, 0.2f}, kX, 1)));
    const std::optional<RayCastHit> atPole = rayCastShape(Shape::sphere(1.0f), kOrigin, ray({0, 1, 0}, -kY, 1));
    QVERIFY(atPole);
    QCOMPARE(atPole->fraction, 0.0f);
    QVERIFY(!rayCastShape(Shape::sphere(1.0f), kOrigin, ray({0, 1, 0}, kY, 1)));
}

void TestRayCast::degenerateInput() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<Shape> shapes = {Shape::sphere(1.0f), Shape::box(Vec3(1.0f)), Shape::capsule(1.0f, 1.0f),
                                       Shape::cylinder(1.0f, 1.0f), octahedron(1.0f)};
    for (const Shape& shape : shapes) {
        const QString name = QString::fromLatin1(shapeTypeName(shape.type).data());
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({-5, 0, 0}, Vec3(0.0f), 10)), qPrintable(name + ": zero direction"));
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({-5, 0, 0}, {nan, 0, 0}, 10)), qPrintable(name + ": NaN direction"));
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({nan, 0, 0}, kX, 10)), qPrintable(name + ": NaN origin"));
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({-inf, 0, 0}, kX, 10)), qPrintable(name + ": infinite origin"));
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({-5, 0, 0}, kX, nan)), qPrintable(name + ": NaN maxFraction"));
        QVERIFY2(!rayCastShape(shape, kOrigin, ray({-5, 0, 0}, kX, -1)), qPrintable(name + ": negative maxFraction"));
        QVERIFY2(!rayCastShape(shape, place({nan, 0, 0}), ray({-5, 0, 0}, kX, 10)), qPrintable(name + ": NaN transform"));

        // Unbounded, tiny and huge directions all find the face at x = -1 (fraction in their units).
        const std::optional<RayCastHit> unbounded = rayCastShape(shape, kOrigin, ray({-5, 0.01f, 0}, kX, inf));
        // (The octahedron's vertex is 0.01 behind its support point at y = 0.01.)
        QVERIFY2(unbounded && std::abs(unbounded->fraction - (5.0f - std::abs(support(shape, -kX).x))) < 2e-2f,
                 qPrintable(name + ": unbounded ray"));
        const std::optional<RayCastHit> tiny = rayCastShape(shape, kOrigin, ray({-5, 0.01f, 0}, 1e-30f * kX, 1e31f));
        QVERIFY2(tiny && isFiniteHit(*tiny) && std::abs(tiny->fraction * 1e-30f - unbounded->fraction) < 1e-3f,
                 qPrintable(name + ": tiny direction"));
        const std::optional<RayCastHit> huge = rayCastShape(shape, kOrigin, ray({-5, 0.01f, 0}, 1e30f * kX, 1));
        QVERIFY2(huge && isFiniteHit(*huge) && std::abs(huge->fraction * 1e30f - unbounded->fraction) < 1e-3f,
                 qPrintable(name + ": huge direction"));
    }
    Shape noHull;
    noHull.type = ShapeType::ConvexHull;
    QVERIFY(!rayCastShape(noHull, kOrigin, ray({-5, 0, 0}, kX, 10)));
    QVERIFY(!rayCastShape(Shape::sphere(0.0f), kOrigin, ray({-5, 0, 0}, kX, 10)));
}

namespace {

Shape randomShape(std::mt19937& rng) {
    std::uniform_real_distribution<float> dimension(0.05f, 1.5f);
    std::uniform_int_distribution<int> kind(0, kShapeTypeCount - 1);
    switch (static_cast<ShapeType>(kind(rng))) {
        case ShapeType::Sphere: return Shape::sphere(dimension(rng));
        case ShapeType::Box: return Shape::box({dimension(rng), dimension(rng), dimension(rng)});
        case ShapeType::Capsule: return Shape::capsule(dimension(rng), dimension(rng));
        case ShapeType::Cylinder: return Shape::cylinder(dimension(rng), dimension(rng));
        case ShapeType::ConvexHull: {
            std::normal_distribution<float> gauss(0.0f, 1.0f);
            const Vec3 stretch(dimension(rng), dimension(rng), dimension(rng));
            std::vector<Vec3> points;
            for (int i = 0; i < 24; ++i) points.push_back(stretch * Vec3(gauss(rng), gauss(rng), gauss(rng)));
            return Shape::convexHull(buildHull(points));
        }
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // kind covers the convex types only
    }
    return Shape::sphere(1.0f);
}

Quat randomRotation(std::mt19937& rng) {
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    return glm::normalize(Quat(gauss(rng), gauss(rng), gauss(rng), gauss(rng)));
}

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    Vec3 v(0.0f);
    while (lengthSquared(v) < 1e-6f) v = Vec3(gauss(rng), gauss(rng), gauss(rng));
    return glm::normalize(v);
}

}  // namespace

// The march steps along the segment and reports the first sample inside the shape. A true entry at
// t lies in (previous sample, first inside sample], so the fractions must agree within one step.
// Two outcomes are legitimately different and are only accepted when the geometry says so:
//   - the cast hits but no sample lands inside: the chord is shorter than a step, so the ray
//     passes within a step of the surface;
//   - samples land inside but the cast misses: only by rounding, so no sample is deeper than 1e-5.
void TestRayCast::randomAgainstMarch() {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    constexpr int kRays = 2000;
    constexpr int kSteps = 8000;
    int hits = 0, grazingDisagreements = 0;
    for (int i = 0; i < kRays; ++i) {
        const Shape shape = randomShape(rng);
        const Transform t = place(Vec3(20.0f * unit(rng) - 10.0f, 20.0f * unit(rng) - 10.0f, 20.0f * unit(rng) - 10.0f),
                                  randomRotation(rng));
        const float size = sizeOf(shape);
        // From outside the bounding sphere, aimed at a point near the shape, with a random direction
        // length and a segment that sometimes ends before the shape.
        const Vec3 origin = t.position + (1.0f + 2.0f * unit(rng)) * size * randomUnit(rng);
        const Aabb bounds = worldBounds(shape, t);
        const Vec3 target = bounds.center() + 0.9f * bounds.halfExtents() * (2.0f * Vec3(unit(rng), unit(rng), unit(rng)) - 1.0f);
        const float directionScale = 0.2f + 3.0f * unit(rng);
        RayCastInput r = ray(origin, (target - origin) * directionScale, (0.6f + 1.4f * unit(rng)) / directionScale);
        QVERIFY(!contains(shape, t, origin));

        const float fractionStep = r.maxFraction / kSteps;
        const float distanceStep = fractionStep * glm::length(r.direction);
        int firstInside = -1;
        float nearest = std::numeric_limits<float>::infinity();  // smallest outsideBy over the samples
        for (int k = 0; k <= kSteps; ++k) {
            const Vec3 p = r.origin + (k * fractionStep) * r.direction;
            nearest = std::min(nearest, outsideBy(shape, t, p));
            if (firstInside < 0 && contains(shape, t, p)) firstInside = k;
        }

        const std::optional<RayCastHit> hit = rayCastShape(shape, t, r);
        const QString which = QStringLiteral("ray %1 (%2): ").arg(i).arg(QString::fromLatin1(shapeTypeName(shape.type).data()));
        // Coordinates up to ~20 m: allow a few ulps of them.
        const float tolerance = 2e-5f + 2e-6f * size;
        if (hit) {
            ++hits;
            const std::string defect = hitDefect(shape, t, r, *hit, tolerance, true);
            QVERIFY2(defect.empty(), qPrintable(which + QString::fromStdString(defect)));
            if (firstInside < 0) {
                ++grazingDisagreements;
                QVERIFY2(nearest <= distanceStep, qPrintable(which + "hit, but the march never came near"));
            } else {
                const float marched = firstInside * fractionStep;
                const float slack = tolerance / glm::length(r.direction);
                QVERIFY2(hit->fraction <= marched + slack && hit->fraction >= marched - fractionStep - slack,
                         qPrintable(which + QStringLiteral("fraction %1, march %2 (step %3)")
                                                .arg(hit->fraction).arg(marched).arg(fractionStep)));
            }
        } else if (firstInside >= 0) {
            ++grazingDisagreements;
            QVERIFY2(nearest >= -1e-5f, qPrintable(which + QStringLiteral("missed, but the march went %1 deep").arg(-nearest)));
        }
    }
    qInfo("%d of %d rays hit; %d grazing disagreements with the march", hits, kRays, grazingDisagreements);
    QVERIFY(hits > kRays / 3);
    QVERIFY(grazingDisagreements < kRays / 100);
}

// Same geometry, two solvers (slabs and face clipping): same fractions, and the same normal unless
// the hit is on an edge, where either face's normal is right.
void TestRayCast::boxHullMatchesBox() {
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 half(0.1f + unit(rng), 0.1f + unit(rng), 0.1f + unit(rng));
        const Shape box = Shape::box(half);
        const Shape hull = boxHull(half);
        const Transform t = place(Vec3(4.0f * unit(rng) - 2.0f, 4.0f * unit(rng) - 2.0f, 4.0f * unit(rng) - 2.0f),
                                  randomRotation(rng));
        const Vec3 origin = t.position + (1.0f + 2.0f * unit(rng)) * 2.0f * glm::length(half) * randomUnit(rng);
        const Vec3 target = t.apply(1.2f * half * (2.0f * Vec3(unit(rng), unit(rng), unit(rng)) - 1.0f));
        const RayCastInput r = ray(origin, target - origin, 0.5f + unit(rng));
        const std::optional<RayCastHit> boxHit = rayCastShape(box, t, r);
        const std::optional<RayCastHit> hullHit = rayCastShape(hull, t, r);
        const QString which = QStringLiteral("ray %1: ").arg(i);
        if (!boxHit || !hullHit) {
            // Disagreement only for a ray that touches an edge or corner within rounding.
            const std::optional<RayCastHit>& only = boxHit ? boxHit : hullHit;
            if (only) {
                const Vec3 local = glm::abs(t.applyInverse(only->point));
                const int onFaces = int(std::abs(local.x - half.x) < 1e-5f) + int(std::abs(local.y - half.y) < 1e-5f) +
                                    int(std::abs(local.z - half.z) < 1e-5f);
                QVERIFY2(onFaces >= 2, qPrintable(which + (boxHit ? "only the box was hit" : "only the hull was hit")));
            }
            continue;
        }
        ++hits;
        QVERIFY2(std::abs(boxHit->fraction - hullHit->fraction) * glm::length(r.direction) <= 1e-5f,
                 qPrintable(which + QStringLiteral("box %1, hull %2").arg(boxHit->fraction).arg(hullHit->fraction)));
        if (glm::length(boxHit->normal - hullHit->normal) > 1e-5f) {
            const Vec3 local = glm::abs(t.applyInverse(boxHit->point));
            const int onFaces = int(std::abs(local.x - half.x) < 1e-4f) + int(std::abs(local.y - half.y) < 1e-4f) +
                                int(std::abs(local.z - half.z) < 1e-4f);
            QVERIFY2(onFaces >= 2, qPrintable(which + "different normals away from an edge"));
        }
    }
    QVERIFY(hits > 500);
}

void TestRayCast::noHeapAllocation() {
    const std::vector<Shape> shapes = {Shape::sphere(0.5f), Shape::box({0.5f, 0.3f, 0.4f}), Shape::capsule(0.3f, 0.4f),
                                       Shape::cylinder(0.4f, 0.5f), octahedron(0.5f)};
    const Transform t = place({0.1f, 0.2f, -0.3f}, rotation(20, {1, 0, 1}));
    float sink = 0.0f;
    test_support::startCountingAllocations();
    for (const Shape& shape : shapes) {
        for (float y = -1.0f; y <= 1.0f; y += 0.05f) {
            const std::optional<RayCastHit> hit = rayCastShape(shape, t, ray({-3, y, 0.1f}, {1, 0.05f, 0}, 10));
            if (hit) sink += hit->fraction;
        }
    }
    const std::size_t allocations = test_support::stopCountingAllocations();
    QCOMPARE(allocations, std::size_t(0));
    QVERIFY(sink > 0.0f);
}

QTEST_APPLESS_MAIN(TestRayCast)
#include "test_ray_cast.moc"
