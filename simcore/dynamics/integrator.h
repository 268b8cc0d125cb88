#pragma once
// Semi-implicit (symplectic) Euler: velocities first from forces, then positions from the new
// velocities. Only awake dynamic bodies move under forces; kinematic bodies move by their velocity.

#include "simcore/dynamics/body_storage.h"

namespace simcore {

struct VelocityIntegration {
    Vec3 gravity{0.0f};              // m/s^2; zero when the gravity effect does not run
    float linearRetention = 1.0f;    // velocity factor over this substep, exp(-rate * dt)
    float angularRetention = 1.0f;
    bool gyroscopic = false;         // include the gyroscopic torque -w x (I w), implicitly
};

void integrateVelocities(BodyStorage& bodies, const VelocityIntegration& params, float dt);

// Advances centres of mass and orientations, renormalises orientations and refreshes world-frame
// inverse inertia.
void integratePositions(BodyStorage& bodies, float dt);

}  // namespace simcore
