#pragma once
// Moves bodies through one substep: velocities from forces first, then - after the constraints
// have corrected the velocities - positions, by the chosen Integrator (see world_settings.h). Only
// awake dynamic bodies move under forces; kinematic bodies move by their velocity.

#include "simcore/dynamics/body_storage.h"
#include "simcore/parallel/task_pool.h"
#include "simcore/world_settings.h"

#include <cstdint>
#include <vector>

namespace simcore {

struct VelocityIntegration {
    Vec3 gravity{0.0f};              // m/s^2; zero when the gravity effect does not run
    float linearRetention = 1.0f;    // velocity factor over this substep, exp(-rate * dt)
    float angularRetention = 1.0f;
    bool gyroscopic = false;         // include the gyroscopic torque -w x (I w), implicitly
};

class BodyIntegrator {
public:
    // Each returns how many bodies' velocities it cut to the safety bound (1e5 m/s, a quarter turn
    // per substep dt), which it applies to every awake dynamic body before using a velocity: more
    // than zero means the simulation is unstable.
    //
    // Updates velocities; the integrators that move by the start-of-substep velocity keep a copy.
    // Applied forces and torques act in every substep; the world clears them when the step ends.
    // Both integrations run over the bodies on the pool's threads, with the same result for any number.
    std::uint32_t integrateVelocities(BodyStorage& bodies, Integrator method, const VelocityIntegration& params, float dt,
                                      TaskPool& pool);
    // Advances centres of mass and orientations, renormalises orientations and refreshes world-
    // frame inverse inertia. `method` must be the one given to this substep's integrateVelocities.
    std::uint32_t integratePositions(BodyStorage& bodies, Integrator method, float dt, TaskPool& pool) const;
    // Only the bound.
    std::uint32_t boundVelocities(BodyStorage& bodies, float dt) const;

private:
    // One body (dense index i); each returns whether it had to bound the body's velocity.
    bool integrateVelocity(BodyStorage& bodies, std::size_t i, bool keepStart, const VelocityIntegration& params, float dt);
    bool integratePosition(BodyStorage& bodies, std::size_t i, Integrator method, float dt) const;

    std::vector<Vec3> startLinear_, startAngular_;  // by dense index; reused, so the step never allocates
};

}  // namespace simcore
