#include "app/document/body_templates.h"

#include "simcore/shapes/convex_hull.h"

#include <QCoreApplication>

#include <stdexcept>
#include <string>

namespace interplay {
namespace {

const std::shared_ptr<const simcore::ConvexHull>& rockHull() {
    // Built once and shared by every hull body the editor makes (hulls are immutable).
    static const std::shared_ptr<const simcore::ConvexHull> hull = [] {
        const std::vector<simcore::Vec3> points{
            {-0.45f, -0.40f, -0.35f}, {0.50f, -0.40f, -0.30f}, {0.05f, -0.40f, 0.50f}, {-0.40f, 0.00f, 0.45f},
            {0.45f, 0.05f, 0.40f},    {0.00f, 0.50f, 0.00f},   {-0.35f, 0.30f, -0.30f}, {0.30f, 0.35f, -0.25f},
            {0.55f, 0.00f, -0.05f},   {-0.55f, 0.05f, 0.05f},
        };
        simcore::ConvexHull::BuildResult built = simcore::ConvexHull::build(points);
        if (!built.hull) throw std::logic_error("template hull: " + built.error);
        return built.hull;
    }();
    return hull;
}

// Colours (linear RGB) per shape type, so new bodies are told apart at a glance.
simcore::Vec3 templateColor(simcore::ShapeType type) {
    switch (type) {
    case simcore::ShapeType::Box: return {0.80f, 0.25f, 0.10f};
    case simcore::ShapeType::Sphere: return {0.10f, 0.45f, 0.70f};
    case simcore::ShapeType::Capsule: return {0.90f, 0.55f, 0.05f};
    case simcore::ShapeType::Cylinder: return {0.35f, 0.20f, 0.70f};
    case simcore::ShapeType::ConvexHull: return {0.25f, 0.55f, 0.25f};
    case simcore::ShapeType::Compound:
    case simcore::ShapeType::Mesh:
    case simcore::ShapeType::HeightField: break;  // no template (see templateShape)
    }
    return {0.5f, 0.5f, 0.5f};
}

}  // namespace

simcore::Shape templateShape(simcore::ShapeType type) {
    switch (type) {
    case simcore::ShapeType::Box: return simcore::Shape::box(simcore::Vec3(0.5f));
    case simcore::ShapeType::Sphere: return simcore::Shape::sphere(0.5f);
    case simcore::ShapeType::Capsule: return simcore::Shape::capsule(0.3f, 0.4f);
    case simcore::ShapeType::Cylinder: return simcore::Shape::cylinder(0.45f, 0.4f);
    case simcore::ShapeType::ConvexHull: return simcore::Shape::convexHull(rockHull());
    case simcore::ShapeType::Compound:
    case simcore::ShapeType::Mesh:
    case simcore::ShapeType::HeightField: break;
    }
    throw std::invalid_argument("no template shape for a " + std::string(simcore::shapeTypeName(type)) +
                                " (the Add menus offer the convex types)");
}

simcore::SceneBody templateBody(simcore::ShapeType type, const QString& name, const simcore::Vec3& position) {
    simcore::SceneBody body;
    body.body.name = name.toStdString();
    body.body.shape = templateShape(type);
    body.body.position = position;
    body.color = templateColor(type);
    return body;
}

simcore::SceneJoint templateJoint(simcore::JointType type, const QString& name, const std::vector<simcore::SceneBody>& bodies,
                                  std::size_t bodyA, std::optional<std::size_t> bodyB) {
    const simcore::Vec3 up(0.0f, 1.0f, 0.0f);
    simcore::SceneJoint joint;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    simcore::JointCreationSettings& s = joint.joint;
    s.name = name.toStdString();
    s.type = type;
    const simcore::Vec3 a = bodies.at(bodyA).body.position;
    if (!bodyB) {
        s.anchor = a;
        s.anchorB = a + up;
        s.axis = type == simcore::JointType::Hinge ? simcore::Vec3(0.0f, 0.0f, 1.0f) : up;
        return joint;
    }
    const simcore::Vec3 b = bodies.at(*bodyB).body.position;
    const simcore::Vec3 line = b - a;
    const float length = glm::length(line);
    const simcore::Vec3 along = length > 1e-6f ? line / length : up;
    const simcore::Vec3 across = glm::cross(along, up);
    s.anchor = type == simcore::JointType::Distance ? a : 0.5f * (a + b);
    s.anchorB = b;
    if (type == simcore::JointType::Hinge) {
        s.axis = glm::length(across) > 1e-3f ? glm::normalize(across) : simcore::Vec3(0.0f, 0.0f, 1.0f);
    } else {
        s.axis = along;
    }
    return joint;
}

QString jointTypeDisplayName(simcore::JointType type) {
    switch (type) {
    case simcore::JointType::Ball: return QCoreApplication::translate("interplay::joints", "Ball");
    case simcore::JointType::Hinge: return QCoreApplication::translate("interplay::joints", "Hinge");
    case simcore::JointType::Slider: return QCoreApplication::translate("interplay::joints", "Slider");
    case simcore::JointType::Fixed: return QCoreApplication::translate("interplay::joints", "Fixed");
    case simcore::JointType::Distance: return QCoreApplication::translate("interplay::joints", "Distance");
    }
    return {};
}

QString shapeDisplayName(simcore::ShapeType type) {
    switch (type) {
    case simcore::ShapeType::Box: return QCoreApplication::translate("interplay::shapes", "Box");
    case simcore::ShapeType::Sphere: return QCoreApplication::translate("interplay::shapes", "Sphere");
    case simcore::ShapeType::Capsule: return QCoreApplication::translate("interplay::shapes", "Capsule");
    case simcore::ShapeType::Cylinder: return QCoreApplication::translate("interplay::shapes", "Cylinder");
    case simcore::ShapeType::ConvexHull: return QCoreApplication::translate("interplay::shapes", "Hull");
    case simcore::ShapeType::Compound: return QCoreApplication::translate("interplay::shapes", "Compound");
    case simcore::ShapeType::Mesh: return QCoreApplication::translate("interplay::shapes", "Mesh");
    case simcore::ShapeType::HeightField: return QCoreApplication::translate("interplay::shapes", "Height field");
    }
    return {};
}

}  // namespace interplay
