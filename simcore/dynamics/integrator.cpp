#include "simcore/dynamics/integrator.h"

#include <algorithm>
#include <cmath>

namespace simcore {

namespace {

// Safety bounds on a dynamic body's velocity, far beyond anything a substep can resolve, so that
// no instability (a violently over-constrained assembly, a joint torn kilometres apart) can grow a
// state to infinity: at worst a body flies off at kMaxLinearSpeed, spinning a quarter turn per
// substep (Box2D bounds rotation the same way).
constexpr float kMaxLinearSpeed = 1e5f;                      // m/s, ten times the loader's limit
constexpr float kMaxRotationPerSubstep = 0.25f * 3.14159265f;  // rad

bool boundSpeed(Vec3& velocity, float maxSpeed) {
    const float speed2 = glm::dot(velocity, velocity);
    if (!(speed2 > maxSpeed * maxSpeed)) return false;
    velocity *= maxSpeed / std::sqrt(speed2);
    return true;
}

// Whether it had to cut either velocity.
bool boundVelocity(Vec3& linear, Vec3& angular, float dt) {
    const bool linearCut = boundSpeed(linear, kMaxLinearSpeed);
    return boundSpeed(angular, kMaxRotationPerSubstep / dt) || linearCut;
}

// Column-major cross-product matrix, skew(v) * x == cross(v, x), for the solve below.
glm::dmat3 skew(const glm::dvec3& v) { return glm::dmat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); }

// Whether a body-axes inertia is diagonal with equal moments that scale to exactly 1 (for some
// moments x * (1 / x) rounds to just below 1).
bool isotropicUnitScaled(const Mat3& inertia, double largestMoment) {
    return isScaledIdentity(inertia) && largestMoment * (1.0 / largestMoment) == 1.0;
}

// The axis of a diagonal inertia whose moment differs from the two others, which are equal; -1
// where there is none (the three all equal or all different, or axes off the body's).
int symmetryAxis(const Mat3& inertia) {
    if (!isDiagonal(inertia)) return -1;
    const float x = inertia[0][0], y = inertia[1][1], z = inertia[2][2];
    if (x == y) return y == z ? -1 : 2;
    if (y == z) return 0;
    return x == z ? 1 : -1;
}

// Torque-free Euler equations I dw/dt + w x (I w) = 0 in body axes, by the implicit midpoint rule:
// I (w1 - w0) + h wm x (I wm) = 0 with wm = (w0 + w1) / 2, solved by Newton's method from w1 = w0.
// The midpoint rule conserves quadratic invariants, here both |I w| = |L| and the energy w.I w / 2,
// and the position update turns the body about w itself, which leaves w in body axes unchanged; so
// a tumbling body neither gains nor loses energy or momentum (the explicit form pumps energy in,
// backward Euler bleeds a few percent of |L| over seconds). Two Newton steps reach float precision
// at any spin a step can resolve. Returns the new angular velocity in world axes.
//
// Over the 10^4-10^5 substeps of a long tumble float rounding must not add up, and twice it did
// (a box tumbling about its middle axis for 100 s at 5 ms steps reached 1.0118 E0):
//  - The whole of w went to body axes and back every substep. The orientation is unit only to
//    rounding, and float normalisation leaves |q|^2 about 5e-8 above 1 on average (biased, not
//    merely noisy); glm rotates as if |q| = 1, so such a q lengthens a vector across its axis by
//    up to 2 (|q|^2 - 1), and w grew by about 7e-8 a substep. Only the change w1 - w0 is turned
//    back to world axes now: it is a small fraction of w, and so is its error.
//  - In float the energy guard below met rounding noise of either sign, 1e-7 of the energy, in
//    every substep and cut only the upward half: a ratchet that took 0.45 % over the same 100 s.
//    The solve and the guard run in double, where the guard sees only what it is for, the Newton
//    steps' shortfall at a fast spin (always an excess).
// What remains is the rounding of w in float as the change is added, which wanders either way:
// within 1e-4 of E0 over those 100 s at 5 ms or 1/60 s, 4e-4 at 1 ms (4e5 substeps).
Vec3 solveGyroscopic(const Quat& orientation, const Mat3& bodyInertia, const Vec3& worldOmega, float dt) {
    using glm::dmat3, glm::dvec3;
    // The equation is homogeneous in I, so it is solved with I scaled to a largest moment of 1: a
    // 0.1 mm bead's moments (about 1e-15 kg m^2) would make the Jacobian's determinant tiny.
    const double largestMoment = std::max({bodyInertia[0][0], bodyInertia[1][1], bodyInertia[2][2]});
    // The same moment about every axis (a sphere, a cube): w x (I w) = 0, no gyroscopic torque.
    // Where the scaled inertia is exactly the identity the solve below returns worldOmega + 0 bit
    // for bit (checked over 2.5 million spins and moments, zeros of either sign included), so it is
    // skipped (the solve took a tenth of mixed1k's step, 7 % of pyramid10's, in perf on one thread).
    if (isotropicUnitScaled(bodyInertia, largestMoment)) return worldOmega + Vec3(0.0f);  // + 0: as the sum below
    const dmat3 inertia = dmat3(bodyInertia) * (1.0 / largestMoment);
    const Vec3 bodyOmega = glm::conjugate(orientation) * worldOmega;
    const dvec3 w0(bodyOmega);
    const double h = dt;
    dvec3 w1 = w0;
    if (const int axis = symmetryAxis(bodyInertia); axis >= 0) {
        // Two equal moments a about the other axes (a cylinder, a capsule, a square bar): the rule
        // is linear there and solves in closed form. The spin about the axis stays; the rest, as a
        // complex number z, becomes z (1 + ik) / (1 - ik) with k = h (c - a) w_axis / (2 a), a
        // rotation about the axis (two Newton steps cost a tenth of mixed1k's step).
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const double k = 0.5 * h * (inertia[axis][axis] - inertia[u][u]) * w0[axis] / inertia[u][u];
        const double scale = 1.0 / (1.0 + k * k), cosine = (1.0 - k * k) * scale, sine = 2.0 * k * scale;
        w1[u] = cosine * w0[u] - sine * w0[v];
        w1[v] = sine * w0[u] + cosine * w0[v];
    } else {
        for (int iteration = 0; iteration < 2; ++iteration) {
            const dvec3 wm = 0.5 * (w0 + w1);
            const dvec3 iwm = inertia * wm;
            const dvec3 residual = inertia * (w1 - w0) + h * glm::cross(wm, iwm);
            const dmat3 jacobian = inertia + (0.5 * h) * (skew(wm) * inertia - skew(iwm));
            w1 -= glm::inverse(jacobian) * residual;
        }
    }
    // The torque is a rotation of L, so the exact step keeps the energy. Where the two Newton steps
    // fall short (a spin too fast for the substep, as violent constraint impulses make) the result
    // is scaled back to the energy it started with: the term may move energy between the axes,
    // never add it.
    const double energy0 = glm::dot(w0, inertia * w0), energy1 = glm::dot(w1, inertia * w1);
    if (energy1 > energy0) w1 *= std::sqrt(energy0 / energy1);
    return worldOmega + orientation * Vec3(w1 - w0);
}

// Bodies per chunk of a parallel integration: each costs tens of nanoseconds, so a chunk must hold
// many to outweigh handing it to a thread.
constexpr std::size_t kBodyGrain = 256;

}  // namespace

