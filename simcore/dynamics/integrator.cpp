#include "simcore/dynamics/integrator.h"

namespace simcore {

namespace {

Mat3 skew(const Vec3& v) {
    // Column-major: skew(v) * x == cross(v, x).
    return Mat3(0.0f, v.z, -v.y, -v.z, 0.0f, v.x, v.y, -v.x, 0.0f);
}

// Torque-free Euler equations I dw/dt + w x (I w) = 0, integrated implicitly in body axes with one
// Newton step (Catto, "Numerical Methods", GDC 2015). The explicit form pumps energy into a tumbling
// body; the implicit one damps slightly instead, so rotation stays bounded however long it runs.
Vec3 solveGyroscopic(const Quat& orientation, const Mat3& inertia, const Vec3& worldOmega, float dt) {
    const Vec3 w = glm::conjugate(orientation) * worldOmega;
    const Vec3 iw = inertia * w;
    const Vec3 residual = dt * glm::cross(w, iw);
    const Mat3 jacobian = inertia + dt * (skew(w) * inertia - skew(iw));
    return orientation * (w - glm::inverse(jacobian) * residual);
}

}  // namespace

void integrateVelocities(BodyStorage& bodies, const VelocityIntegration& params, float dt) {
    const std::size_t n = bodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] != MotionType::Dynamic || !bodies.awake[i]) continue;

        Vec3 v = bodies.linearVelocity[i];
        Vec3 w = bodies.angularVelocity[i];
        v += dt * (params.gravity + bodies.inverseMass[i] * bodies.force[i]);

        w += dt * (bodies.inverseInertiaWorld[i] * bodies.torque[i]);
        if (params.gyroscopic) w = solveGyroscopic(bodies.orientation[i], bodies.inertiaLocal[i], w, dt);

        bodies.linearVelocity[i] = v * params.linearRetention;
        bodies.angularVelocity[i] = w * params.angularRetention;
        bodies.force[i] = Vec3(0.0f);
        bodies.torque[i] = Vec3(0.0f);
    }
}

void integratePositions(BodyStorage& bodies, float dt) {
    const std::size_t n = bodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] == MotionType::Static || !bodies.awake[i]) continue;

        bodies.centerOfMass[i] += dt * bodies.linearVelocity[i];

        // dq/dt = 1/2 (0, w) q; the first-order update is renormalised so |q| = 1 holds to
        // rounding at every step, however long the run.
        const Vec3& w = bodies.angularVelocity[i];
        Quat& q = bodies.orientation[i];
        const Quat spin(0.0f, w.x, w.y, w.z);
        q = glm::normalize(q + (0.5f * dt) * (spin * q));
        bodies.refreshInverseInertiaWorld(i);
    }
}

}  // namespace simcore
