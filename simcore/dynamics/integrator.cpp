#include "simcore/dynamics/integrator.h"

#include "simcore/dynamics/constraint_math.h"

namespace simcore {

namespace {

// Torque-free Euler equations I dw/dt + w x (I w) = 0 in body axes, by the implicit midpoint rule:
// I (w1 - w0) + h wm x (I wm) = 0 with wm = (w0 + w1) / 2, solved by Newton's method from w1 = w0.
// The midpoint rule conserves quadratic invariants, here both |I w| = |L| and the energy w.I w / 2,
// and the position update turns the body about w itself, which leaves w in body axes unchanged; so
// a tumbling body neither gains nor loses energy or momentum (the explicit form pumps energy in,
// backward Euler bleeds a few percent of |L| over seconds). Two Newton steps reach float precision
// at any spin a step can resolve.
Vec3 solveGyroscopic(const Quat& orientation, const Mat3& inertia, const Vec3& worldOmega, float dt) {
    const Vec3 w0 = glm::conjugate(orientation) * worldOmega;
    Vec3 w1 = w0;
    for (int iteration = 0; iteration < 2; ++iteration) {
        const Vec3 wm = 0.5f * (w0 + w1);
        const Vec3 iwm = inertia * wm;
        const Vec3 residual = inertia * (w1 - w0) + dt * glm::cross(wm, iwm);
        const Mat3 jacobian = inertia + (0.5f * dt) * (skew(wm) * inertia - skew(iwm));
        w1 -= glm::inverse(jacobian) * residual;
    }
    return orientation * w1;
}

}  // namespace

void BodyIntegrator::integrateVelocities(BodyStorage& bodies, Integrator method, const VelocityIntegration& params,
                                         float dt) {
    const std::size_t n = bodies.size();
    if (method != Integrator::SymplecticEuler) {
        // Kinematic bodies too: their start velocity is their only velocity.
        startLinear_.assign(bodies.linearVelocity.begin(), bodies.linearVelocity.end());
        startAngular_.assign(bodies.angularVelocity.begin(), bodies.angularVelocity.end());
    }
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

void BodyIntegrator::integratePositions(BodyStorage& bodies, Integrator method, float dt) const {
    const std::size_t n = bodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (bodies.motion[i] == MotionType::Static || !bodies.awake[i]) continue;

        Vec3 v = bodies.linearVelocity[i];
        Vec3 w = bodies.angularVelocity[i];
        if (method == Integrator::ExplicitEuler) {
            v = startLinear_[i];
            w = startAngular_[i];
        } else if (method == Integrator::VelocityVerlet) {
            v = 0.5f * (v + startLinear_[i]);
            w = 0.5f * (w + startAngular_[i]);
        }
        bodies.centerOfMass[i] += dt * v;

        // dq/dt = 1/2 (0, w) q; the first-order update is renormalised so |q| = 1 holds to
        // rounding at every step, however long the run.
        Quat& q = bodies.orientation[i];
        const Quat spin(0.0f, w.x, w.y, w.z);
        q = glm::normalize(q + (0.5f * dt) * (spin * q));
        bodies.refreshInverseInertiaWorld(i);
    }
}

}  // namespace simcore
