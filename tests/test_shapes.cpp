// Shapes: mass properties against textbook closed forms (hulls against the primitives they
// reproduce, and a sampled sphere against bounds that follow from containment), support mapping
// against the analytic support function and brute-force surface sampling, tight local and world
// bounds, volumes and minimum extents.

#include "support/geometry.h"
#include "simcore/shapes/shape.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace simcore;
using test_support::signedDistance;

using PointCloud = std::vector<Vec3>;
Q_DECLARE_METATYPE(simcore::Shape)
Q_DECLARE_METATYPE(simcore::Transform)

namespace {

constexpr double kPiD = 3.14159265358979323846;

// Small deterministic generator, so samples are identical on every platform.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    float uniform(float lo, float hi) {
        state_ += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = state_;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return lo + (hi - lo) * (float(z >> 40) / float(1ull << 24));
    }
    Vec3 unitVector() {
        for (;;) {
            const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const float length2 = glm::dot(v, v);
            if (length2 > 1e-4f && length2 <= 1.0f) return v / std::sqrt(length2);
        }
    }

private:
    std::uint64_t state_;
};

PointCloud fibonacciSphere(int count, float radius = 1.0f) {
    PointCloud points;
    const double golden = kPiD * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double r = std::sqrt(1.0 - y * y);
        points.push_back(radius * Vec3(float(r * std::cos(golden * i)), float(y), float(r * std::sin(golden * i))));
    }
    return points;
}

PointCloud boxCorners(const Vec3& half, const Vec3& offset = Vec3(0.0f)) {
    PointCloud points;
    for (float x : {-1.0f, 1.0f})
        for (float y : {-1.0f, 1.0f})
            for (float z : {-1.0f, 1.0f}) points.push_back(offset + Vec3(x, y, z) * half);
    return points;
}

Shape hullShape(const PointCloud& points) {
    auto result = ConvexHull::build(points);
    if (!result.hull) qFatal("hull build failed: %s", result.error.c_str());
    return Shape::convexHull(result.hull);
}

// An irregular hull: random points in an ellipsoid.
Shape irregularHull() {
    Random random(99);
    PointCloud points;
    for (int i = 0; i < 200; ++i) points.push_back(random.unitVector() * Vec3(0.6f, 1.1f, 0.4f) * random.uniform(0.3f, 1.0f));
    return hullShape(points);
}

// Dense samples of the shape's surface, edges and rims included.
PointCloud surfaceSamples(const Shape& shape) {
    PointCloud samples;
    constexpr int kSteps = 24;
    auto ring = [&](float y, float radius) {
        for (int i = 0; i < 4 * kSteps; ++i) {
            const float a = 2.0f * kPi * float(i) / float(4 * kSteps);
            samples.emplace_back(radius * std::cos(a), y, radius * std::sin(a));
        }
    };
    switch (shape.type) {
    case ShapeType::Sphere:
        samples = fibonacciSphere(4000, shape.radius);
        break;
    case ShapeType::Box:
        for (int axis = 0; axis < 3; ++axis)
            for (float side : {-1.0f, 1.0f})
                for (int i = 0; i <= kSteps; ++i)
                    for (int j = 0; j <= kSteps; ++j) {
                        Vec3 unit;
                        unit[axis] = side;
                        unit[(axis + 1) % 3] = -1.0f + 2.0f * float(i) / kSteps;
                        unit[(axis + 2) % 3] = -1.0f + 2.0f * float(j) / kSteps;
                        samples.push_back(unit * shape.halfExtents);
                    }
        break;
    case ShapeType::Capsule:
        for (int k = 0; k <= kSteps; ++k) ring(-shape.halfHeight + 2.0f * shape.halfHeight * float(k) / kSteps, shape.radius);
        for (const Vec3& p : fibonacciSphere(2000, shape.radius)) {
            samples.push_back(p + Vec3(0.0f, p.y >= 0.0f ? shape.halfHeight : -shape.halfHeight, 0.0f));
        }
        break;
    case ShapeType::Cylinder:
        for (int k = 0; k <= kSteps; ++k) ring(-shape.halfHeight + 2.0f * shape.halfHeight * float(k) / kSteps, shape.radius);
        for (float y : {-shape.halfHeight, shape.halfHeight}) {
            for (int k = 0; k < kSteps; ++k) ring(y, shape.radius * float(k) / kSteps);
        }
        break;
    case ShapeType::ConvexHull:
        samples = shape.hull->vertices();
        break;
    case ShapeType::Compound:
    case ShapeType::Mesh:
    case ShapeType::HeightField: break;  // not convex: these tests pass convex shapes only
    }
    return samples;
}

