#pragma once
// What a joint is made from (creation settings) and how it is referred to (a generational handle).
// Anchors and axes are given in world space at creation; the joint keeps them in each body's frame,
// so the bodies' poses at creation are the joint's rest pose (zero hinge angle, zero slide).

#include "simcore/dynamics/body.h"

#include <optional>
#include <string>
#include <string_view>

namespace simcore {

enum class JointType : std::uint8_t {
    Ball,      // anchors coincide; rotation free
    Hinge,     // anchors coincide; rotation only about the axis (limits, motor)
    Slider,    // no rotation; translation only along the axis (limits, motor)
    Fixed,     // anchors coincide; no relative rotation
    Distance,  // anchor distance held at the rest length, or within [minLength, maxLength] (spring)
};
std::string_view jointTypeName(JointType type);  // "ball", "hinge", ... as in the scene file

// Stable reference to a joint; stale after the joint (or one of its bodies) is destroyed.
struct JointId {
    static constexpr std::uint32_t kInvalidIndex = 0xFFFFFFFFu;
    std::uint32_t index = kInvalidIndex;
    std::uint32_t generation = 0;

    bool isValid() const { return index != kInvalidIndex; }
    friend bool operator==(const JointId&, const JointId&) = default;
};

// Hinge angle (rad) or slider translation (m) of bodyA relative to bodyB (for a joint to the world:
// of the body), from the rest pose, right-handed about / along the axis; lower <= upper.
struct JointLimits {
    float lower = 0.0f;
    float upper = 0.0f;
    friend bool operator==(const JointLimits&, const JointLimits&) = default;
};

// Drives the hinge's angular speed (rad/s) or the slider's speed (m/s) of bodyA relative to bodyB
// about / along the axis, with at most maxForce (N m for a hinge, N for a slider).
struct JointMotor {
    float speed = 0.0f;
    float maxForce = 0.0f;
    friend bool operator==(const JointMotor&, const JointMotor&) = default;
};

// A distance joint's spring towards the rest length: frequency (Hz, > 0) and damping ratio (>= 0)
// for the mass the joint moves.
struct JointSpring {
    float hertz = 1.0f;
    float dampingRatio = 0.0f;
    friend bool operator==(const JointSpring&, const JointSpring&) = default;
};

struct JointCreationSettings {
    std::string name;
    JointType type = JointType::Ball;
    BodyId bodyA;           // must be a live body
    BodyId bodyB;           // a live body other than bodyA, or invalid for the world
    Vec3 anchor{0.0f};      // world frame (m): the joint point (a distance joint's point on A)
    Vec3 anchorB{0.0f};     // world frame (m): a distance joint's point on B; unused by other types
    Vec3 axis{0.0f, 1.0f, 0.0f};  // world frame, hinge and slider; normalised at creation

    std::optional<JointLimits> limits;  // hinge and slider
    std::optional<JointMotor> motor;    // hinge and slider
    std::optional<JointSpring> spring;  // distance
    // Distance limits (m). Unset: the rest length |anchorB - anchor| without a spring (a rigid
    // rod), unbounded (0 and infinity) with one.
    std::optional<float> minLength;
    std::optional<float> maxLength;

    bool collideConnected = false;  // whether the two bodies still collide with each other
};

// A distance joint's lengths (m): the rest length |anchorB - anchor| and the limits in effect.
struct DistanceLengths {
    float rest = 0.0f;
    float min = 0.0f;
    float max = 0.0f;
};
DistanceLengths distanceLengths(const JointCreationSettings& settings);
// The same from the rest length (m) and the joint's options, for a joint that already exists.
DistanceLengths distanceLengths(float restLength, bool hasSpring, std::optional<float> minLength,
                                std::optional<float> maxLength);

// How far a joint is from satisfied: the worst of its position rows (m) and angle rows (rad),
// limits included.
struct JointError {
    float position = 0.0f;
    float angle = 0.0f;
};

}  // namespace simcore
