#pragma once
// Body state as a structure of arrays. Every per-body quantity lives in its own contiguous array,
// indexed by a dense index; stable BodyIds map to dense indices through a slot table, so removing a
// body (swap with the last, pop) never invalidates other handles.

#include "simcore/dynamics/body.h"
#include "simcore/dynamics/slot_map.h"

#include <optional>
#include <string>
#include <vector>

namespace simcore {

class BodyStorage {
public:
    // Dense arrays, all of size size(). The step iterates these directly.
    std::vector<Vec3> centerOfMass;          // world frame (m); the integrated position
    std::vector<Quat> orientation;           // unit quaternion, body -> world
    std::vector<Vec3> linearVelocity;        // m/s, of the centre of mass
    std::vector<Vec3> angularVelocity;       // rad/s, world frame
    std::vector<Vec3> force;                 // N, accumulated until the next step
    std::vector<Vec3> torque;                // N m, accumulated until the next step
    std::vector<float> mass;                 // kg; 0 for static and kinematic bodies
    std::vector<float> inverseMass;          // 1/kg; 0 for static and kinematic bodies
    std::vector<Mat3> inertiaLocal;          // kg m^2 about the centre of mass, body axes
    std::vector<Mat3> inverseInertiaLocal;   // zero for static and kinematic bodies
    std::vector<Mat3> inverseInertiaWorld;   // R I^-1 R^T, refreshed when orientation changes
    std::vector<Vec3> localCenterOfMass;     // body origin -> centre of mass, body frame (m)
    // What the mass was made from, kept for every body so a change of shape or motion type
    // can recompute it (a static body turned dynamic gets the mass it was authored with).
    std::vector<std::optional<float>> massSetting;  // kg, when given; else from density
    std::vector<float> density;              // kg/m^3, used when massSetting is unset
    std::vector<MotionType> motion;
    std::vector<Shape> shape;
    std::vector<float> friction;
    std::vector<float> restitution;
    std::vector<float> rollingResistance;    // coefficient C (dimensionless)
    std::vector<std::uint8_t> ccd;           // 1 when the body always sweeps
    std::vector<std::uint8_t> awake;         // 1 when simulated this step
    std::vector<float> sleepTime;            // s the body has been below the sleep thresholds
    std::vector<std::string> name;
    std::vector<std::uint32_t> proxy;        // broad-phase proxy, set by the world
    std::vector<Aabb> bounds;                // tight world bounds, refreshed by the world's broad phase

    std::size_t size() const { return centerOfMass.size(); }

    // Appends a body; the settings must already be validated (World::createBody does it).
    BodyId add(const BodyCreationSettings& settings, const MassProperties& massProperties);
    void remove(BodyId id);

    // Dense index of a live body, or -1 for a stale or invalid id.
    int denseIndex(BodyId id) const { return slots_.denseIndex(id); }
    BodyId idAt(std::size_t denseIndex) const { return slots_.idAt(denseIndex); }
    std::size_t denseIndexOfSlot(std::uint32_t slot) const { return slots_.denseIndexOfSlot(slot); }  // slot must be live

    // Whether the step moves the body: dynamic and awake (static, kinematic and sleeping bodies
    // take part in contacts as immovable).
    bool isAwakeDynamic(std::size_t i) const { return motion[i] == MotionType::Dynamic && awake[i]; }

    Vec3 origin(std::size_t i) const { return centerOfMass[i] - orientation[i] * localCenterOfMass[i]; }
    Transform transform(std::size_t i) const { return {origin(i), orientation[i]}; }
    void refreshInverseInertiaWorld(std::size_t i);
    // Sets mass, inertia and the local centre of mass (zero mass and inertia unless dynamic);
    // the caller keeps the centre of mass and the world inertia in step.
    void setMassProperties(std::size_t i, const MassProperties& massProperties);

private:
    SlotMap<BodyId> slots_;
};

}  // namespace simcore
