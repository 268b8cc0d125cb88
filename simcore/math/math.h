#pragma once
// Math vocabulary of simcore: GLM single precision, with the few helpers every stage needs.
// Single precision is deliberate: it halves memory traffic in the step, and every quantity the
// engine integrates is renormalised or bounded, so float's 7 digits are not the limiting error.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>

namespace simcore {

using Vec3 = glm::vec3;
using Quat = glm::quat;  // GLM stores (x, y, z, w) but constructs as Quat(w, x, y, z).
using Mat3 = glm::mat3;

constexpr float kPi = 3.14159265358979323846f;

inline bool isFinite(float v) { return std::isfinite(v); }
inline bool isFinite(const Vec3& v) { return isFinite(v.x) && isFinite(v.y) && isFinite(v.z); }
inline bool isFinite(const Quat& q) { return isFinite(q.w) && isFinite(q.x) && isFinite(q.y) && isFinite(q.z); }

inline float lengthSquared(const Vec3& v) { return glm::dot(v, v); }

// Component-wise diagonal matrix.
inline Mat3 diagonal(const Vec3& d) {
    Mat3 m(0.0f);
    m[0][0] = d.x;
    m[1][1] = d.y;
    m[2][2] = d.z;
    return m;
}

// Whether m is zero off its diagonal.
inline bool isDiagonal(const Mat3& m) {
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
            if (row != column && m[column][row] != 0.0f) return false;
    return true;
}

// Whether m is s times the identity for some s (zero included): a tensor the same in every frame
// (R m R^T = m for any rotation R), so it need not be rotated at all.
inline bool isScaledIdentity(const Mat3& m) { return isDiagonal(m) && m[0][0] == m[1][1] && m[1][1] == m[2][2]; }

// Rigid transform: rotate, then translate. Maps local (body) coordinates to world coordinates.
struct Transform {
    Vec3 position{0.0f};
    Quat rotation{1.0f, 0.0f, 0.0f, 0.0f};

    Vec3 apply(const Vec3& local) const { return position + rotation * local; }
    Vec3 applyInverse(const Vec3& world) const { return glm::conjugate(rotation) * (world - position); }
    Vec3 rotate(const Vec3& local) const { return rotation * local; }
    Vec3 rotateInverse(const Vec3& world) const { return glm::conjugate(rotation) * world; }
};

}  // namespace simcore
