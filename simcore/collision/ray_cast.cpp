// Each shape is hit in its own frame, where it is axis-aligned and centred, with a unit direction:
// distances along a unit direction keep the quadratics well scaled whatever length the caller's
// direction has, and the result is converted back to a fraction once at the end.
//
// Every solver finds the interval of the infinite line that lies in the shape and keeps its start
// only when that start is at or ahead of the origin. A start behind the origin means the origin is
// inside (or the shape is behind), which by convention is no hit.

#include "simcore/collision/ray_cast.h"

#include "simcore/shapes/compound_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcore {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Below this squared sine between the ray and the Y axis, a ray counts as parallel to a round
// side: the side quadratic's leading coefficient would amplify rounding without bound.
constexpr float kParallelToAxisSquared = 1e-12f;

struct LocalRay {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f};  // unit
    float maxDistance = 0.0f;
};

struct LocalHit {
    float distance = 0.0f;  // along the unit local direction
    Vec3 normal{0.0f};      // local frame, unit, outward
};

// Entry distance into a sphere of `radius` centred at `center`, when the origin is outside it.
std::optional<float> enterSphere(const LocalRay& ray, const Vec3& center, float radius) {
    const Vec3 fromCenter = ray.origin - center;
    const float along = glm::dot(fromCenter, ray.direction);
    const float radiusSquared = radius * radius;
    if (lengthSquared(fromCenter) < radiusSquared) return std::nullopt;  // origin inside
    if (along > 0.0f) return std::nullopt;                                // heading away
    // r^2 minus the squared distance from the centre to the line; subtracting the perpendicular
    // part avoids the cancellation of b^2 - c when the origin is far away.
    const float discriminant = radiusSquared - lengthSquared(fromCenter - along * ray.direction);
    if (discriminant < 0.0f) return std::nullopt;
    // Rounding may push an on-surface start a hair behind the origin.
    const float distance = std::max(0.0f, -along - std::sqrt(discriminant));
    if (distance > ray.maxDistance) return std::nullopt;
    return distance;
}

std::optional<LocalHit> castSphere(const LocalRay& ray, float radius) {
    if (!(radius > 0.0f)) return std::nullopt;
    const std::optional<float> distance = enterSphere(ray, Vec3(0.0f), radius);
    if (!distance) return std::nullopt;
    return LocalHit{*distance, glm::normalize(ray.origin + *distance * ray.direction)};
}

std::optional<LocalHit> castBox(const LocalRay& ray, const Vec3& halfExtents) {
    float enter = -kInfinity;
    float exit = kInfinity;
    Vec3 enterNormal(0.0f);
    for (int axis = 0; axis < 3; ++axis) {
        const float o = ray.origin[axis];
        const float d = ray.direction[axis];
        const float h = halfExtents[axis];
        if (d == 0.0f) {
            // Only an exact zero is parallel: 1/d of a tiny d is large but keeps the right order.
            if (o < -h || o > h) return std::nullopt;
            continue;
        }
        const float toMin = (-h - o) / d;
        const float toMax = (h - o) / d;
        const float near = std::min(toMin, toMax);
        const float far = std::max(toMin, toMax);
        if (near > enter) {
            enter = near;
            enterNormal = Vec3(0.0f);
            enterNormal[axis] = d > 0.0f ? -1.0f : 1.0f;  // the slab face the ray crosses first
        }
        exit = std::min(exit, far);
    }
    if (enter > exit || enter < 0.0f || enter > ray.maxDistance) return std::nullopt;
    return LocalHit{enter, enterNormal};
}

// Interval of the line inside the infinite cylinder of `radius` around the local Y axis.
// Returns false when the line misses it.
bool clipToInfiniteCylinder(const LocalRay& ray, float radius, float& enter, float& exit) {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const float a = d.x * d.x + d.z * d.z;
    if (a < kParallelToAxisSquared) {
        enter = -kInfinity;
        exit = kInfinity;
        return o.x * o.x + o.z * o.z <= radius * radius;
    }
    const float b = o.x * d.x + o.z * d.z;
    // b^2 - a c rewritten by Lagrange's identity: a r^2 - (o x d)_y^2, free of cancellation.
    const float cross = o.x * d.z - o.z * d.x;
    const float discriminant = a * radius * radius - cross * cross;
    if (discriminant < 0.0f) return false;
    const float root = std::sqrt(discriminant);
    enter = (-b - root) / a;
    exit = (-b + root) / a;
    return true;
}