// The support function h(d) = max over the shape of dot(x, d), in closed form for unit d.
float supportFunction(const Shape& shape, const Vec3& d) {
    switch (shape.type) {
    case ShapeType::Sphere: return shape.radius;
    case ShapeType::Box: return glm::dot(glm::abs(d), shape.halfExtents);
    case ShapeType::Capsule: return shape.halfHeight * std::abs(d.y) + shape.radius;
    case ShapeType::Cylinder: return shape.halfHeight * std::abs(d.y) + shape.radius * std::sqrt(d.x * d.x + d.z * d.z);
    case ShapeType::ConvexHull: {
        float best = -std::numeric_limits<float>::max();
        for (const Vec3& v : shape.hull->sourcePoints()) best = std::max(best, glm::dot(v, d));
        return best;
    }
    case ShapeType::Compound:
    case ShapeType::Mesh:
    case ShapeType::HeightField: break;  // not convex: these tests pass convex shapes only
    }
    return 0.0f;
}

struct Expected {
    double mass;
    double ixx, iyy, izz;
};

bool closeRelative(double actual, double expected, double relative) {
    return std::abs(actual - expected) <= relative * std::max(std::abs(expected), 1e-30);
}

QString compareInertia(const Mat3& actual, const Mat3& expected, double relative) {
    double scale = 0.0;
    for (int i = 0; i < 3; ++i) scale = std::max(scale, double(std::abs(expected[i][i])));
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            if (std::abs(double(actual[c][r]) - double(expected[c][r])) > relative * scale) {
                return QString("inertia[%1][%2] = %3, expected %4").arg(c).arg(r).arg(actual[c][r]).arg(expected[c][r]);
            }
        }
    return {};
}

const std::vector<Shape>& allShapeKinds() {
    static const std::vector<Shape> shapes{
        Shape::sphere(0.7f), Shape::box(Vec3(0.5f, 1.0f, 1.5f)), Shape::capsule(0.3f, 0.8f),
        Shape::cylinder(0.4f, 0.9f), irregularHull()};
    return shapes;
}

}  // namespace

class TestShapes : public QObject {
    Q_OBJECT

private slots:
    void typeNamesAndFactories();
    void massPropertiesMatchClosedForms_data();
    void massPropertiesMatchClosedForms();
    void hullOfBoxCornersMatchesBox();
    void offCentreHullHasShiftedCentreOfMass();
    void rotatedBoxHullHasRotatedInertia();
    void hullOfSampledSphereApproachesSphere();
    void massPropertiesForMassGivesRequestedMass_data();
    void massPropertiesForMassGivesRequestedMass();
    void supportIsFarthestSurfacePoint_data();
    void supportIsFarthestSurfacePoint();
    void localBoundsAreTight_data();
    void localBoundsAreTight();
    void worldBoundsAreTight_data();
    void worldBoundsAreTight();
    void volumeMatchesClosedForms_data();
    void volumeMatchesClosedForms();
    void minimumExtentIsThinnestDimension_data();
    void minimumExtentIsThinnestDimension();
};

