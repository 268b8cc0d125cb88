#pragma once
// The checks World applies to what it is given, shared by creation and the live setters so that
// both refuse a bad value with the same message. Each throws std::invalid_argument naming the field.

#include "simcore/dynamics/body.h"
#include "simcore/dynamics/joint.h"
#include "simcore/shapes/shape.h"
#include "simcore/world_settings.h"

#include <optional>
#include <string>

namespace simcore::validation {

void require(bool condition, const std::string& what);  // throws `what` unless `condition`
bool isPositiveFinite(float v);

void validateShape(const Shape& shape);
void validateMass(float mass);
void validateDensity(float density);
void validateFriction(float friction);
void validateRestitution(float restitution);
void validateRollingResistance(float coefficient);
void validateBody(const BodyCreationSettings& s);

// A body's mass properties: from its mass or density when dynamic; static and kinematic bodies
// have infinite mass, and only the centre of mass matters (as the integrated point of a kinematic
// body). Throws when the shape gives no usable mass.
// Why a body of this shape cannot be dynamic, or empty when it can: surfaces (meshes, height
// fields) have no volume, so no mass; the message suggests what to use instead.
std::string dynamicShapeProblem(ShapeType type);
MassProperties bodyMassProperties(const Shape& shape, MotionType motion, std::optional<float> mass, float density);

void validateSettings(const WorldSettings& s);

// The options a joint type takes, each checked on its own so the live setters check the same.
void validateJointLimits(JointType type, const std::optional<JointLimits>& limits);
void validateJointMotor(JointType type, const std::optional<JointMotor>& motor);
void validateJointSpring(JointType type, const std::optional<JointSpring>& spring);
// A distance joint's limits given its rest length (m) and whether it has a spring.
void validateJointLengths(JointType type, float restLength, bool hasSpring, std::optional<float> minLength,
                          std::optional<float> maxLength);
// Where a joint holds its bodies: a finite anchor; a distance joint's anchorB at least 0.1 mm from
// it; a hinge's or slider's axis finite and not zero.
void validateJointFrame(JointType type, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB);
// What can be checked without the bodies: numbers, and which options the type takes.
void validateJoint(const JointCreationSettings& s);

}  // namespace simcore::validation
