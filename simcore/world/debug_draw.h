#pragma once
// Debug drawing: World::draw walks the world and hands what a renderer or a tool needs to a
// DebugDraw, one callback per item, so nothing outside the engine reads its storage (as Box2D
// v3's b2DebugDraw). The options say which kinds of item are emitted; a callback left as is
// ignores its items. All positions are in the world frame (m); the references passed to a
// callback are valid only during the call.

#include "simcore/dynamics/body.h"
#include "simcore/dynamics/joint.h"
#include "simcore/math/aabb.h"
#include "simcore/shapes/shape.h"

#include <optional>

namespace simcore {

struct DebugDrawOptions {
    bool bodies = true;        // drawBody: shape, pose, state, centre of mass
    bool tightBounds = false;  // drawBounds: the shape's world bounds in its pose now
    bool fatBounds = false;    // drawBounds: the broad phase's enlarged bounds
    bool contacts = false;     // drawContactPoint: every point of every persistent contact
    bool joints = false;       // drawJoint
};

struct DebugBody {
    BodyId id;
    const Shape& shape;
    Transform transform;  // the body's origin and orientation
    Vec3 centerOfMass;
    MotionType motion;
    bool awake;
};

enum class DebugBoundsKind { Tight, Fat };

struct DebugContactPoint {
    BodyId bodyA, bodyB;
    Vec3 point;              // midway between the two surfaces
    Vec3 normal;             // unit, from A towards B
    float separation;        // negative when penetrating (m)
    float normalImpulse;     // accumulated by the solver in the last step (N s)
    bool speculative;        // the surfaces are still apart: the point only keeps them from closing
};

struct DebugJoint {
    JointId id;
    JointType type;
    BodyId bodyA, bodyB;              // bodyB invalid: the world
    Vec3 centerA;                     // body A's centre of mass
    std::optional<Vec3> centerB;      // body B's centre of mass; none for a joint to the world
    Vec3 anchorA, anchorB;            // the joint's point on each body now (apart for a distance
                                      // joint, a sliding slider or a strained joint)
    Vec3 axis;                        // unit, on A (meaningful for hinge and slider)
    // Hinge angle (rad), slider translation (m) or distance length (m): the limits in effect (a
    // distance joint's min and max length) and the value now; none and 0 for ball and fixed joints.
    std::optional<JointLimits> limits;
    float position;
};

class DebugDraw {
public:
    virtual ~DebugDraw() = default;

    virtual void drawBody(const DebugBody&) {}
    virtual void drawBounds(BodyId, const Aabb&, DebugBoundsKind) {}
    virtual void drawContactPoint(const DebugContactPoint&) {}
    virtual void drawJoint(const DebugJoint&) {}
};

}  // namespace simcore