void TestShapes::typeNamesAndFactories() {
    QCOMPARE(shapeTypeName(ShapeType::Sphere), std::string_view("sphere"));
    QCOMPARE(shapeTypeName(ShapeType::Box), std::string_view("box"));
    QCOMPARE(shapeTypeName(ShapeType::Capsule), std::string_view("capsule"));
    QCOMPARE(shapeTypeName(ShapeType::Cylinder), std::string_view("cylinder"));
    QCOMPARE(shapeTypeName(ShapeType::ConvexHull), std::string_view("convexHull"));

    QCOMPARE(Shape::sphere(2.0f).type, ShapeType::Sphere);
    QCOMPARE(Shape::sphere(2.0f).radius, 2.0f);
    QCOMPARE(Shape::box(Vec3(1, 2, 3)).halfExtents, Vec3(1, 2, 3));
    const Shape capsule = Shape::capsule(0.25f, 1.5f);
    QCOMPARE(capsule.type, ShapeType::Capsule);
    QCOMPARE(capsule.radius, 0.25f);
    QCOMPARE(capsule.halfHeight, 1.5f);
    const Shape cylinder = Shape::cylinder(0.75f, 0.5f);
    QCOMPARE(cylinder.type, ShapeType::Cylinder);
    QCOMPARE(cylinder.radius, 0.75f);
    QCOMPARE(cylinder.halfHeight, 0.5f);
    const Shape hull = hullShape(boxCorners(Vec3(1.0f)));
    QCOMPARE(hull.type, ShapeType::ConvexHull);
    QVERIFY(hull.hull);
}

void TestShapes::massPropertiesMatchClosedForms_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<float>("density");
    QTest::addColumn<double>("mass");
    QTest::addColumn<double>("ixx");
    QTest::addColumn<double>("iyy");
    QTest::addColumn<double>("izz");

    auto add = [](const char* name, const Shape& shape, double density, Expected e) {
        QTest::newRow(name) << shape << float(density) << e.mass << e.ixx << e.iyy << e.izz;
    };
    auto sphere = [](double r, double rho) {
        const double m = rho * 4.0 / 3.0 * kPiD * r * r * r;
        const double i = 2.0 / 5.0 * m * r * r;
        return Expected{m, i, i, i};
    };
    auto box = [](double a, double b, double c, double rho) {  // full side lengths
        const double m = rho * a * b * c;
        return Expected{m, m / 12.0 * (b * b + c * c), m / 12.0 * (a * a + c * c), m / 12.0 * (a * a + b * b)};
    };
    auto cylinder = [](double r, double h, double rho) {  // h: full height along y
        const double m = rho * kPiD * r * r * h;
        const double transverse = m / 12.0 * (3.0 * r * r + h * h);
        return Expected{m, transverse, 0.5 * m * r * r, transverse};
    };
    // The usual capsule formula: cylinder of height h plus hemispheres of mass m_h each,
    // I_axis = m_c r^2/2 + 2 (2/5 m_h r^2), I_transverse = m_c (h^2/12 + r^2/4) + 2 m_h (2r^2/5 + h^2/4 + 3hr/8).
    auto capsule = [](double r, double h, double rho) {
        const double mc = rho * kPiD * r * r * h;
        const double mh = rho * 2.0 / 3.0 * kPiD * r * r * r;
        const double axial = mc * r * r / 2.0 + 2.0 * (2.0 / 5.0 * mh * r * r);
        const double transverse = mc * (h * h / 12.0 + r * r / 4.0) + 2.0 * mh * (2.0 * r * r / 5.0 + h * h / 4.0 + 3.0 * h * r / 8.0);
        return Expected{mc + 2.0 * mh, transverse, axial, transverse};
    };

    add("sphere r=0.7", Shape::sphere(0.7f), 2.5, sphere(0.7, 2.5));
    add("sphere r=3 water", Shape::sphere(3.0f), 1000.0, sphere(3.0, 1000.0));
    add("box 1x2x3", Shape::box(Vec3(0.5f, 1.0f, 1.5f)), 2.5, box(1.0, 2.0, 3.0, 2.5));
    add("cube 0.2", Shape::box(Vec3(0.1f)), 7800.0, box(0.2, 0.2, 0.2, 7800.0));
    add("cylinder r=0.4 h=1.8", Shape::cylinder(0.4f, 0.9f), 3.0, cylinder(0.4, 1.8, 3.0));
    add("flat cylinder", Shape::cylinder(2.0f, 0.05f), 1.0, cylinder(2.0, 0.1, 1.0));
    add("capsule r=0.3 h=1.6", Shape::capsule(0.3f, 0.8f), 1.5, capsule(0.3, 1.6, 1.5));
    add("stubby capsule", Shape::capsule(1.0f, 0.1f), 900.0, capsule(1.0, 0.2, 900.0));
    add("capsule without straight part is a sphere", Shape::capsule(0.5f, 0.0f), 2.0, sphere(0.5, 2.0));
}

