#include "simcore/shapes/shape.h"

#include "simcore/shapes/compound_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcore {

std::string_view shapeTypeName(ShapeType type) {
    switch (type) {
    case ShapeType::Sphere: return "sphere";
    case ShapeType::Box: return "box";
    case ShapeType::Capsule: return "capsule";
    case ShapeType::Cylinder: return "cylinder";
    case ShapeType::ConvexHull: return "convexHull";
    case ShapeType::Compound: return "compound";
    case ShapeType::Mesh: return "mesh";
    case ShapeType::HeightField: return "heightField";
    }
    return "unknown";
}

Shape Shape::sphere(float radius) {
    Shape s;
    s.type = ShapeType::Sphere;
    s.radius = radius;
    return s;
}

Shape Shape::box(const Vec3& halfExtents) {
    Shape s;
    s.type = ShapeType::Box;
    s.halfExtents = halfExtents;
    return s;
}

Shape Shape::capsule(float radius, float halfHeight) {
    Shape s;
    s.type = ShapeType::Capsule;
    s.radius = radius;
    s.halfHeight = halfHeight;
    return s;
}

Shape Shape::cylinder(float radius, float halfHeight) {
    Shape s;
    s.type = ShapeType::Cylinder;
    s.radius = radius;
    s.halfHeight = halfHeight;
    return s;
}

Shape Shape::convexHull(std::shared_ptr<const ConvexHull> hull) {
    Shape s;
    s.type = ShapeType::ConvexHull;
    s.hull = std::move(hull);
    return s;
}

Shape Shape::compoundOf(std::shared_ptr<const CompoundShape> compound) {
    Shape s;
    s.type = ShapeType::Compound;
    s.compound = std::move(compound);
    return s;
}

Shape Shape::triangleMesh(std::shared_ptr<const TriangleMesh> mesh) {
    Shape s;
    s.type = ShapeType::Mesh;
    s.mesh = std::move(mesh);
    return s;
}

Shape Shape::heightFieldOf(std::shared_ptr<const HeightField> field) {
    Shape s;
    s.type = ShapeType::HeightField;
    s.heightField = std::move(field);
    return s;
}

namespace {

bool hasSurface(const Shape& shape) {
    return shape.type == ShapeType::Mesh ? shape.mesh != nullptr : shape.heightField != nullptr;
}

}  // namespace

Aabb boundsInFrame(const Aabb& box, const Transform& transform) {
    const Mat3 toLocal = glm::transpose(glm::mat3_cast(transform.rotation));
    const Vec3 half = box.halfExtents();
    Vec3 localHalf(0.0f);
    for (int j = 0; j < 3; ++j) localHalf += glm::abs(toLocal[j]) * half[j];
    return Aabb::fromCenterHalfExtents(toLocal * (box.center() - transform.position), localHalf);
}

Aabb placedBounds(const Aabb& local, const Transform& transform) {
    const Mat3 rotation = glm::mat3_cast(transform.rotation);
    const Vec3 half = local.halfExtents();
    Vec3 worldHalf(0.0f);
    for (int j = 0; j < 3; ++j) worldHalf += glm::abs(rotation[j]) * half[j];
    return Aabb::fromCenterHalfExtents(transform.apply(local.center()), worldHalf);
}

std::size_t subShapeCount(const Shape& shape) {
    if (isSurface(shape.type))
        return hasSurface(shape) ? visitSurface(shape, [](const auto& s) { return s.triangleCount(); }) : 0;
    if (shape.type != ShapeType::Compound) return 1;
    return shape.compound ? shape.compound->size() : 0;
}

const Shape& subShape(const Shape& shape, std::size_t index) {
    return shape.type == ShapeType::Compound ? shape.compound->children()[index].shape : shape;
}

Transform subShapeTransform(const Shape& shape, std::size_t index, const Transform& bodyTransform) {
    // A convex shape's transform is returned as it is, so its collisions round exactly as before.
    if (shape.type != ShapeType::Compound) return bodyTransform;
    return childTransform(shape.compound->children()[index], bodyTransform);
}

Aabb subShapeLocalBounds(const Shape& shape, std::size_t index) {
    if (isSurface(shape.type)) {
        Aabb bounds;
        const Triangle triangle =
            visitSurface(shape, [&](const auto& s) { return s.triangle(static_cast<std::uint32_t>(index)); });
        for (const Vec3& v : triangle.vertices) bounds.grow(v);
        return bounds;
    }
    return shape.type == ShapeType::Compound ? shape.compound->childBounds(index) : localBounds(shape);
}

