// Mass properties of uniform solids. Primitives use textbook closed forms; hulls are decomposed
// into signed tetrahedra, accumulated in double so that large or off-centre hulls keep their
// precision, and shifted to the centre of mass at the end.

#include "simcore/shapes/compound_shape.h"
#include "simcore/shapes/shape.h"

#include <glm/gtc/constants.hpp>

#include <vector>

namespace simcore {
namespace {

using DVec3 = glm::dvec3;
using DMat3 = glm::dmat3;

MassProperties withDiagonalInertia(double mass, const DVec3& inertia) {
    MassProperties props;
    props.mass = float(mass);
    props.inertia = diagonal(Vec3(inertia));
    return props;
}

MassProperties sphereProperties(double r, double density) {
    const double mass = density * 4.0 / 3.0 * glm::pi<double>() * r * r * r;
    const double i = 0.4 * mass * r * r;
    return withDiagonalInertia(mass, DVec3(i));
}

MassProperties boxProperties(const DVec3& half, double density) {
    const double mass = density * 8.0 * half.x * half.y * half.z;
    // m/12 (b^2 + c^2) with full sides b = 2 h_b, c = 2 h_c.
    const DVec3 h2 = half * half;
    return withDiagonalInertia(mass, mass / 3.0 * DVec3(h2.y + h2.z, h2.x + h2.z, h2.x + h2.y));
}

MassProperties cylinderProperties(double r, double halfHeight, double density) {
    const double height = 2.0 * halfHeight;
    const double mass = density * glm::pi<double>() * r * r * height;
    const double axial = 0.5 * mass * r * r;
    const double transverse = mass / 12.0 * (3.0 * r * r + height * height);
    return withDiagonalInertia(mass, DVec3(transverse, axial, transverse));
}

// Cylinder of height 2 h plus two hemispherical caps. A cap's transverse inertia about its own
// centre of mass (3r/8 from its flat face) is (2/5 - 9/64) m r^2 = 83/320 m r^2; it is then
// carried by the parallel-axis theorem to the capsule centre, h + 3r/8 away.
MassProperties capsuleProperties(double r, double halfHeight, double density) {
    const double pi = glm::pi<double>();
    const double height = 2.0 * halfHeight;
    const double cylinderMass = density * pi * r * r * height;
    const double capMass = density * 2.0 / 3.0 * pi * r * r * r;  // one hemisphere

    const double axial = 0.5 * cylinderMass * r * r + 2.0 * (0.4 * capMass * r * r);
    const double capOffset = halfHeight + 3.0 / 8.0 * r;
    const double capTransverse = capMass * (83.0 / 320.0 * r * r + capOffset * capOffset);
    const double transverse = cylinderMass / 12.0 * (3.0 * r * r + height * height) + 2.0 * capTransverse;
    return withDiagonalInertia(cylinderMass + 2.0 * capMass, DVec3(transverse, axial, transverse));
}

// Each face is fanned into triangles and each triangle forms a tetrahedron with a reference point
// inside the hull (the vertex mean, which keeps the arms short). For a tetrahedron (0, a, b, c)
// with d = det[a b c]: volume d/6, first moment d/24 (a+b+c), and second moment
// integral(x x^T) = d/120 (a a^T + b b^T + c c^T + s s^T) with s = a+b+c, which follows from the
// canonical tetrahedron's (I + 1 1^T)/120 mapped through [a b c].
MassProperties hullProperties(const ConvexHull& hull, double density) {
    const auto& vertices = hull.vertices();
    const auto& indices = hull.faceVertexIndices();
    if (vertices.empty()) return {};

    DVec3 reference(0.0);
    for (const Vec3& v : vertices) reference += DVec3(v);
    reference /= double(vertices.size());

    double volume = 0.0;
    DVec3 firstMoment(0.0);
    DMat3 secondMoment(0.0);
    for (const HullFace& face : hull.faces()) {
        const DVec3 a = DVec3(vertices[indices[face.firstIndex]]) - reference;
        for (std::uint32_t k = 1; k + 1 < face.vertexCount; ++k) {
            const DVec3 b = DVec3(vertices[indices[face.firstIndex + k]]) - reference;
            const DVec3 c = DVec3(vertices[indices[face.firstIndex + k + 1]]) - reference;
            const double det = glm::dot(a, glm::cross(b, c));
            const DVec3 s = a + b + c;
            volume += det / 6.0;
            firstMoment += det / 24.0 * s;
            secondMoment += det / 120.0 *
                            (glm::outerProduct(a, a) + glm::outerProduct(b, b) + glm::outerProduct(c, c) +
                             glm::outerProduct(s, s));
        }
    }
    if (!(volume > 0.0)) return {};

    const DVec3 centroid = firstMoment / volume;  // relative to the reference point
    // Second moment about the centre of mass, then inertia = trace(C) I - C.
    const DMat3 central = secondMoment - volume * glm::outerProduct(centroid, centroid);
    const double trace = central[0][0] + central[1][1] + central[2][2];
    const DMat3 inertia = density * (trace * DMat3(1.0) - central);

    MassProperties props;
    props.mass = float(density * volume);
    props.centerOfMass = Vec3(reference + centroid);
    props.inertia = Mat3(inertia);
    return props;
}

// The children's properties summed about the common centre of mass: each child's inertia turned
// into the body frame (R I R^T), then carried from its own centre by the parallel-axis theorem,
// m (|d|^2 E - d d^T). The body's origin stays where the user put it; only the centre moves.
MassProperties compoundProperties(const CompoundShape& compound, double density) {
    std::vector<MassProperties> parts;
    parts.reserve(compound.size());
    double mass = 0.0;
    DVec3 firstMoment(0.0);
    for (const CompoundChild& child : compound.children()) {
        parts.push_back(massProperties(child.shape, float(density)));
        mass += parts.back().mass;
        firstMoment += double(parts.back().mass) * DVec3(child.pose.apply(parts.back().centerOfMass));
    }
    if (!(mass > 0.0)) return {};
    const DVec3 center = firstMoment / mass;

    DMat3 inertia(0.0);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const Transform& pose = compound.children()[i].pose;
        const DMat3 rotation = DMat3(glm::mat3_cast(pose.rotation));
        const DVec3 d = DVec3(pose.apply(parts[i].centerOfMass)) - center;
        inertia += rotation * DMat3(parts[i].inertia) * glm::transpose(rotation) +
                   double(parts[i].mass) * (glm::dot(d, d) * DMat3(1.0) - glm::outerProduct(d, d));
    }
    MassProperties props;
    props.mass = float(mass);
    props.centerOfMass = Vec3(center);
    props.inertia = Mat3(inertia);
    return props;
}

}  // namespace