std::uint32_t BodyIntegrator::integrateVelocities(BodyStorage& bodies, Integrator method, const VelocityIntegration& params,
                                                  float dt, TaskPool& pool) {
    const std::size_t n = bodies.size();
    const bool keepStart = method != Integrator::SymplecticEuler;
    if (keepStart) {
        startLinear_.resize(n);
        startAngular_.resize(n);
    }
    // Every body's update reads and writes only its own entries.
    return static_cast<std::uint32_t>(pool.parallelSum(n, kBodyGrain, [&](std::size_t begin, std::size_t end) {
        std::uint32_t bounded = 0;
        for (std::size_t i = begin; i < end; ++i) {
            if (integrateVelocity(bodies, i, keepStart, params, dt)) ++bounded;
        }
        return bounded;
    }));
}

bool BodyIntegrator::integrateVelocity(BodyStorage& bodies, std::size_t i, bool keepStart, const VelocityIntegration& params,
                                       float dt) {
    const bool moves = bodies.isAwakeDynamic(i);
    // The relax passes of the substep before may have left a torn assembly beyond the bound.
    const bool bounded = moves && boundVelocity(bodies.linearVelocity[i], bodies.angularVelocity[i], dt);
    if (keepStart) {
        // Kinematic bodies too: their start velocity is their only velocity.
        startLinear_[i] = bodies.linearVelocity[i];
        startAngular_[i] = bodies.angularVelocity[i];
    }
    if (!moves) return bounded;

    Vec3 v = bodies.linearVelocity[i];
    Vec3 w = bodies.angularVelocity[i];
    v += dt * (params.gravity + bodies.inverseMass[i] * bodies.force[i]);

    w += dt * (bodies.inverseInertiaWorld[i] * bodies.torque[i]);
    if (params.gyroscopic) w = solveGyroscopic(bodies.orientation[i], bodies.inertiaLocal[i], w, dt);

    bodies.linearVelocity[i] = v * params.linearRetention;
    bodies.angularVelocity[i] = w * params.angularRetention;
    return bounded;
}

std::uint32_t BodyIntegrator::boundVelocities(BodyStorage& bodies, float dt) const {
    std::uint32_t bounded = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies.isAwakeDynamic(i) &&
            boundVelocity(bodies.linearVelocity[i], bodies.angularVelocity[i], dt))
            ++bounded;
    return bounded;
}

std::uint32_t BodyIntegrator::integratePositions(BodyStorage& bodies, Integrator method, float dt, TaskPool& pool) const {
    // Every body's update reads and writes only its own entries.
    return static_cast<std::uint32_t>(pool.parallelSum(bodies.size(), kBodyGrain, [&](std::size_t begin, std::size_t end) {
        std::uint32_t bounded = 0;
        for (std::size_t i = begin; i < end; ++i) {
            if (integratePosition(bodies, i, method, dt)) ++bounded;
        }
        return bounded;
    }));
}

bool BodyIntegrator::integratePosition(BodyStorage& bodies, std::size_t i, Integrator method, float dt) const {
    if (bodies.motion[i] == MotionType::Static || !bodies.awake[i]) return false;

    const bool bounded =
        bodies.motion[i] == MotionType::Dynamic && boundVelocity(bodies.linearVelocity[i], bodies.angularVelocity[i], dt);
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
    return bounded;
}

}  // namespace simcore