void TestShapes::massPropertiesMatchClosedForms() {
    QFETCH(Shape, shape);
    QFETCH(float, density);
    QFETCH(double, mass);
    QFETCH(double, ixx);
    QFETCH(double, iyy);
    QFETCH(double, izz);

    const MassProperties props = massProperties(shape, density);
    QVERIFY2(closeRelative(props.mass, mass, 1e-5), qPrintable(QString("mass %1 vs %2").arg(props.mass).arg(mass)));
    QCOMPARE(props.centerOfMass, Vec3(0.0f));
    const Mat3 expected = diagonal(Vec3(float(ixx), float(iyy), float(izz)));
    const QString mismatch = compareInertia(props.inertia, expected, 1e-5);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestShapes::hullOfBoxCornersMatchesBox() {
    const Vec3 half(0.5f, 1.25f, 2.0f);
    const float density = 3.5f;
    const MassProperties box = massProperties(Shape::box(half), density);
    const MassProperties hull = massProperties(hullShape(boxCorners(half)), density);
    QVERIFY(closeRelative(hull.mass, box.mass, 1e-5));
    QVERIFY(glm::length(hull.centerOfMass) < 1e-6f);
    const QString mismatch = compareInertia(hull.inertia, box.inertia, 1e-5);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestShapes::offCentreHullHasShiftedCentreOfMass() {
    // The inertia is about the centre of mass, so shifting the solid leaves it unchanged.
    const Vec3 half(1.0f, 0.5f, 0.25f);
    const MassProperties box = massProperties(Shape::box(half), 2.0f);
    const MassProperties hull = massProperties(hullShape(boxCorners(half, Vec3(1.0f, 2.0f, 3.0f))), 2.0f);
    QVERIFY(closeRelative(hull.mass, box.mass, 1e-5));
    QVERIFY2(glm::length(hull.centerOfMass - Vec3(1.0f, 2.0f, 3.0f)) < 1e-5f,
             qPrintable(QString("COM (%1, %2, %3)").arg(hull.centerOfMass.x).arg(hull.centerOfMass.y).arg(hull.centerOfMass.z)));
    const QString mismatch = compareInertia(hull.inertia, box.inertia, 1e-5);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestShapes::rotatedBoxHullHasRotatedInertia() {
    // Off-diagonal products of inertia: a rotated box has I' = R I R^T.
    const Vec3 half(0.3f, 0.8f, 1.6f);
    const Quat rotation = glm::angleAxis(0.7f, glm::normalize(Vec3(1.0f, 2.0f, -0.5f)));
    PointCloud corners = boxCorners(half);
    for (Vec3& p : corners) p = rotation * p;
    const MassProperties hull = massProperties(hullShape(corners), 1.0f);
    const Mat3 r = glm::mat3_cast(rotation);
    const Mat3 expected = r * massProperties(Shape::box(half), 1.0f).inertia * glm::transpose(r);
    const QString mismatch = compareInertia(hull.inertia, expected, 1e-5);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    QVERIFY(std::abs(expected[0][1]) > 0.01f * expected[0][0]);  // the test does exercise products
}

void TestShapes::hullOfSampledSphereApproachesSphere() {
    // All 2000 vertices lie on the unit sphere, so the hull lies inside the unit ball; and it
    // contains the ball of radius d, the smallest distance from the centre to a face plane. Every
    // quantity monotone in the solid is therefore bracketed by its value for these two balls:
    //   V(d) <= V <= V(1),  I(d) <= I_ii <= I(1)  with V(r) = 4/3 pi r^3, I(r) = 8/15 pi r^5.
    // Off-diagonal products and the centre of mass only get contributions from the shell between
    // the balls: |I_ij| <= (I(1) - I(d)) / 2 (as |xy| <= (x^2 + y^2) / 2) and |c| <= (V(1) - V(d)) / V(d).
    const Shape shape = hullShape(fibonacciSphere(2000));
    float d = std::numeric_limits<float>::max();
    for (const HullFace& f : shape.hull->faces()) d = std::min(d, f.offset);
    QVERIFY2(d > 0.995f, qPrintable(QString("inscribed radius %1").arg(d)));

    const double slack = 1e-5;  // float rounding of the computed properties
    auto ballVolume = [](double r) { return 4.0 / 3.0 * kPiD * r * r * r; };
    auto ballInertia = [](double r) { return 8.0 / 15.0 * kPiD * std::pow(r, 5.0); };
    const MassProperties props = massProperties(shape, 1.0f);

    QVERIFY(props.mass >= ballVolume(d) * (1.0 - slack) && props.mass <= ballVolume(1.0) * (1.0 + slack));
    for (int i = 0; i < 3; ++i) {
        QVERIFY(props.inertia[i][i] >= ballInertia(d) * (1.0 - slack));
        QVERIFY(props.inertia[i][i] <= ballInertia(1.0) * (1.0 + slack));
        for (int j = 0; j < 3; ++j) {
            if (i != j) QVERIFY(std::abs(props.inertia[i][j]) <= (ballInertia(1.0) - ballInertia(d)) / 2.0 + slack);
        }
    }
    QVERIFY(glm::length(props.centerOfMass) <= (ballVolume(1.0) - ballVolume(d)) / ballVolume(d) + slack);

    // With this sampling the polyhedral deficit is well under 1%.
    QVERIFY(closeRelative(props.mass, ballVolume(1.0), 0.01));
    QVERIFY(closeRelative(props.inertia[0][0], ballInertia(1.0), 0.01));
}

void TestShapes::massPropertiesForMassGivesRequestedMass_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<float>("mass");
    for (const Shape& shape : allShapeKinds()) {
        QTest::newRow(std::string(shapeTypeName(shape.type)).c_str()) << shape << 3.7f;
    }
    QTest::newRow("heavy hull box") << hullShape(boxCorners(Vec3(0.5f), Vec3(0.2f, 0.0f, -0.1f))) << 1250.0f;
}

void TestShapes::massPropertiesForMassGivesRequestedMass() {
    QFETCH(Shape, shape);
    QFETCH(float, mass);
    const MassProperties props = massPropertiesForMass(shape, mass);
    QVERIFY(closeRelative(props.mass, mass, 1e-6));

    // Same as with the density that gives this mass.
    const MassProperties unit = massProperties(shape, 1.0f);
    const MassProperties byDensity = massProperties(shape, mass / unit.mass);
    QVERIFY(glm::length(props.centerOfMass - byDensity.centerOfMass) <= 1e-6f);
    const QString mismatch = compareInertia(props.inertia, byDensity.inertia, 1e-5);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestShapes::supportIsFarthestSurfacePoint_data() {
    QTest::addColumn<Shape>("shape");
    for (const Shape& shape : allShapeKinds()) {
        QTest::newRow(std::string(shapeTypeName(shape.type)).c_str()) << shape;
    }
    QTest::newRow("hull of box corners") << hullShape(boxCorners(Vec3(0.4f, 0.2f, 0.9f)));
}

void TestShapes::supportIsFarthestSurfacePoint() {
    QFETCH(Shape, shape);
    const PointCloud samples = surfaceSamples(shape);
    constexpr float kTol = 1e-5f;

    // Directions all around, plus the axis-aligned ones where support has ties (box faces,
    // cylinder caps), none of them unit length.
    PointCloud directions = fibonacciSphere(200);
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            Vec3 d(0.0f);
            d[axis] = sign;
            directions.push_back(d);
        }
    }
    directions.push_back(glm::normalize(Vec3(1.0f, 0.0f, 1.0f)));
    directions.push_back(glm::normalize(Vec3(0.0f, 1.0f, -1.0f)));

    for (const Vec3& unit : directions) {
        const Vec3 s = support(shape, 3.7f * unit);
        QVERIFY2(std::abs(signedDistance(shape, s)) <= kTol,
                 qPrintable(QString("support point is %1 off the surface").arg(signedDistance(shape, s))));
        const float reach = glm::dot(s, unit);
        QVERIFY(std::abs(reach - supportFunction(shape, unit)) <= kTol);
        float farthestSample = -std::numeric_limits<float>::max();
        for (const Vec3& p : samples) farthestSample = std::max(farthestSample, glm::dot(p, unit));
        QVERIFY2(reach >= farthestSample - kTol,
                 qPrintable(QString("a sample reaches %1, support only %2").arg(farthestSample).arg(reach)));
    }

    // A zero direction still yields a point of the surface.
    const Vec3 s = support(shape, Vec3(0.0f));
    QVERIFY(isFinite(s));
    QVERIFY(std::abs(signedDistance(shape, s)) <= kTol);
}

void TestShapes::localBoundsAreTight_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<Vec3>("expectedMax");  // bounds are symmetric about the origin for these

    QTest::newRow("sphere") << Shape::sphere(0.7f) << Vec3(0.7f);
    QTest::newRow("box") << Shape::box(Vec3(0.5f, 1.0f, 1.5f)) << Vec3(0.5f, 1.0f, 1.5f);
    QTest::newRow("capsule") << Shape::capsule(0.3f, 0.8f) << Vec3(0.3f, 1.1f, 0.3f);
    QTest::newRow("cylinder") << Shape::cylinder(0.4f, 0.9f) << Vec3(0.4f, 0.9f, 0.4f);
    QTest::newRow("hull") << hullShape(boxCorners(Vec3(0.2f, 0.3f, 0.4f))) << Vec3(0.2f, 0.3f, 0.4f);
}