namespace {

bool hasChildren(const Shape& shape) { return shape.compound && shape.compound->size() > 0; }

// Unit vector along v; for a zero vector any unit vector is an equally valid support direction.
Vec3 directionOrX(const Vec3& v) {
    const float length2 = lengthSquared(v);
    return length2 > 0.0f ? v / std::sqrt(length2) : Vec3(1.0f, 0.0f, 0.0f);
}

bool hasHull(const Shape& shape) { return shape.hull && !shape.hull->vertices().empty(); }

}  // namespace

Vec3 support(const Shape& shape, const Vec3& direction) {
    switch (shape.type) {
    case ShapeType::Sphere:
        return shape.radius * directionOrX(direction);
    case ShapeType::Box:
        return {direction.x >= 0.0f ? shape.halfExtents.x : -shape.halfExtents.x,
                direction.y >= 0.0f ? shape.halfExtents.y : -shape.halfExtents.y,
                direction.z >= 0.0f ? shape.halfExtents.z : -shape.halfExtents.z};
    case ShapeType::Capsule: {
        const float endY = direction.y >= 0.0f ? shape.halfHeight : -shape.halfHeight;
        return Vec3(0.0f, endY, 0.0f) + shape.radius * directionOrX(direction);
    }
    case ShapeType::Cylinder: {
        const float capY = direction.y >= 0.0f ? shape.halfHeight : -shape.halfHeight;
        const float radial2 = direction.x * direction.x + direction.z * direction.z;
        // Straight along the axis the whole cap is extreme; its centre is as good as any point.
        if (radial2 <= 0.0f) return {0.0f, capY, 0.0f};
        const float scale = shape.radius / std::sqrt(radial2);
        return {direction.x * scale, capY, direction.z * scale};
    }
    case ShapeType::ConvexHull:
        return hasHull(shape) ? shape.hull->support(direction) : Vec3(0.0f);
    case ShapeType::Compound: {
        if (!hasChildren(shape)) return Vec3(0.0f);
        Vec3 best(0.0f);
        float bestReach = -std::numeric_limits<float>::max();
        for (const CompoundChild& child : shape.compound->children()) {
            const Vec3 p = child.pose.apply(support(child.shape, child.pose.rotateInverse(direction)));
            if (const float reach = glm::dot(p, direction); reach > bestReach) {
                best = p;
                bestReach = reach;
            }
        }
        return best;
    }
    case ShapeType::Mesh:
    case ShapeType::HeightField: {
        const Aabb bounds = localBounds(shape);
        return {direction.x >= 0.0f ? bounds.max.x : bounds.min.x, direction.y >= 0.0f ? bounds.max.y : bounds.min.y,
                direction.z >= 0.0f ? bounds.max.z : bounds.min.z};
    }
    }
    return Vec3(0.0f);
}

Aabb localBounds(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Sphere:
        return Aabb::fromCenterHalfExtents(Vec3(0.0f), Vec3(shape.radius));
    case ShapeType::Box:
        return Aabb::fromCenterHalfExtents(Vec3(0.0f), shape.halfExtents);
    case ShapeType::Capsule:
        return Aabb::fromCenterHalfExtents(
            Vec3(0.0f), Vec3(shape.radius, shape.halfHeight + shape.radius, shape.radius));
    case ShapeType::Cylinder:
        return Aabb::fromCenterHalfExtents(Vec3(0.0f), Vec3(shape.radius, shape.halfHeight, shape.radius));
    case ShapeType::ConvexHull: {
        // A hull-less shape still gets a point box so broad phases never see an empty one.
        if (!hasHull(shape)) return {Vec3(0.0f), Vec3(0.0f)};
        Aabb bounds;
        for (const Vec3& v : shape.hull->vertices()) bounds.grow(v);
        return bounds;
    }
    case ShapeType::Compound:
        return shape.compound ? shape.compound->bounds() : Aabb{Vec3(0.0f), Vec3(0.0f)};
    case ShapeType::Mesh:
    case ShapeType::HeightField:
        if (!hasSurface(shape)) return {Vec3(0.0f), Vec3(0.0f)};
        return visitSurface(shape, [](const auto& s) { return s.bounds(); });
    }
    return {Vec3(0.0f), Vec3(0.0f)};
}

