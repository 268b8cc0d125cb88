#include "simcore/world/validation.h"

#include "simcore/settings_schema.h"
#include "simcore/shapes/compound_shape.h"

#include <cmath>
#include <stdexcept>

namespace simcore::validation {

void require(bool condition, const std::string& what) {
    if (!condition) throw std::invalid_argument(what);
}

bool isPositiveFinite(float v) { return isFinite(v) && v > 0.0f; }

namespace {

// `path` names the shape in messages: "shape", or "shape.children[1].shape" inside a compound.
void validateShapeAt(const Shape& shape, const std::string& path) {
    switch (shape.type) {
        case ShapeType::Sphere:
            require(isPositiveFinite(shape.radius), path + ".radius must be a positive finite number");
            break;
        case ShapeType::Box:
            require(isPositiveFinite(shape.halfExtents.x) && isPositiveFinite(shape.halfExtents.y) &&
                        isPositiveFinite(shape.halfExtents.z),
                    path + ".halfExtents must be positive finite numbers");
            break;
        case ShapeType::Capsule:
        case ShapeType::Cylinder:
            require(isPositiveFinite(shape.radius), path + ".radius must be a positive finite number");
            require(isPositiveFinite(shape.halfHeight), path + ".halfHeight must be a positive finite number");
            break;
        case ShapeType::ConvexHull:
            require(shape.hull != nullptr, path + ".hull is missing");
            break;
        case ShapeType::Compound: {
            require(shape.compound != nullptr, path + ".children are missing");
            const std::size_t count = shape.compound->size();
            require(count >= 1 && count <= limits::kMaxCompoundChildren,
                    path + ".children must number 1 to " + std::to_string(limits::kMaxCompoundChildren) + ", got " +
                        std::to_string(count));
            for (std::size_t i = 0; i < count; ++i) {
                const CompoundChild& child = shape.compound->children()[i];
                const std::string childPath = path + ".children[" + std::to_string(i) + "]";
                require(isConvex(child.shape.type), childPath + ".shape must be convex (compounds do not nest)");
                validateShapeAt(child.shape, childPath + ".shape");
                require(isFinite(child.pose.position), childPath + ".position must be finite");
                require(isFinite(child.pose.rotation) &&
                            std::abs(glm::length(child.pose.rotation) - 1.0f) <= 1e-3f,
                        childPath + ".orientation must be a unit quaternion");
            }
            break;
        }
        case ShapeType::Mesh:
            require(shape.mesh != nullptr, path + " has no triangle mesh");
            break;
        case ShapeType::HeightField:
            require(shape.heightField != nullptr, path + " has no height field");
            break;
    }
}

}  // namespace

void validateShape(const Shape& shape) { validateShapeAt(shape, "shape"); }

void validateMass(float mass) { require(isPositiveFinite(mass), "mass must be a positive finite number"); }
void validateDensity(float density) { require(isPositiveFinite(density), "density must be a positive finite number"); }
void validateFriction(float friction) {
    require(isFinite(friction) && friction >= 0.0f, "friction must be finite and >= 0");
}
void validateRestitution(float restitution) {
    require(isFinite(restitution) && restitution >= 0.0f && restitution <= 1.0f, "restitution must be in [0, 1]");
}
void validateRollingResistance(float coefficient) {
    require(isFinite(coefficient) && coefficient >= 0.0f, "rollingResistance must be finite and >= 0");
}

void validateBody(const BodyCreationSettings& s) {
    validateShape(s.shape);
    require(isFinite(s.position), "position must be finite");
    require(isFinite(s.orientation) && glm::length(s.orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    require(isFinite(s.linearVelocity), "linearVelocity must be finite");
    require(isFinite(s.angularVelocity), "angularVelocity must be finite");
    if (s.mass) validateMass(*s.mass);
    validateDensity(s.density);
    validateFriction(s.friction);
    validateRestitution(s.restitution);
    validateRollingResistance(s.rollingResistance);
}

std::string dynamicShapeProblem(ShapeType type) {
    if (!isSurface(type)) return {};
    return "a " + std::string(shapeTypeName(type)) +
           " body must be static or kinematic: for a moving body use a convexHull or a compound of convex shapes";
}

MassProperties bodyMassProperties(const Shape& shape, MotionType motion, std::optional<float> mass, float density) {
    if (motion == MotionType::Dynamic) {
        const std::string problem = dynamicShapeProblem(shape.type);
        require(problem.empty(), problem);
    }
    if (motion != MotionType::Dynamic) {
        MassProperties centreOnly;
        centreOnly.centerOfMass = massProperties(shape, 1.0f).centerOfMass;
        return centreOnly;
    }
    const MassProperties result = mass ? massPropertiesForMass(shape, *mass) : massProperties(shape, density);
    require(isPositiveFinite(result.mass), "the shape's mass is not a positive finite number");
    // A huge mass on a large shape overflows the moments to infinity, whose inverse is NaN.
    for (int c = 0; c < 3; ++c)
        require(isFinite(result.inertia[c]), "mass and shape give a non-finite inertia (a smaller mass or density)");
    return result;
}

void validateSettings(const WorldSettings& s) {
    require(isFinite(s.gravity), "gravity must be finite");
    require(isPositiveFinite(s.timeStep), "timeStep must be a positive finite number");
    require(s.substeps >= 1, "substeps must be at least 1");
    require(s.threads >= 0, "threads must be >= 0 (0: one per core)");
    require(s.solver.velocityIterations >= 0, "solver.velocityIterations must be >= 0");
    require(s.solver.positionIterations >= 0, "solver.positionIterations must be >= 0");
    require(isFinite(s.damping.linear) && s.damping.linear >= 0.0f, "damping.linear must be finite and >= 0");
    require(isFinite(s.damping.angular) && s.damping.angular >= 0.0f, "damping.angular must be finite and >= 0");
    require(isFinite(s.sleep.linearVelocity) && s.sleep.linearVelocity >= 0.0f,
            "sleep.linearVelocity must be finite and >= 0");
    require(isFinite(s.sleep.angularVelocity) && s.sleep.angularVelocity >= 0.0f,
            "sleep.angularVelocity must be finite and >= 0");
    require(isFinite(s.sleep.timeToSleep) && s.sleep.timeToSleep >= 0.0f,
            "sleep.timeToSleep must be finite and >= 0");
    require(isPositiveFinite(s.joint.hertz), "joint.hertz must be a positive finite number");
    require(isFinite(s.joint.dampingRatio) && s.joint.dampingRatio >= 0.0f, "joint.dampingRatio must be finite and >= 0");
}

void validateJointLimits(JointType type, const std::optional<JointLimits>& limits) {
    if (!limits) return;
    require(type == JointType::Hinge || type == JointType::Slider, "limits apply to hinge and slider joints only");
    require(isFinite(limits->lower) && isFinite(limits->upper), "limits must be finite");
    require(limits->lower <= limits->upper, "limits.lower must not exceed limits.upper");
    if (type == JointType::Hinge)
        require(limits->lower >= -kPi && limits->upper <= kPi, "hinge limits must lie within [-pi, pi] rad");
}

void validateJointMotor(JointType type, const std::optional<JointMotor>& motor) {
    if (!motor) return;
    require(type == JointType::Hinge || type == JointType::Slider, "motor applies to hinge and slider joints only");
    require(isFinite(motor->speed), "motor.speed must be finite");
    require(isFinite(motor->maxForce) && motor->maxForce >= 0.0f, "motor.maxForce must be finite and >= 0");
}

void validateJointSpring(JointType type, const std::optional<JointSpring>& spring) {
    if (!spring) return;
    require(type == JointType::Distance, "spring applies to distance joints only");
    require(isPositiveFinite(spring->hertz), "spring.hertz must be a positive finite number");
    require(isFinite(spring->dampingRatio) && spring->dampingRatio >= 0.0f, "spring.dampingRatio must be finite and >= 0");
}

void validateJointLengths(JointType type, float restLength, bool hasSpring, std::optional<float> minLength,
                          std::optional<float> maxLength) {
    if (minLength || maxLength) {
        require(type == JointType::Distance, "minLength and maxLength apply to distance joints only");
        require(!minLength || (isFinite(*minLength) && *minLength >= 0.0f), "minLength must be finite and >= 0");
        require(!maxLength || (isFinite(*maxLength) && *maxLength >= 0.0f), "maxLength must be finite and >= 0");
    }
    if (type == JointType::Distance) {
        const DistanceLengths lengths = distanceLengths(restLength, hasSpring, minLength, maxLength);
        require(lengths.min <= lengths.max, "minLength must not exceed maxLength (unset, each is the rest length)");
    }
}

void validateJointFrame(JointType type, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB) {
    require(isFinite(anchor), "anchor must be finite");
    if (type == JointType::Distance) {
        require(isFinite(anchorB), "anchorB must be finite");
        require(glm::length(anchorB - anchor) >= 1e-4f, "anchorB must be at least 0.1 mm from anchor");
    }
    if (type == JointType::Hinge || type == JointType::Slider)
        require(isFinite(axis) && glm::length(axis) > 1e-6f, "axis must be a finite, non-zero vector");
}

void validateJoint(const JointCreationSettings& s) {
    validateJointFrame(s.type, s.anchor, s.axis, s.anchorB);
    validateJointLimits(s.type, s.limits);
    validateJointMotor(s.type, s.motor);
    validateJointSpring(s.type, s.spring);
    validateJointLengths(s.type, distanceLengths(s).rest, s.spring.has_value(), s.minLength, s.maxLength);
}

}  // namespace simcore::validation
