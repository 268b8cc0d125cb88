#pragma once
// Collision shapes. A Shape is a small value: its type and dimensions, plus a shared, immutable
// hull for convex hulls, child list for compounds or surface for meshes and height fields. The
// convex types come first; a compound is a list of convex children, each placed in the body frame;
// a mesh or height field is a static surface of triangles (static and kinematic bodies only: it has
// no volume, so no mass). Shapes are described in their own
// local frame, whose origin is the owning body's origin (not necessarily the centre of mass).
//
// Sub-shapes: what collision works on. A convex shape is its own single sub-shape (index 0); a
// compound's sub-shapes are its children, in order; a surface's are its triangles, by index (a
// triangle is not a Shape value: collision asks the surface for it). Contacts, ray hits and sweeps
// name them.

#include "simcore/math/aabb.h"
#include "simcore/math/math.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/shapes/height_field.h"
#include "simcore/shapes/triangle_mesh.h"

#include <memory>
#include <string_view>

namespace simcore {

enum class ShapeType : std::uint8_t { Sphere, Box, Capsule, Cylinder, ConvexHull, Compound, Mesh, HeightField };
// The convex types, which come first: what collideShapes dispatches over, a compound's children may
// be and the editor's Add menus offer. Compound, made of them, follows, then the static surfaces.
constexpr int kShapeTypeCount = 5;
constexpr bool isConvex(ShapeType type) { return static_cast<int>(type) < kShapeTypeCount; }
// A surface of triangles (TriangleMesh or HeightField): static and kinematic bodies only.
constexpr bool isSurface(ShapeType type) { return type == ShapeType::Mesh || type == ShapeType::HeightField; }

// "sphere", "box", "capsule", "cylinder", "convexHull", "compound", "mesh", "heightField"
std::string_view shapeTypeName(ShapeType type);

class CompoundShape;  // compound_shape.h

struct Shape {
    ShapeType type = ShapeType::Sphere;
    Vec3 halfExtents{0.5f};   // box only (m)
    float radius = 0.5f;      // sphere, capsule, cylinder (m)
    float halfHeight = 0.5f;  // capsule: half the straight segment; cylinder: half the height (m), along local Y
    std::shared_ptr<const ConvexHull> hull;  // convexHull only
    std::shared_ptr<const CompoundShape> compound;  // compound only
    std::shared_ptr<const TriangleMesh> mesh;        // mesh only
    std::shared_ptr<const HeightField> heightField;  // heightField only

    static Shape sphere(float radius);
    static Shape box(const Vec3& halfExtents);
    static Shape capsule(float radius, float halfHeight);
    static Shape cylinder(float radius, float halfHeight);
    static Shape convexHull(std::shared_ptr<const ConvexHull> hull);
    static Shape compoundOf(std::shared_ptr<const CompoundShape> compound);
    static Shape triangleMesh(std::shared_ptr<const TriangleMesh> mesh);
    static Shape heightFieldOf(std::shared_ptr<const HeightField> field);
};

// Calls visit(surface) with a surface shape's TriangleMesh or HeightField (which share the surface
// interface: triangle(), forEachTriangleOverlapping(), rayCast(), bounds()). The shape must be a
// surface holding its data (validation::validateShape checks that).
template <class Visit>
decltype(auto) visitSurface(const Shape& shape, Visit&& visit) {
    if (shape.type == ShapeType::Mesh) return visit(*shape.mesh);
    return visit(*shape.heightField);
}

// Sub-shapes (see the top): 1 for a convex shape, the child count for a compound, the triangle
// count for a surface.
std::size_t subShapeCount(const Shape& shape);
// Sub-shape `index` (< subShapeCount) and where it sits: the shape itself at `bodyTransform` for a
// convex shape, the child at bodyTransform * child pose for a compound. A surface answers with
// itself at `bodyTransform` (its triangles are not Shapes: what is asked of a sub-shape's Shape,
// its rounding and rolling radius, is the surface's, 0).
const Shape& subShape(const Shape& shape, std::size_t index);
Transform subShapeTransform(const Shape& shape, std::size_t index, const Transform& bodyTransform);
// The sub-shape's bounds in the body frame.
Aabb subShapeLocalBounds(const Shape& shape, std::size_t index);

// Farthest point of the shape along `direction` (local frame; direction need not be unit). For a
// compound: the farthest point of any child, i.e. of the children's convex hull. For a surface, the
// corner of its bounds (surfaces never enter GJK; collision works on their triangles).
Vec3 support(const Shape& shape, const Vec3& direction);

// Tight bounds in the local frame, and of the shape placed by `transform` in the world.
Aabb localBounds(const Shape& shape);
Aabb worldBounds(const Shape& shape, const Transform& transform);

// The box `box` (world) seen from the frame `transform` places, and a box of that frame placed in the
// world: the bounds of its corners.
Aabb boundsInFrame(const Aabb& box, const Transform& transform);
Aabb placedBounds(const Aabb& local, const Transform& transform);

float volume(const Shape& shape);  // (m^3); a compound's is the sum of its children's; a surface's 0


// Mass, centre of mass (local frame) and inertia tensor about the centre of mass, axes parallel to
// the local frame, for a uniform solid of the given density (kg/m^3). Exact closed forms for the
// primitives; hulls by signed tetrahedral decomposition; compounds as the sum of their children
// carried to the common centre of mass (parallel-axis theorem). Children that overlap count their
// shared volume twice, as in Jolt and Bullet: the user sees and sets each child's size. A surface
// has none (zero mass and inertia; its centre of mass is its origin).
struct MassProperties {
    float mass = 0.0f;          // kg
    Vec3 centerOfMass{0.0f};    // m, local frame
    Mat3 inertia{0.0f};         // kg m^2, about centerOfMass
};
MassProperties massProperties(const Shape& shape, float density);

// Same properties scaled to a prescribed total mass (density chosen to match).
MassProperties massPropertiesForMass(const Shape& shape, float mass);

// Smallest extent of the shape (m): the thinnest dimension, used to decide when a body moves fast
// enough to need continuous collision. A compound's is its thinnest child's; a surface's its bounds'
// thinnest side (surfaces never move dynamically, so it decides nothing).
float minimumExtent(const Shape& shape);

// The lever of rolling resistance (m): the radius a round body rolls on (sphere, capsule and
// cylinder radius), 0 for boxes and hulls, which rest on flat faces and tip rather than roll. A
// cylinder standing on a flat end keeps its radius, so its resistance also acts against turning
// on that end. A compound's is 0: its contacts roll on the child that touches (sub-shapes). A
// surface's is 0.
float rollingRadius(const Shape& shape);

}  // namespace simcore
