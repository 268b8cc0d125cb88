#pragma once
// Joints in one contiguous array, indexed densely; stable JointIds map to dense indices through a
// slot table (as bodies do), so removing a joint never invalidates other handles. Each joint keeps
// its frames in its bodies' axes and its accumulated impulses, carried from step to step for warm
// starting.

#include "simcore/dynamics/body_storage.h"
#include "simcore/dynamics/joint.h"
#include "simcore/dynamics/slot_map.h"

#include <limits>
#include <string>
#include <vector>

namespace simcore {

// Impulses accumulated by a joint's rows (N s, or N m s for angular rows), world frame.
struct JointImpulses {
    Vec3 point{0.0f};    // anchors coincide (ball, hinge, fixed); slider: perpendicular to the axis
    Vec3 angular{0.0f};  // hinge: axis alignment; fixed and slider: relative rotation
    float axial = 0.0f;  // distance: the rigid row or the spring
    float motor = 0.0f;
    float lower = 0.0f;  // limits (hinge angle, slider translation, distance length), >= 0
    float upper = 0.0f;
};

struct Joint {
    JointType type = JointType::Ball;
    BodyId bodyA, bodyB;               // bodyB invalid: the world
    Vec3 localAnchorA{0.0f};           // from A's centre of mass, A's axes (m)
    Vec3 localAnchorB{0.0f};           // from B's centre of mass, B's axes; the world's: world frame
    Vec3 localAxisA{0.0f, 1.0f, 0.0f}; // unit, A's axes (hinge, slider)
    Vec3 localAxisB{0.0f, 1.0f, 0.0f}; // unit, B's axes (hinge)
    Quat restRotation{1.0f, 0.0f, 0.0f, 0.0f};  // B's orientation in A's axes at creation
    std::optional<JointLimits> limits;
    std::optional<JointMotor> motor;
    std::optional<JointSpring> spring;
    float restLength = 0.0f;  // distance: |anchorB - anchor| at creation (m)
    float minLength = 0.0f;   // distance: effective limits (m); equal for a rigid rod
    float maxLength = std::numeric_limits<float>::infinity();
    // distance: the limits as given (unset: from the rest length and the spring), so a change of
    // spring re-derives the effective ones as creation would.
    std::optional<float> minLengthSetting;
    std::optional<float> maxLengthSetting;
    bool collideConnected = false;
    JointImpulses impulses;
};

// Where a body of a joint is: its centre of mass and orientation; the world is at the origin.
struct JointBodyPose {
    Vec3 centerOfMass{0.0f};
    Quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
};

// The joint's geometry in a pose of its two bodies: what its rows constrain.
struct JointGeometry {
    Vec3 armA, armB;            // centres of mass -> anchor points, world frame (m)
    Vec3 separation;            // anchor B - anchor A (m)
    Quat relativeRotation;      // B's rotation away from the rest pose, in A's axes
    Vec3 axisA;                 // hinge and slider axis on A, world frame (unit)
    Vec3 axisB;                 // hinge axis on B, world frame (unit)
    Quat orientationA;          // A's axes, in which relativeRotation is given

    // Hinge angle of A relative to B about the axis (rad, in [-pi, pi]), from the rest pose.
    float hingeAngle(const Joint& joint) const;
    // Slider translation of A relative to B along the axis (m), from the rest pose.
    float slide() const { return -glm::dot(separation, axisA); }
    // Rotation vector (axis * angle, world frame) of the relative rotation.
    Vec3 rotationError() const;
};
JointGeometry jointGeometry(const Joint& joint, const JointBodyPose& a, const JointBodyPose& b);

class JointStorage {
public:
    std::vector<Joint> joints;        // dense
    std::vector<std::string> names;   // dense, beside the solver's data

    std::size_t size() const { return joints.size(); }
    bool empty() const { return joints.empty(); }

    // Appends a joint; the settings must already be validated (World::createJoint does it) and
    // the bodies live in `bodies`.
    JointId add(const JointCreationSettings& settings, const BodyStorage& bodies);
    // Holds `joint` at these world points and axis (as creation reads them from its settings) at
    // the bodies' current poses; its rest rotation is left as it was. A distance joint's rest
    // length becomes the anchors' distance.
    void place(Joint& joint, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB, const BodyStorage& bodies) const;
    void remove(JointId id);

    int denseIndex(JointId id) const { return slots_.denseIndex(id); }  // -1 for a stale or invalid id
    JointId idAt(std::size_t denseIndex) const { return slots_.idAt(denseIndex); }

    JointBodyPose poseOf(BodyId body, const BodyStorage& bodies) const;
    // Worst position (m) and angle (rad) error of a joint, limits included.
    JointError error(std::size_t denseIndex, const BodyStorage& bodies) const;

private:
    SlotMap<JointId> slots_;
};

}  // namespace simcore
