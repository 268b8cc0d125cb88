#pragma once
// Collision shapes. A Shape is a small value: its type and dimensions, plus a shared, immutable
// hull for convex hulls. All shapes are convex and described in their own local frame, whose
// origin is the owning body's origin (not necessarily the centre of mass).

#include "simcore/math/aabb.h"
#include "simcore/math/math.h"
#include "simcore/shapes/convex_hull.h"

#include <memory>
#include <string_view>

namespace simcore {

enum class ShapeType : std::uint8_t { Sphere, Box, Capsule, Cylinder, ConvexHull };
constexpr int kShapeTypeCount = 5;

std::string_view shapeTypeName(ShapeType type);  // "sphere", "box", "capsule", "cylinder", "convexHull"

struct Shape {
    ShapeType type = ShapeType::Sphere;
    Vec3 halfExtents{0.5f};   // box only (m)
    float radius = 0.5f;      // sphere, capsule, cylinder (m)
    float halfHeight = 0.5f;  // capsule: half the straight segment; cylinder: half the height (m), along local Y
    std::shared_ptr<const ConvexHull> hull;  // convexHull only

    static Shape sphere(float radius);
    static Shape box(const Vec3& halfExtents);
    static Shape capsule(float radius, float halfHeight);
    static Shape cylinder(float radius, float halfHeight);
    static Shape convexHull(std::shared_ptr<const ConvexHull> hull);
};

// Farthest point of the shape along `direction` (local frame; direction need not be unit).
Vec3 support(const Shape& shape, const Vec3& direction);

// Tight bounds in the local frame, and of the shape placed by `transform` in the world.
Aabb localBounds(const Shape& shape);
Aabb worldBounds(const Shape& shape, const Transform& transform);

float volume(const Shape& shape);  // (m^3)

// Mass, centre of mass (local frame) and inertia tensor about the centre of mass, axes parallel to
// the local frame, for a uniform solid of the given density (kg/m^3). Exact closed forms for the
// primitives; hulls by signed tetrahedral decomposition.
struct MassProperties {
    float mass = 0.0f;          // kg
    Vec3 centerOfMass{0.0f};    // m, local frame
    Mat3 inertia{0.0f};         // kg m^2, about centerOfMass
};
MassProperties massProperties(const Shape& shape, float density);

// Same properties scaled to a prescribed total mass (density chosen to match).
MassProperties massPropertiesForMass(const Shape& shape, float mass);

// Smallest extent of the shape (m): the thinnest dimension, used to decide when a body moves fast
// enough to need continuous collision.
float minimumExtent(const Shape& shape);

// The lever of rolling resistance (m): the radius a round body rolls on (sphere, capsule and
// cylinder radius), 0 for boxes and hulls, which rest on flat faces and tip rather than roll. A
// cylinder standing on a flat end keeps its radius, so its resistance also acts against turning
// on that end.
float rollingRadius(const Shape& shape);

}  // namespace simcore
