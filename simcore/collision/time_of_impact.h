#pragma once
// Time of impact of two convex shapes moving over one step, by conservative advancement (Mirtich,
// 1996): at the current time the GJK distance d and normal n bound how soon the shapes can touch,
// since no point of either moves faster along n than its linear speed plus spin times reach; so
// time can safely advance by d / (that bound). Repeating converges on the first contact from
// outside and never steps past it, however thin the shapes or fast the motion. A compound is
// swept child by child (each child pair in turn; the earliest hit counts). Against a surface (mesh
// or height field), taken at rest at its sweep's start, each sub-shape is advanced towards each
// triangle its swept box meets, with the triangle narrow phase's separation as the distance.

#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

namespace simcore {

// A body's motion over a step: its centre of mass and orientation at the start and the end.
// Between them the centre moves on a line and the orientation turns at a constant rate (slerp).
struct Sweep {
    Vec3 localCenter{0.0f};  // body origin -> centre of mass, body frame
    Vec3 center0{0.0f}, center1{0.0f};
    Quat rotation0{1.0f, 0.0f, 0.0f, 0.0f}, rotation1{1.0f, 0.0f, 0.0f, 0.0f};

    Transform at(float fraction) const;  // the shape's transform (body origin and orientation)
    float rotationAngle() const;         // rad turned over the sweep
};

struct TimeOfImpact {
    enum class Outcome {
        Separated,        // no contact within the sweep
        Hit,              // the shapes come within `target` of each other at `fraction`
        InitiallyTouching // already within `target` at the start: contacts handle the pair
    } outcome = Outcome::Separated;
    float fraction = 1.0f;  // of the sweep, in [0, 1]
    Vec3 normal{0.0f};      // on a hit: unit, from A to B at the time of impact
};

// `target` is the separation to stop at (> 0, so the shapes are still apart and the next step's
// contacts take over); the result is within `tolerance` of it.
TimeOfImpact timeOfImpact(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, float target,
                          float tolerance);

}  // namespace simcore