void TestShapes::localBoundsAreTight() {
    QFETCH(Shape, shape);
    QFETCH(Vec3, expectedMax);
    const Aabb bounds = localBounds(shape);
    QCOMPARE(bounds.max, expectedMax);
    QCOMPARE(bounds.min, -expectedMax);
    const Aabb world = worldBounds(shape, Transform{});
    QVERIFY(glm::length(world.min - bounds.min) < 1e-6f && glm::length(world.max - bounds.max) < 1e-6f);
}

void TestShapes::worldBoundsAreTight_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<Transform>("transform");

    const std::vector<std::pair<const char*, Transform>> transforms{
        {"identity", Transform{}},
        {"translated", Transform{Vec3(3.0f, -2.0f, 1.0f), Quat(1.0f, 0.0f, 0.0f, 0.0f)}},
        {"quarter turn about z", Transform{Vec3(0.0f), glm::angleAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f))}},
        {"tilted", Transform{Vec3(-1.0f, 0.5f, 4.0f), glm::angleAxis(0.9f, glm::normalize(Vec3(1.0f, 2.0f, 3.0f)))}},
        {"tumbled", Transform{Vec3(2.0f, 2.0f, -3.0f), glm::angleAxis(2.6f, glm::normalize(Vec3(-0.3f, 0.2f, 0.9f)))}},
    };
    for (const Shape& shape : allShapeKinds()) {
        for (const auto& [name, transform] : transforms) {
            const std::string row = std::string(shapeTypeName(shape.type)) + ", " + name;
            QTest::newRow(row.c_str()) << shape << transform;
        }
    }
}

