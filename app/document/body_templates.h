#pragma once
// Bodies the editor creates (Add, Throw, changing a body's shape type): one template per shape
// type, about one metre across, so a new body of any type is comparable to the others.

#include "simcore/io/scene.h"

#include <QString>

namespace interplay {

// The default shape of a type. The convex hull is a fixed, irregular ten-point rock.
simcore::Shape templateShape(simcore::ShapeType type);

// A dynamic body of that shape at `position`, named `name`, with a palette colour.
simcore::SceneBody templateBody(simcore::ShapeType type, const QString& name, const simcore::Vec3& position);

// "Box", "Sphere", "Capsule", "Cylinder", "Hull": the base of new bodies' names.
QString shapeDisplayName(simcore::ShapeType type);

}  // namespace interplay
