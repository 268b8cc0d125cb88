#pragma once
// What a body is made from (creation settings) and how it is referred to (a generational handle).

#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

#include <cstdint>
#include <optional>
#include <string>

namespace simcore {

enum class MotionType : std::uint8_t {
    Static,     // never moves, infinite mass
    Kinematic,  // moved by its velocity only, pushes dynamic bodies, infinite mass
    Dynamic,    // moved by forces, contacts and joints
};

// Stable reference to a body. The generation makes a handle to a destroyed body detectably stale
// even after its slot is reused, so the editor and undo history can hold ids safely.
struct BodyId {
    static constexpr std::uint32_t kInvalidIndex = 0xFFFFFFFFu;
    std::uint32_t index = kInvalidIndex;
    std::uint32_t generation = 0;

    bool isValid() const { return index != kInvalidIndex; }
    friend bool operator==(const BodyId&, const BodyId&) = default;
};

struct BodyCreationSettings {
    std::string name;
    Shape shape;
    MotionType motion = MotionType::Dynamic;

    Vec3 position{0.0f};                      // body origin, world frame (m)
    Quat orientation{1.0f, 0.0f, 0.0f, 0.0f}; // unit quaternion
    Vec3 linearVelocity{0.0f};                // of the centre of mass, world frame (m/s)
    Vec3 angularVelocity{0.0f};               // world frame (rad/s)

    std::optional<float> mass;  // kg; when unset, mass follows from density and shape volume
    float density = 1000.0f;    // kg/m^3, used only when mass is unset

    float friction = 0.5f;      // Coulomb coefficient, >= 0
    float restitution = 0.0f;   // in [0, 1]
    // Coefficient of rolling resistance C, dimensionless, >= 0: a contact resists the bodies'
    // relative turning with a torque of up to C times the rolling radius (rollingRadius in
    // shape.h) times the normal force. 0 (the default) leaves rolling free.
    float rollingResistance = 0.0f;
    bool ccd = false;           // always sweep this body (continuous collision)
};

}  // namespace simcore