void TestShapes::worldBoundsAreTight() {
    QFETCH(Shape, shape);
    QFETCH(Transform, transform);
    constexpr float kTol = 1e-5f;
    const Aabb bounds = worldBounds(shape, transform);

    // Each face of the box touches the placed shape: it is where the shape's support point along
    // that world axis lies.
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 worldAxis(0.0f);
        worldAxis[axis] = 1.0f;
        const Vec3 highest = transform.apply(support(shape, transform.rotateInverse(worldAxis)));
        const Vec3 lowest = transform.apply(support(shape, transform.rotateInverse(-worldAxis)));
        QVERIFY2(std::abs(bounds.max[axis] - highest[axis]) <= kTol,
                 qPrintable(QString("axis %1: max %2, support %3").arg(axis).arg(bounds.max[axis]).arg(highest[axis])));
        QVERIFY2(std::abs(bounds.min[axis] - lowest[axis]) <= kTol,
                 qPrintable(QString("axis %1: min %2, support %3").arg(axis).arg(bounds.min[axis]).arg(lowest[axis])));
    }
    // And it contains the whole placed surface.
    for (const Vec3& p : surfaceSamples(shape)) {
        const Vec3 q = transform.apply(p);
        QVERIFY(glm::all(glm::greaterThanEqual(q, bounds.min - Vec3(kTol))) &&
                glm::all(glm::lessThanEqual(q, bounds.max + Vec3(kTol))));
    }
}

