#pragma once
// Bodies the editor creates (Add, Throw, changing a body's shape type): one template per shape
// type, about one metre across, so a new body of any type is comparable to the others. And the
// joints Add Joint creates, placed for the bodies they join.

#include "simcore/io/scene.h"

#include <QString>

#include <optional>

namespace interplay {

// The default shape of a convex type (isConvex: what the Add menus offer); the convex hull is a
// fixed, irregular ten-point rock. Throws std::invalid_argument for the other types.
simcore::Shape templateShape(simcore::ShapeType type);

// A dynamic body of that shape at `position`, named `name`, with a palette colour.
simcore::SceneBody templateBody(simcore::ShapeType type, const QString& name, const simcore::Vec3& position);

// "Box", "Sphere", "Capsule", "Cylinder", "Hull": the base of new bodies' names.
QString shapeDisplayName(simcore::ShapeType type);

// A joint of that type holding `bodies[bodyA]` to `bodies[bodyB]`, or to the world without bodyB.
// Between two bodies the anchor is midway between their origins (a distance joint joins the two
// origins); the hinge axis is horizontal and square to the line between them (they swing in the
// vertical plane through both), the slider axis along that line. To the world the anchor is the
// body's origin (a distance joint hangs it one metre below a world point), the hinge axis is z and
// the slider axis vertical.
simcore::SceneJoint templateJoint(simcore::JointType type, const QString& name, const std::vector<simcore::SceneBody>& bodies,
                                  std::size_t bodyA, std::optional<std::size_t> bodyB);

// "Ball", "Hinge", "Slider", "Fixed", "Distance".
QString jointTypeDisplayName(simcore::JointType type);

}  // namespace interplay
