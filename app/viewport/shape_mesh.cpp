#include "app/viewport/shape_mesh.h"

#include <algorithm>
#include <cmath>

namespace interplay {
namespace {

constexpr float kTwoPi = 2.0f * simcore::kPi;

// One point of a surface-of-revolution profile in the (radius, y) half-plane, with its normal in
// that plane. A profile runs from the bottom to the top of the solid; `hardEdge` starts a new band
// without joining it to the previous point (so caps and sides can carry different normals).
struct ProfilePoint {
    float r = 0.0f, y = 0.0f;
    float nr = 0.0f, ny = 0.0f;
    bool hardEdge = false;
};

// Sweeps the profile around local Y. Rings whose radius is zero are poles: the bands touching them
// become triangle fans instead of quads with a degenerate half.
void lathe(const std::vector<ProfilePoint>& profile, int slices, ShapeMesh& mesh) {
    const auto ringStart = [&](const ProfilePoint& p) {
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int j = 0; j <= slices; ++j) {
            // The seam column reuses angle 0 exactly, so seam positions match bit for bit.
            const float angle = kTwoPi * static_cast<float>(j % slices) / static_cast<float>(slices);
            const float c = std::cos(angle), s = std::sin(angle);
            mesh.vertices.push_back({{p.r * c, p.y, p.r * s}, glm::normalize(glm::vec3{p.nr * c, p.ny, p.nr * s})});
        }
        return first;
    };

    std::uint32_t previous = 0;
    for (std::size_t k = 0; k < profile.size(); ++k) {
        const std::uint32_t current = ringStart(profile[k]);
        if (k > 0 && !profile[k].hardEdge) {
            const bool fromPole = profile[k - 1].r == 0.0f;
            const bool toPole = profile[k].r == 0.0f;
            for (int j = 0; j < slices; ++j) {
                const std::uint32_t a0 = previous + j, a1 = previous + j + 1;
                const std::uint32_t b0 = current + j, b1 = current + j + 1;
                // With angle increasing towards +z and the profile running bottom to top,
                // (a0, b0, b1) and (a0, b1, a1) are counter-clockwise seen from outside.
                if (!toPole) mesh.indices.insert(mesh.indices.end(), {a0, b0, b1});
                if (!fromPole) mesh.indices.insert(mesh.indices.end(), {a0, b1, a1});
            }
        }
        previous = current;
    }
}

// Quarter circle of a sphere of `radius` centred at y = `centerY`, latitudes from `fromAngle` to
// `toAngle` (radians, -pi/2 = bottom pole) in `bands` steps.
void appendArc(std::vector<ProfilePoint>& profile, float radius, float centerY, float fromAngle, float toAngle,
               int bands, bool skipFirst) {
    for (int i = skipFirst ? 1 : 0; i <= bands; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(bands);
        const float angle = fromAngle + (toAngle - fromAngle) * t;
        float c = std::cos(angle);
        const float s = std::sin(angle);
        // Exact zero at the poles so lathe() recognises them (cos(pi/2) is not 0 in float).
        if (std::abs(angle) >= 0.5f * simcore::kPi - 1e-6f) c = 0.0f;
        profile.push_back({radius * c, centerY + radius * s, c, s, false});
    }
}

ShapeMesh sphereMesh(float radius, const MeshDetail& d) {
    std::vector<ProfilePoint> profile;
    appendArc(profile, radius, 0.0f, -0.5f * simcore::kPi, 0.5f * simcore::kPi, std::max(d.stacks, 2), false);
    ShapeMesh mesh;
    lathe(profile, std::max(d.slices, 3), mesh);
    return mesh;
}

ShapeMesh capsuleMesh(float radius, float halfHeight, const MeshDetail& d) {
    // Bottom hemisphere up to its equator, then the top one from its equator: the band between the
    // two equators is the straight part, and its normals are radial on both rings as they should be.
    const int bands = std::max(d.stacks / 2, 1);
    std::vector<ProfilePoint> profile;
    appendArc(profile, radius, -halfHeight, -0.5f * simcore::kPi, 0.0f, bands, false);
    appendArc(profile, radius, halfHeight, 0.0f, 0.5f * simcore::kPi, bands, halfHeight == 0.0f);
    ShapeMesh mesh;
    lathe(profile, std::max(d.slices, 3), mesh);
    return mesh;
}

ShapeMesh cylinderMesh(float radius, float halfHeight, const MeshDetail& d) {
    const float h = halfHeight, r = radius;
    const std::vector<ProfilePoint> profile = {
        {0.0f, -h, 0.0f, -1.0f, false},  // bottom cap centre
        {r, -h, 0.0f, -1.0f, false},     // bottom cap rim
        {r, -h, 1.0f, 0.0f, true},       // side, bottom
        {r, h, 1.0f, 0.0f, false},       // side, top
        {r, h, 0.0f, 1.0f, true},        // top cap rim
        {0.0f, h, 0.0f, 1.0f, false},    // top cap centre
    };
    ShapeMesh mesh;
    lathe(profile, std::max(d.slices, 3), mesh);
    return mesh;
}

ShapeMesh boxMesh(const glm::vec3& e) {
    ShapeMesh mesh;
    // For each axis and sign, the face's two in-plane axes ordered so that u x v = normal.
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            glm::vec3 u(0.0f), v(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
            for (const auto& [su, sv] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
                mesh.vertices.push_back({(n + su * u + sv * v) * e, n});
            }
            mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        }
    }
    return mesh;
}

