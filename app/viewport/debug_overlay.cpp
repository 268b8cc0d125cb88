#include "app/viewport/debug_overlay.h"

#include "app/viewport/debug_draw_options.h"
#include "app/viewport/look.h"

#include <QColor>
#include <QPainter>
#include <QPen>
#include <QRect>

namespace interplay {

using look::srgb;

void paintRubberBand(QPainter& painter, const QRect& box) {
    constexpr int kFillAlpha = 40;  // of 255: the bodies inside stay visible
    QColor fill = QColor::fromRgb(look::kSelectionColor);
    fill.setAlpha(kFillAlpha);
    painter.fillRect(box, fill);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor::fromRgb(look::kJointColor), 1.0));
    painter.drawRect(box);
    QPen dashes(Qt::white, 1.0, Qt::DashLine);
    painter.setPen(dashes);
    painter.drawRect(box);
}

SceneJoints::SceneJoints(const std::vector<simcore::JointId>& jointIds)
    : m_jointIds(jointIds), m_bySceneIndex(jointIds.size()) {
    for (std::size_t j = 0; j < jointIds.size(); ++j) {
        const simcore::JointId id = jointIds[j];
        if (!id.isValid()) continue;
        if (id.index >= m_sceneIndexOfSlot.size()) m_sceneIndexOfSlot.resize(id.index + 1, -1);
        m_sceneIndexOfSlot[id.index] = static_cast<int>(j);
    }
}

simcore::DebugDrawOptions SceneJoints::jointsOnly() {
    simcore::DebugDrawOptions options;
    options.bodies = false;
    options.joints = true;
    return options;
}

void SceneJoints::drawJoint(const simcore::DebugJoint& joint) {
    if (joint.id.index >= m_sceneIndexOfSlot.size()) return;
    const int sceneIndex = m_sceneIndexOfSlot[joint.id.index];
    // A joint made since, in a slot a scene joint's removed joint held, is no scene joint.
    if (sceneIndex < 0 || !(m_jointIds[static_cast<std::size_t>(sceneIndex)] == joint.id)) return;
    m_bySceneIndex[static_cast<std::size_t>(sceneIndex)] = joint;
}

DebugOverlay::DebugOverlay(const DebugDrawOptions* options, const std::vector<simcore::JointId>& jointIds)
    : m_bounds(options && options->aabbs()),
      m_contactPoints(options && options->contactPoints()),
      m_contactNormals(options && options->contactNormals()),
      m_joints(jointIds) {}

simcore::DebugDrawOptions DebugOverlay::worldOptions(const DebugDrawOptions* options) {
    simcore::DebugDrawOptions world = SceneJoints::jointsOnly();
    world.tightBounds = options && options->aabbs();
    world.contacts = options && (options->contactPoints() || options->contactNormals());
    return world;
}

void DebugOverlay::addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color) {
    m_lines.push_back({a, color});
    m_lines.push_back({b, color});
}

void DebugOverlay::addCross(const glm::vec3& point, float halfSize, const glm::vec3& color) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 d(0.0f);
        d[axis] = halfSize;
        addLine(point - d, point + d, color);
    }
}

void DebugOverlay::drawBounds(simcore::BodyId, const simcore::Aabb& box, simcore::DebugBoundsKind) {
    const glm::vec3 color = srgb(look::kAabbColor);
    const auto corner = [&box](int c) {
        return glm::vec3((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                         (c & 4) ? box.max.z : box.min.z);
    };
    // The 12 edges: corners differing in exactly one bit.
    for (int c = 0; c < 8; ++c) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(c & bit)) addLine(corner(c), corner(c | bit), color);
        }
    }
}

void DebugOverlay::drawContactPoint(const simcore::DebugContactPoint& point) {
    if (m_contactPoints) addCross(point.point, look::kContactMarkSize, srgb(look::kContactPointColor));
    if (m_contactNormals) {
        addLine(point.point, point.point + point.normal * look::kContactNormalLength, srgb(look::kContactNormalColor));
    }
}

std::vector<OverlayVertex> DebugOverlay::finish(const QList<int>& selectedJoints,
                                                const std::optional<std::pair<glm::vec3, glm::vec3>>& grabLine) {
    // Joints: from body A's centre to body B's, or to the joint's point in the world for a joint
    // to the world (a pendulum shows its rod), with a small cross at the live anchor, where a
    // click picks the joint.
    const auto& joints = m_joints.bySceneIndex();
    for (std::size_t j = 0; j < joints.size(); ++j) {
        if (!joints[j]) continue;
        const simcore::DebugJoint& joint = *joints[j];
        const bool selected = selectedJoints.contains(static_cast<int>(j));
        const glm::vec3 color = srgb(selected ? look::kSelectionColor : look::kJointColor);
        addLine(joint.centerA, joint.centerB ? *joint.centerB : joint.anchorB, color);
        const bool distance = joint.type == simcore::JointType::Distance;
        const float mark = selected ? look::kJointMarkSize : 0.5f * look::kJointMarkSize;
        addCross(joint.anchorA, mark, color);
        if (selected || distance) addCross(joint.anchorB, mark, color);
        if (!selected) continue;
        if (joint.type == simcore::JointType::Hinge || joint.type == simcore::JointType::Slider) {
            addLine(joint.anchorA - joint.axis * look::kJointAxisLength,
                    joint.anchorA + joint.axis * look::kJointAxisLength, color);
        }
    }
    if (grabLine) addLine(grabLine->first, grabLine->second, srgb(look::kGrabColor));
    return std::move(m_lines);
}

}  // namespace interplay
