#pragma once
// Small pieces of constraint math shared by the contact and joint solvers.

#include "simcore/math/math.h"

#include <algorithm>
#include <cmath>

namespace simcore {

// A constraint solved as an implicit mass-spring-damper (Catto, "Solver2D", 2024; Box2D v3's soft
// step). One velocity update of a row is
//   lambda = -effectiveMass * massScale * (Cdot + biasRate * C) - impulseScale * accumulatedImpulse,
// the implicit-Euler answer for a spring of the given frequency and damping ratio acting on the
// row's effective mass: the stiffness scales with the mass the row moves.
struct SoftConstraint {
    float biasRate = 0.0f;      // 1/s: position error -> velocity bias
    float massScale = 1.0f;     // fraction of the rigid impulse applied
    float impulseScale = 0.0f;  // fraction of the accumulated impulse relaxed each update

    // hertz > 0, dampingRatio >= 0, substepDt > 0.
    static SoftConstraint make(float hertz, float dampingRatio, float substepDt) {
        const float h = substepDt;
        const float omega = 2.0f * kPi * hertz;
        const float a1 = 2.0f * dampingRatio + h * omega;
        const float a2 = h * omega * a1;
        const float a3 = 1.0f / (1.0f + a2);
        return {omega / a1, a2 * a3, a3};
    }

    // Stiffness of position correction (contacts, joint rows) is capped at a quarter of the
    // substep rate, beyond which the substep cannot resolve the spring. Physical springs are not.
    static float cappedHertz(float hertz, float substepDt) { return std::min(hertz, 0.25f / substepDt); }
};

// Orthonormal t1, t2 perpendicular to the unit vector n, without branches on near-parallel axes
// (Duff et al., "Building an Orthonormal Basis, Revisited", 2017). Continuous in n, so impulses
// kept along the tangents stay meaningful from step to step.
inline void orthonormalBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    t1 = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

// Column-major cross-product matrix: skew(v) * x == cross(v, x).
inline Mat3 skew(const Vec3& v) { return Mat3(0.0f, v.z, -v.y, -v.z, 0.0f, v.x, v.y, -v.x, 0.0f); }

}  // namespace simcore