Aabb worldBounds(const Shape& shape, const Transform& transform) {
    const Mat3 rotation = glm::mat3_cast(transform.rotation);
    // GLM matrices are column-major: rotation[j] is the image of local axis j.
    const Vec3& axisY = rotation[1];

    switch (shape.type) {
    case ShapeType::Sphere:
        return Aabb::fromCenterHalfExtents(transform.position, Vec3(shape.radius));
    case ShapeType::Box: {
        // World half extent along axis i: sum over local axes j of |R_ij| * h_j.
        Vec3 half(0.0f);
        for (int j = 0; j < 3; ++j) half += glm::abs(rotation[j]) * shape.halfExtents[j];
        return Aabb::fromCenterHalfExtents(transform.position, half);
    }
    case ShapeType::Capsule: {
        const Vec3 half = shape.halfHeight * glm::abs(axisY) + Vec3(shape.radius);
        return Aabb::fromCenterHalfExtents(transform.position, half);
    }
    case ShapeType::Cylinder: {
        // A cap disc of radius r with unit normal a reaches r * sqrt(1 - a_i^2) along world axis i,
        // written as r * sqrt(a_j^2 + a_k^2) to avoid cancellation when a is nearly along axis i.
        Vec3 half;
        for (int i = 0; i < 3; ++i) {
            const float aj = axisY[(i + 1) % 3], ak = axisY[(i + 2) % 3];
            half[i] = shape.halfHeight * std::abs(axisY[i]) + shape.radius * std::sqrt(aj * aj + ak * ak);
        }
        return Aabb::fromCenterHalfExtents(transform.position, half);
    }
    case ShapeType::ConvexHull: {
        if (!hasHull(shape)) return {transform.position, transform.position};
        Aabb bounds;
        for (const Vec3& v : shape.hull->vertices()) bounds.grow(rotation * v);
        bounds.min += transform.position;
        bounds.max += transform.position;
        return bounds;
    }
    case ShapeType::Compound: {
        // Each child's own tight box: far tighter than the rotated box of the compound's bounds.
        if (!hasChildren(shape)) return {transform.position, transform.position};
        Aabb bounds;
        for (const CompoundChild& child : shape.compound->children())
            bounds.grow(worldBounds(child.shape, childTransform(child, transform)));
        return bounds;
    }
    case ShapeType::Mesh:
    case ShapeType::HeightField:
        return placedBounds(localBounds(shape), transform);
    }
    return {transform.position, transform.position};
}

float volume(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Sphere:
        return 4.0f / 3.0f * kPi * shape.radius * shape.radius * shape.radius;
    case ShapeType::Box:
        return 8.0f * shape.halfExtents.x * shape.halfExtents.y * shape.halfExtents.z;
    case ShapeType::Capsule:
        return kPi * shape.radius * shape.radius * (2.0f * shape.halfHeight + 4.0f / 3.0f * shape.radius);
    case ShapeType::Cylinder:
        return kPi * shape.radius * shape.radius * 2.0f * shape.halfHeight;
    case ShapeType::ConvexHull:
        // Unit density makes the mass the volume; the decomposition is in double precision.
        return massProperties(shape, 1.0f).mass;
    case ShapeType::Compound: {
        float total = 0.0f;
        if (shape.compound)
            for (const CompoundChild& child : shape.compound->children()) total += volume(child.shape);
        return total;
    }
    case ShapeType::Mesh:
    case ShapeType::HeightField: return 0.0f;
    }
    return 0.0f;
}

float rollingRadius(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Sphere:
    case ShapeType::Capsule:
    case ShapeType::Cylinder: return shape.radius;
    case ShapeType::Box:
    case ShapeType::ConvexHull:
    case ShapeType::Compound:
    case ShapeType::Mesh:
    case ShapeType::HeightField: return 0.0f;
    }
    return 0.0f;
}

float minimumExtent(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Sphere:
        return 2.0f * shape.radius;
    case ShapeType::Box:
        return 2.0f * std::min({shape.halfExtents.x, shape.halfExtents.y, shape.halfExtents.z});
    case ShapeType::Capsule:
        return 2.0f * shape.radius;
    case ShapeType::Cylinder:
        return 2.0f * std::min(shape.radius, shape.halfHeight);
    case ShapeType::ConvexHull: {
        // Thinnest width across the face normals. It is exact for boxes and prisms; for other hulls
        // it can exceed the true minimum width (attained between two edges) by a small factor, which
        // is acceptable for a threshold that only decides when to sweep.
        if (!hasHull(shape)) return 0.0f;
        const ConvexHull& hull = *shape.hull;
        float thinnest = std::numeric_limits<float>::max();
        for (const HullFace& face : hull.faces()) {
            float deepest = face.offset;
            for (const Vec3& v : hull.vertices()) deepest = std::min(deepest, glm::dot(face.normal, v));
            thinnest = std::min(thinnest, face.offset - deepest);
        }
        return hull.faces().empty() ? 0.0f : thinnest;
    }
    case ShapeType::Compound: {
        // The thinnest child: a fast compound can pass a wall with its thinnest part first.
        if (!hasChildren(shape)) return 0.0f;
        float thinnest = std::numeric_limits<float>::max();
        for (const CompoundChild& child : shape.compound->children())
            thinnest = std::min(thinnest, minimumExtent(child.shape));
        return thinnest;
    }
    case ShapeType::Mesh:
    case ShapeType::HeightField: {
        const Vec3 size = localBounds(shape).max - localBounds(shape).min;
        return std::min({size.x, size.y, size.z});
    }
    }
    return 0.0f;
}

}  // namespace simcore