ShapeMesh hullMesh(const simcore::ConvexHull& hull) {
    // Flat-shaded: each face gets its own vertices carrying the face normal, fanned from its first
    // vertex (faces are convex and counter-clockwise from outside).
    ShapeMesh mesh;
    const auto& points = hull.vertices();
    const auto& faceIndices = hull.faceVertexIndices();
    for (const simcore::HullFace& face : hull.faces()) {
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (std::uint32_t k = 0; k < face.vertexCount; ++k) {
            mesh.vertices.push_back({points[faceIndices[face.firstIndex + k]], face.normal});
        }
        for (std::uint32_t k = 1; k + 1 < face.vertexCount; ++k) {
            mesh.indices.insert(mesh.indices.end(), {first, first + k, first + k + 1});
        }
    }
    return mesh;
}

// A surface's triangles with their face normals; three vertices each, since neighbours may crease.
ShapeMesh surfaceMesh(const simcore::Shape& shape) {
    ShapeMesh mesh;
    const std::size_t count = simcore::subShapeCount(shape);
    mesh.vertices.reserve(3 * count);
    mesh.indices.reserve(3 * count);
    simcore::visitSurface(shape, [&](const auto& surface) {
        for (std::uint32_t t = 0; t < count; ++t) {
            const simcore::Triangle triangle = surface.triangle(t);
            for (const simcore::Vec3& v : triangle.vertices) {
                mesh.indices.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
                mesh.vertices.push_back({v, triangle.normal});
            }
        }
    });
    return mesh;
}

}  // namespace

ShapeMesh buildShapeMesh(const simcore::Shape& shape, const MeshDetail& detail) {
    switch (shape.type) {
    case simcore::ShapeType::Sphere: return sphereMesh(shape.radius, detail);
    case simcore::ShapeType::Box: return boxMesh(shape.halfExtents);
    case simcore::ShapeType::Capsule: return capsuleMesh(shape.radius, shape.halfHeight, detail);
    case simcore::ShapeType::Cylinder: return cylinderMesh(shape.radius, shape.halfHeight, detail);
    case simcore::ShapeType::ConvexHull: return shape.hull ? hullMesh(*shape.hull) : ShapeMesh{};
    case simcore::ShapeType::Compound: break;  // drawn child by child (body_batches.h)
    case simcore::ShapeType::Mesh: return shape.mesh ? surfaceMesh(shape) : ShapeMesh{};
    case simcore::ShapeType::HeightField: return shape.heightField ? surfaceMesh(shape) : ShapeMesh{};
    }
    return {};
}

}  // namespace interplay