Vec3 radialNormal(const Vec3& point) { return glm::normalize(Vec3(point.x, 0.0f, point.z)); }

// The capsule is the union of the cylinder part and the two end spheres; from an origin outside
// all of them, the first entry into the union is the earliest entry into any part. The side counts
// only between the end circles: past them the end sphere is entered first anyway.
std::optional<LocalHit> castCapsule(const LocalRay& ray, float radius, float halfHeight) {
    if (!(radius > 0.0f)) return std::nullopt;
    const Vec3& o = ray.origin;
    const Vec3 nearestOnSegment(0.0f, std::clamp(o.y, -halfHeight, halfHeight), 0.0f);
    if (lengthSquared(o - nearestOnSegment) < radius * radius) return std::nullopt;  // origin inside

    std::optional<LocalHit> best;
    float sideEnter = 0.0f, sideExit = 0.0f;
    if (clipToInfiniteCylinder(ray, radius, sideEnter, sideExit) && sideEnter >= 0.0f &&
        sideEnter <= ray.maxDistance) {
        const Vec3 point = o + sideEnter * ray.direction;
        if (std::abs(point.y) <= halfHeight) best = LocalHit{sideEnter, radialNormal(point)};
    }
    for (const float endY : {-halfHeight, halfHeight}) {
        const Vec3 center(0.0f, endY, 0.0f);
        const std::optional<float> distance = enterSphere(ray, center, radius);
        if (distance && (!best || *distance < best->distance)) {
            best = LocalHit{*distance, glm::normalize(o + *distance * ray.direction - center)};
        }
    }
    return best;
}

// The cylinder is the infinite cylinder intersected with the slab |y| <= halfHeight: the line is
// inside from the later of the two entries to the earlier of the two exits, and whichever entry is
// later is the feature hit (side or cap disc).
std::optional<LocalHit> castCylinder(const LocalRay& ray, float radius, float halfHeight) {
    if (!(radius > 0.0f)) return std::nullopt;
    float sideEnter = 0.0f, sideExit = 0.0f;
    if (!clipToInfiniteCylinder(ray, radius, sideEnter, sideExit)) return std::nullopt;

    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    float capEnter = -kInfinity;
    float capExit = kInfinity;
    if (d.y != 0.0f) {
        const float toBottom = (-halfHeight - o.y) / d.y;
        const float toTop = (halfHeight - o.y) / d.y;
        capEnter = std::min(toBottom, toTop);
        capExit = std::max(toBottom, toTop);
    } else if (o.y < -halfHeight || o.y > halfHeight) {
        return std::nullopt;
    }

    const float enter = std::max(sideEnter, capEnter);
    const float exit = std::min(sideExit, capExit);
    if (enter > exit || enter < 0.0f || enter > ray.maxDistance) return std::nullopt;
    if (sideEnter >= capEnter) return LocalHit{enter, radialNormal(o + enter * d)};
    return LocalHit{enter, Vec3(0.0f, d.y > 0.0f ? -1.0f : 1.0f, 0.0f)};
}

// Clips the line against every face plane: a front face (normal against the ray) can only move the
// entry later, a back face only the exit earlier. The last front face to be crossed is the one hit.
std::optional<LocalHit> castHull(const LocalRay& ray, const ConvexHull& hull) {
    float enter = -kInfinity;
    float exit = kInfinity;
    const HullFace* enterFace = nullptr;
    for (const HullFace& face : hull.faces()) {
        const float approach = glm::dot(face.normal, ray.direction);
        const float outside = glm::dot(face.normal, ray.origin) - face.offset;  // > 0: in front of the plane
        if (approach == 0.0f) {
            if (outside > 0.0f) return std::nullopt;  // parallel and beyond this face forever
            continue;
        }
        const float crossing = -outside / approach;
        if (approach < 0.0f) {
            if (crossing > enter) {
                enter = crossing;
                enterFace = &face;
            }
        } else {
            exit = std::min(exit, crossing);
        }
        if (enter > exit || enter > ray.maxDistance) return std::nullopt;
    }
    // No front face at all, or the entry behind the origin: the origin is inside, or the hull behind.
    if (!enterFace || enter < 0.0f) return std::nullopt;
    return LocalHit{enter, enterFace->normal};
}

}  // namespace