MassProperties massProperties(const Shape& shape, float density) {
    const double rho = density;
    switch (shape.type) {
    case ShapeType::Sphere: return sphereProperties(shape.radius, rho);
    case ShapeType::Box: return boxProperties(DVec3(shape.halfExtents), rho);
    case ShapeType::Capsule: return capsuleProperties(shape.radius, shape.halfHeight, rho);
    case ShapeType::Cylinder: return cylinderProperties(shape.radius, shape.halfHeight, rho);
    case ShapeType::ConvexHull: return shape.hull ? hullProperties(*shape.hull, rho) : MassProperties{};
    case ShapeType::Compound: return shape.compound ? compoundProperties(*shape.compound, rho) : MassProperties{};
    case ShapeType::Mesh:
    case ShapeType::HeightField: return {};  // a surface has no volume: static and kinematic only
    }
    return {};
}

MassProperties massPropertiesForMass(const Shape& shape, float mass) {
    MassProperties props = massProperties(shape, 1.0f);
    if (!(props.mass > 0.0f)) {
        // A shape without volume has no meaningful inertia; still honour the requested mass.
        props.mass = mass;
        props.inertia = Mat3(0.0f);
        return props;
    }
    const float scale = mass / props.mass;
    props.mass = mass;
    props.inertia *= scale;
    return props;
}

}  // namespace simcore
