#pragma once
// The debug overlay: a DebugDraw that turns what World::draw emits into coloured lines over the
// bodies: bounds, contact points and normals (as the DebugDrawOptions ask), the joints (always:
// a rod or a hinge pin, a small cross at each live anchor; selected joints in the selection colour
// with their anchors marked large and their axis drawn) and the grab spring. And, painted over
// the frame in widget pixels, the box-select rectangle.

#include "app/viewport/renderer.h"

#include "simcore/world/debug_draw.h"

#include <QList>

class QPainter;
class QRect;

#include <optional>
#include <utility>
#include <vector>

namespace interplay {

class DebugDrawOptions;

// The running world's joints by scene index (jointIds[i] is the world joint made from scene joint
// i), gathered from World::draw; none where the world does not hold the scene's joint.
class SceneJoints : public simcore::DebugDraw {
public:
    explicit SceneJoints(const std::vector<simcore::JointId>& jointIds);
    void drawJoint(const simcore::DebugJoint& joint) override;
    const std::vector<std::optional<simcore::DebugJoint>>& bySceneIndex() const { return m_bySceneIndex; }

    // The options that make World::draw emit the joints only.
    static simcore::DebugDrawOptions jointsOnly();

private:
    const std::vector<simcore::JointId>& m_jointIds;
    std::vector<int> m_sceneIndexOfSlot;  // by JointId::index, -1 where no scene joint
    std::vector<std::optional<simcore::DebugJoint>> m_bySceneIndex;
};

// The box-select rectangle: a faint selection-coloured fill, a dark edge and a light dashed line on
// it, so the box reads over a light sky and a dark body alike.
void paintRubberBand(QPainter& painter, const QRect& box);

class DebugOverlay : public simcore::DebugDraw {
public:
    // `options` may be null (overlays off, the joints still drawn).
    DebugOverlay(const DebugDrawOptions* options, const std::vector<simcore::JointId>& jointIds);

    // What World::draw (or a snapshot of it) must emit for an overlay with these `options`.
    static simcore::DebugDrawOptions worldOptions(const DebugDrawOptions* options);

    void drawBounds(simcore::BodyId body, const simcore::Aabb& box, simcore::DebugBoundsKind kind) override;
    void drawContactPoint(const simcore::DebugContactPoint& point) override;
    void drawJoint(const simcore::DebugJoint& joint) override { m_joints.drawJoint(joint); }

    // After World::draw: the lines, joints last (in scene order) and then the grab spring, if any.
    std::vector<OverlayVertex> finish(const QList<int>& selectedJoints,
                                      const std::optional<std::pair<glm::vec3, glm::vec3>>& grabLine);

private:
    void addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color);
    // Three axis-aligned strokes through `point`, each 2 * halfSize long.
    void addCross(const glm::vec3& point, float halfSize, const glm::vec3& color);

    bool m_bounds = false;
    bool m_contactPoints = false;
    bool m_contactNormals = false;
    SceneJoints m_joints;
    std::vector<OverlayVertex> m_lines;
};

}  // namespace interplay