std::optional<RayCastHit> rayCastShape(const Shape& shape, const Transform& transform, const RayCastInput& ray) {
    if (shape.type == ShapeType::Compound) {
        // The nearest child's entry: each child is cast with the limit cut to the best hit so far.
        std::optional<RayCastHit> nearest;
        if (!shape.compound) return nearest;
        RayCastInput clipped = ray;
        for (std::uint32_t i = 0; i < shape.compound->size(); ++i) {
            const CompoundChild& child = shape.compound->children()[i];
            if (auto hit = rayCastShape(child.shape, childTransform(child, transform), clipped)) {
                hit->subShape = i;
                clipped.maxFraction = hit->fraction;
                nearest = hit;
            }
        }
        return nearest;
    }
    if (isSurface(shape.type)) {
        // The surface's own nearest-triangle cast in its frame; a rotation keeps the direction's
        // length, so the fraction is the same in both frames. Two-sided: picking finds it from below.
        if (!isFinite(ray.origin) || !isFinite(ray.direction) || !(ray.maxFraction >= 0.0f)) return std::nullopt;
        const std::optional<SurfaceRayHit> hit = visitSurface(shape, [&](const auto& surface) {
            return surface.rayCast(transform.applyInverse(ray.origin), transform.rotateInverse(ray.direction),
                                   ray.maxFraction);
        });
        if (!hit) return std::nullopt;
        RayCastHit result;
        result.fraction = hit->fraction;
        result.point = ray.origin + hit->fraction * ray.direction;
        result.normal = transform.rotate(hit->normal);
        result.subShape = hit->triangle;
        return result;
    }
    if (!isFinite(ray.origin) || !isFinite(ray.direction) || !(ray.maxFraction >= 0.0f)) return std::nullopt;

    // Length computed on the direction scaled by its largest component, so that neither tiny nor
    // huge directions underflow or overflow when squared.
    const Vec3 magnitude = glm::abs(ray.direction);
    const float largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    if (!(largest > 0.0f)) return std::nullopt;
    const Vec3 scaled = ray.direction / largest;
    const float scaledLength = glm::length(scaled);
    const float length = largest * scaledLength;
    if (!isFinite(length)) return std::nullopt;

    LocalRay local;
    local.origin = transform.applyInverse(ray.origin);
    local.direction = transform.rotateInverse(scaled / scaledLength);
    local.maxDistance = ray.maxFraction * length;  // may be infinite: an unbounded ray
    if (!isFinite(local.origin) || !isFinite(local.direction)) return std::nullopt;  // broken transform

    std::optional<LocalHit> hit;
    switch (shape.type) {
        case ShapeType::Sphere: hit = castSphere(local, shape.radius); break;
        case ShapeType::Box: hit = castBox(local, shape.halfExtents); break;
        case ShapeType::Capsule: hit = castCapsule(local, shape.radius, shape.halfHeight); break;
        case ShapeType::Cylinder: hit = castCylinder(local, shape.radius, shape.halfHeight); break;
        case ShapeType::ConvexHull:
            if (shape.hull) hit = castHull(local, *shape.hull);
            break;
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // cast above
    }
    if (!hit) return std::nullopt;

    RayCastHit result;
    // Rounding of distance / length may overshoot the limit by an ulp; the outer max turns an
    // on-surface -0 into +0.
    result.fraction = std::max(0.0f, std::min(hit->distance / length, ray.maxFraction));
    result.point = ray.origin + result.fraction * ray.direction;
    result.normal = glm::normalize(transform.rotate(hit->normal));
    // Only reachable with extreme inputs (an unbounded ray with a denormal direction).
    if (!isFinite(result.fraction) || !isFinite(result.point) || !isFinite(result.normal)) return std::nullopt;
    return result;
}

}  // namespace simcore
