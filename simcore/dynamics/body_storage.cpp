#include "simcore/dynamics/body_storage.h"

#include <cassert>
#include <utility>

namespace simcore {

namespace {

// Moves the last element into slot `i` and drops the last, for each array.
template <typename... Arrays>
void swapRemove(std::size_t i, Arrays&... arrays) {
    auto removeFrom = [i](auto& array) {
        if (i + 1 != array.size()) array[i] = std::move(array.back());
        array.pop_back();
    };
    (removeFrom(arrays), ...);
}

}  // namespace

BodyId BodyStorage::add(const BodyCreationSettings& settings, const MassProperties& massProperties) {
    const Quat q = glm::normalize(settings.orientation);

    const std::size_t dense = size();
    centerOfMass.push_back(settings.position + q * massProperties.centerOfMass);
    orientation.push_back(q);
    linearVelocity.push_back(settings.motion == MotionType::Static ? Vec3(0.0f) : settings.linearVelocity);
    angularVelocity.push_back(settings.motion == MotionType::Static ? Vec3(0.0f) : settings.angularVelocity);
    force.emplace_back(0.0f);
    torque.emplace_back(0.0f);
    mass.push_back(0.0f);
    inverseMass.push_back(0.0f);
    inertiaLocal.emplace_back(0.0f);
    inverseInertiaLocal.emplace_back(0.0f);
    inverseInertiaWorld.emplace_back(0.0f);
    localCenterOfMass.emplace_back(0.0f);
    massSetting.push_back(settings.mass);
    density.push_back(settings.density);
    motion.push_back(settings.motion);
    shape.push_back(settings.shape);
    friction.push_back(settings.friction);
    restitution.push_back(settings.restitution);
    rollingResistance.push_back(settings.rollingResistance);
    ccd.push_back(settings.ccd ? 1 : 0);
    awake.push_back(settings.motion == MotionType::Static ? 0 : 1);
    sleepTime.push_back(0.0f);
    name.push_back(settings.name);
    proxy.push_back(0);
    bounds.push_back(worldBounds(settings.shape, Transform{settings.position, q}));
    setMassProperties(dense, massProperties);
    refreshInverseInertiaWorld(dense);

    return slots_.add();
}

void BodyStorage::setMassProperties(std::size_t i, const MassProperties& massProperties) {
    const bool isDynamic = motion[i] == MotionType::Dynamic;
    mass[i] = isDynamic ? massProperties.mass : 0.0f;
    inverseMass[i] = isDynamic ? 1.0f / massProperties.mass : 0.0f;
    inertiaLocal[i] = isDynamic ? massProperties.inertia : Mat3(0.0f);
    // Inverted in double: the determinant of a tiny body's tensor (a 0.1 mm bead's moments are
    // about 4e-15 kg m^2) underflows float.
    inverseInertiaLocal[i] = isDynamic ? Mat3(glm::inverse(glm::dmat3(massProperties.inertia))) : Mat3(0.0f);
    localCenterOfMass[i] = massProperties.centerOfMass;
}

void BodyStorage::remove(BodyId id) {
    const int dense = denseIndex(id);
    assert(dense >= 0);
    if (dense < 0) return;
    const auto i = static_cast<std::size_t>(dense);
    swapRemove(i, centerOfMass, orientation, linearVelocity, angularVelocity, force, torque, mass,
               inverseMass, inertiaLocal, inverseInertiaLocal, inverseInertiaWorld,
               localCenterOfMass, massSetting, density, motion, shape, friction, restitution, rollingResistance, ccd, awake, sleepTime,
               name, proxy, bounds);
    slots_.removeAt(i);
}

void BodyStorage::refreshInverseInertiaWorld(std::size_t i) {
    // The same moment about every axis (a sphere, a cube, a static body's zero): turning the body
    // leaves the tensor as it is, exactly, where rotating it would add rounding.
    if (isScaledIdentity(inverseInertiaLocal[i])) {
        inverseInertiaWorld[i] = inverseInertiaLocal[i];
        return;
    }
    const Mat3 r = glm::mat3_cast(orientation[i]);
    const Mat3& local = inverseInertiaLocal[i];
    if (!isDiagonal(local)) {
        inverseInertiaWorld[i] = r * local * glm::transpose(r);
        return;
    }
    // Moments about the body's axes (every shape but a hull): the sum over the axes of the moment
    // times the axis's outer product, half the work of the two products above.
    const Vec3 scaledX = local[0][0] * r[0], scaledY = local[1][1] * r[1], scaledZ = local[2][2] * r[2];
    Mat3& world = inverseInertiaWorld[i];
    for (int column = 0; column < 3; ++column)
        for (int row = column; row < 3; ++row)
            world[column][row] = world[row][column] =
                scaledX[row] * r[0][column] + scaledY[row] * r[1][column] + scaledZ[row] * r[2][column];
}

}  // namespace simcore