void TestShapes::volumeMatchesClosedForms_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<double>("expected");

    QTest::newRow("sphere") << Shape::sphere(0.7f) << 4.0 / 3.0 * kPiD * 0.343;
    QTest::newRow("box") << Shape::box(Vec3(0.5f, 1.0f, 1.5f)) << 6.0;
    QTest::newRow("capsule") << Shape::capsule(0.3f, 0.8f) << kPiD * 0.09 * 1.6 + 4.0 / 3.0 * kPiD * 0.027;
    QTest::newRow("cylinder") << Shape::cylinder(0.4f, 0.9f) << kPiD * 0.16 * 1.8;
    QTest::newRow("hull box") << hullShape(boxCorners(Vec3(0.5f, 1.0f, 1.5f), Vec3(5.0f, 0.0f, 0.0f))) << 6.0;
    QTest::newRow("hull tetrahedron") << hullShape({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) << 1.0 / 6.0;
}

void TestShapes::volumeMatchesClosedForms() {
    QFETCH(Shape, shape);
    QFETCH(double, expected);
    QVERIFY2(closeRelative(volume(shape), expected, 1e-5), qPrintable(QString("volume %1 vs %2").arg(volume(shape)).arg(expected)));
    // Consistent with the mass at unit density.
    QVERIFY(closeRelative(massProperties(shape, 1.0f).mass, volume(shape), 1e-5));
}

void TestShapes::minimumExtentIsThinnestDimension_data() {
    QTest::addColumn<Shape>("shape");
    QTest::addColumn<float>("expected");

    QTest::newRow("sphere") << Shape::sphere(0.7f) << 1.4f;
    QTest::newRow("box") << Shape::box(Vec3(0.5f, 0.1f, 1.5f)) << 0.2f;
    QTest::newRow("capsule") << Shape::capsule(0.3f, 0.8f) << 0.6f;
    QTest::newRow("long cylinder") << Shape::cylinder(0.4f, 0.9f) << 0.8f;
    QTest::newRow("flat cylinder") << Shape::cylinder(2.0f, 0.05f) << 0.1f;
    QTest::newRow("hull box") << hullShape(boxCorners(Vec3(0.5f, 1.0f, 0.25f), Vec3(1.0f, 2.0f, 3.0f))) << 0.5f;
}

void TestShapes::minimumExtentIsThinnestDimension() {
    QFETCH(Shape, shape);
    QFETCH(float, expected);
    QVERIFY(std::abs(minimumExtent(shape) - expected) <= 1e-5f * expected);
}

QTEST_APPLESS_MAIN(TestShapes)
#include "test_shapes.moc"
