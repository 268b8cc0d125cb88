#include "app/viewport/selection_tool.h"

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QUndoStack>
#include <QWheelEvent>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace interplay {
namespace {

// Fly speed in m/s per metre of camera distance, so flying suits a scene of any size; Shift boosts.
constexpr float kFlySpeedPerMetre = 0.6f;
constexpr float kFlyBoost = 4.0f;
constexpr float kRotateDegreesPerPixel = 0.5f;  // R- or Alt-drag turning a body about the vertical
constexpr int kClickJitterPixels = 3;           // a press that travels no further is still a click
const QSet<int> kFlyKeys{Qt::Key_W, Qt::Key_A, Qt::Key_S, Qt::Key_D, Qt::Key_Q, Qt::Key_E, Qt::Key_Shift};

}  // namespace

SelectionTool::SelectionTool(Viewport& viewport) : m_viewport(viewport), m_gizmo(viewport) {
    connect(&m_gizmo, &GizmoTool::repaintNeeded, this, &SelectionTool::repaintNeeded);
    m_flyTimer.setInterval(16);
    connect(&m_flyTimer, &QTimer::timeout, this, &SelectionTool::flyTick);
}

bool SelectionTool::mousePress(QMouseEvent* event) {
    if (m_gesture == Gesture::Gizmo && event->button() == Qt::RightButton) {
        m_gizmo.cancel();
        m_gesture = Gesture::None;
        return true;
    }
    if (m_gesture != Gesture::None) return true;  // a second button during a gesture: ignore it
    if (event->button() != Qt::RightButton && event->button() != Qt::MiddleButton &&
        event->button() != Qt::LeftButton) {
        return false;
    }
    m_lastMouse = m_pressMouse = event->position().toPoint();
    m_pressModifiers = event->modifiers();
    m_dragMoved = false;
    m_clickedBody = -1;
    m_clickedJoint = -1;
    m_jointInPressedBody = -1;
    if (event->button() == Qt::RightButton) {
        m_gesture = Gesture::Fly;
        m_flyClock.start();
        m_flyTimer.start();
    } else if (event->button() == Qt::MiddleButton) {
        // As in Blender and Godot: the left button selects, the middle one turns the view.
        m_gesture = (event->modifiers() & Qt::ShiftModifier) ? Gesture::Pan : Gesture::Orbit;
    } else if (m_gizmo.press(event->position())) {
        m_gesture = Gesture::Gizmo;  // drawn over everything, the gizmo takes presses on its handles first
    } else {
        // Joint marks are drawn over the bodies, so a joint near the cursor takes the click (it is
        // selected on release, and a drag from it moves the camera, never a body), unless its point
        // lies inside or behind the body under the cursor, as a joint anchored at a body's centre
        // does: then the body takes the press, to be dragged, and a click on it once it alone is
        // selected reaches the joint, if the joint is one of that body's.
        auto hit = m_viewport.pick(event->position());
        const int hitIndex = hit ? m_simulation->sceneIndexOf(hit->body) : -1;
        if (const auto joint = m_viewport.pickJoint(event->position())) {
            if (!hit || hit->fraction >= joint->distance) {
                m_clickedJoint = joint->joint;
            } else if (m_document && hitIndex >= 0) {
                const simcore::SceneJoint& hidden = m_document->joint(joint->joint);
                if (hidden.bodyA == static_cast<std::size_t>(hitIndex) || hidden.bodyB == static_cast<std::size_t>(hitIndex))
                    m_jointInPressedBody = joint->joint;
            }
        }
        if (m_clickedJoint >= 0) hit.reset();
        const int sceneIndex = hit ? hitIndex : -1;
        m_pressedBodyWasSelected = m_document && sceneIndex >= 0 && m_document->selectedBodies() == QList<int>{sceneIndex};
        if (hit && (sceneIndex >= 0 || m_simulation->isPlaying())) {
            pressOnBody(event, *hit, sceneIndex);
        } else if (!hit && m_clickedJoint < 0 && m_document) {
            m_gesture = Gesture::BoxSelect;  // a release without a drag is a click on nothing
        } else {
            m_gesture = Gesture::Orbit;
        }
    }
    return true;
}

void SelectionTool::pressOnBody(QMouseEvent* event, const simcore::WorldRayHit& hit, int sceneIndex) {
    m_clickedBody = sceneIndex;
    const bool extend = event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier);
    // Select on press (so a drag moves what was pressed), unless extending: that toggles on release.
    if (m_document && sceneIndex >= 0 && !extend && !m_document->selectedBodies().contains(sceneIndex)) {
        m_document->setSelectedBodies({sceneIndex});
    }
    if (m_simulation->isPlaying()) {
        // Grab the hit point; the spring keeps it at the same distance from the eye.
        const simcore::World* world = m_simulation->world();
        const glm::vec3 local = glm::inverse(world->orientation(hit.body)) * (hit.point - world->position(hit.body));
        m_grabDepth = glm::length(hit.point - m_viewport.rayThrough(event->position()).first);
        m_simulation->beginGrab(hit.body, local, hit.point);
        m_gesture = Gesture::Grab;
        return;
    }
    if (!m_document || extend) {
        m_gesture = Gesture::Orbit;
        return;
    }
    m_gesture = (m_rotateKeyHeld || (event->modifiers() & Qt::AltModifier)) ? Gesture::RotateBodies : Gesture::MoveBodies;
    m_dragIndices = m_document->selectedBodies();
    m_dragStartBodies.clear();
    for (int index : m_dragIndices) m_dragStartBodies.push_back(m_document->body(index));
    m_dragPlaneHeight = hit.point.y;
    m_dragStart = hit.point;
    m_dragPushed = false;
}

std::optional<glm::vec3> SelectionTool::dragPlanePoint(const QPointF& pixel) const {
    const auto [origin, direction] = m_viewport.rayThrough(pixel);
    // Rays nearly parallel to the plane would throw the body to the horizon.
    if (std::abs(direction.y) < 1e-3f) return std::nullopt;
    const float t = (m_dragPlaneHeight - origin.y) / direction.y;
    if (t <= 0.0f || t > m_viewport.camera().rayReach()) return std::nullopt;
    return origin + t * direction;
}

void SelectionTool::dragBodies(const QPointF& position) {
    std::vector<simcore::SceneBody> after = m_dragStartBodies;
    QString text;
    BodyField field;
    if (m_gesture == Gesture::MoveBodies) {
        const auto point = dragPlanePoint(position);
        if (!point) return;
        const glm::vec3 offset = *point - m_dragStart;
        for (simcore::SceneBody& body : after) body.body.position += offset;
        field = BodyField::Position;
        text = tr("Move %1").arg(bodiesLabel(*m_document, m_dragIndices));
    } else {
        const float degrees = static_cast<float>(position.x() - m_pressMouse.x()) * kRotateDegreesPerPixel;
        const glm::quat turn = glm::angleAxis(glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
        for (simcore::SceneBody& body : after) body.body.orientation = glm::normalize(turn * body.body.orientation);
        field = BodyField::Orientation;
        text = tr("Rotate %1").arg(bodiesLabel(*m_document, m_dragIndices));
    }
    // The first command of a drag starts a history entry; the rest merge into it.
    m_document->undoStack()->push(
        new MoveBodies(m_document, text, field, m_dragIndices, std::move(after), std::exchange(m_dragPushed, true)));
}

bool SelectionTool::mouseMove(QMouseEvent* event) {
    if (m_gesture == Gesture::None) {
        m_gizmo.hover(event->position());
        return false;
    }
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if ((position - m_pressMouse).manhattanLength() > kClickJitterPixels) m_dragMoved = true;
    if (!m_dragMoved) return true;
    Camera& camera = m_viewport.camera();
    const float dx = static_cast<float>(delta.x()), dy = static_cast<float>(delta.y());
    switch (m_gesture) {
    case Gesture::Orbit: camera.orbit(dx, dy); break;
    case Gesture::Pan: camera.pan(dx, dy, static_cast<float>(m_viewport.height())); break;
    case Gesture::Fly: camera.lookAround(dx, dy); break;
    case Gesture::MoveBodies:
    case Gesture::RotateBodies: dragBodies(event->position()); return true;
    case Gesture::BoxSelect: emit repaintNeeded(); return true;
    case Gesture::Gizmo: m_gizmo.drag(event->position(), event->modifiers()); return true;
    case Gesture::Grab: {
        const auto [origin, direction] = m_viewport.rayThrough(event->position());
        m_simulation->moveGrab(origin + direction * m_grabDepth);
        emit repaintNeeded();
        return true;
    }
    case Gesture::None: return true;
    }
    emit cameraChanged();
    emit repaintNeeded();
    return true;
}

bool SelectionTool::mouseRelease(QMouseEvent* event) {
    if (m_gesture == Gesture::None) return false;
    if (m_gesture == Gesture::Grab) m_simulation->endGrab();
    if (m_gesture == Gesture::Gizmo) {
        m_gizmo.release();
        m_gesture = Gesture::None;
        return true;
    }
    if (m_gesture == Gesture::Fly) {
        m_flyTimer.stop();
        m_flyKeys.clear();
    }
    if (!m_dragMoved) clickSelect(event->button());
    else if (m_gesture == Gesture::BoxSelect) boxSelect(*rubberBand());
    m_gesture = Gesture::None;
    m_dragStartBodies.clear();
    m_dragIndices.clear();
    emit repaintNeeded();
    return true;
}

void SelectionTool::clickSelect(Qt::MouseButton button) {
    // A click (no drag): Ctrl/Shift toggles the joint or body in the selection; a plain click
    // selects just it, or on nothing clears the selection. Camera gestures that moved select nothing.
    if (!m_document || button != Qt::LeftButton) return;
    const bool extend = m_pressModifiers & (Qt::ControlModifier | Qt::ShiftModifier);
    const auto toggle = [](QList<int> indices, int index) {
        if (!indices.removeOne(index)) indices << index;
        return indices;
    };
    if (extend && m_clickedJoint >= 0) {
        m_document->setSelection(m_document->selectedBodies(), toggle(m_document->selectedJoints(), m_clickedJoint));
    } else if (extend && m_clickedBody >= 0) {
        m_document->setSelection(toggle(m_document->selectedBodies(), m_clickedBody), m_document->selectedJoints());
    } else if (!extend && m_clickedJoint >= 0) {
        m_document->setSelectedJoints({m_clickedJoint});
    } else if (!extend && m_clickedBody < 0) {
        m_document->setSelectedBodies({});
    } else if (!extend && m_jointInPressedBody >= 0 && m_pressedBodyWasSelected) {
        m_document->setSelectedJoints({m_jointInPressedBody});
    } else if (!extend) {
        m_document->setSelectedBodies({m_clickedBody});
    }
}

std::optional<QRect> SelectionTool::rubberBand() const {
    if (m_gesture != Gesture::BoxSelect || !m_dragMoved) return std::nullopt;
    return QRect(m_pressMouse, m_lastMouse).normalized();
}

void SelectionTool::boxSelect(const QRect& box) {
    // A body is in the box when its centre (the live one: what the view shows) projects inside it:
    // one point per body, so a large ground seen across the whole view is not caught by every box.
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    static const std::vector<simcore::BodyId> kNoBodies;
    const std::vector<simcore::BodyId>& ids = m_simulation ? m_simulation->bodyIds() : kNoBodies;
    const float width = static_cast<float>(m_viewport.width()), height = static_cast<float>(m_viewport.height());
    QList<int> inBox;
    for (int i = 0; i < m_document->bodyCount(); ++i) {
        const std::size_t slot = static_cast<std::size_t>(i);
        const glm::vec3 centre = world && slot < ids.size() ? world->position(ids[slot]) : m_document->body(i).body.position;
        const glm::vec3 pixel = m_viewport.camera().project(centre, width, height);
        if (pixel.z > 1.0f || pixel.z < 0.0f) continue;  // behind the eye or beyond the far plane
        if (box.contains(QPoint(static_cast<int>(std::floor(pixel.x)), static_cast<int>(std::floor(pixel.y))))) inBox << i;
    }
    // Plain replaces the selection (dropping selected joints, as a click on nothing does), Shift
    // adds, Ctrl toggles (a box may hold selected and unselected bodies, so the two differ).
    QList<int> bodies = m_document->selectedBodies();
    QList<int> joints = m_document->selectedJoints();
    if (m_pressModifiers & Qt::ControlModifier) {
        for (int i : inBox) {
            if (!bodies.removeOne(i)) bodies << i;
        }
    } else if (m_pressModifiers & Qt::ShiftModifier) {
        bodies << inBox;
    } else {
        bodies = inBox;
        joints.clear();
    }
    m_document->setSelection(bodies, joints);
}

void SelectionTool::wheel(QWheelEvent* event) {
    // 120 units per notch; touchpads send smaller deltas, which zoom proportionally.
    m_viewport.camera().zoom(static_cast<float>(event->angleDelta().y()) / 120.0f);
    emit cameraChanged();
    emit repaintNeeded();
}

bool SelectionTool::wantsKey(const QKeyEvent* event) const {
    if (m_gesture == Gesture::Gizmo) return event->key() == Qt::Key_Escape;
    return m_gesture == Gesture::Fly && kFlyKeys.contains(event->key());
}

bool SelectionTool::keyPress(QKeyEvent* event) {
    if (m_gesture == Gesture::Gizmo && event->key() == Qt::Key_Escape) {
        m_gizmo.cancel();
        m_gesture = Gesture::None;
        return true;
    }
    if (event->key() == Qt::Key_R && !(event->modifiers() & ~Qt::KeypadModifier)) {
        m_rotateKeyHeld = true;
        return true;
    }
    if (m_gesture != Gesture::Fly || !kFlyKeys.contains(event->key())) return false;
    m_flyKeys.insert(event->key());
    return true;
}

bool SelectionTool::keyRelease(QKeyEvent* event) {
    if (event->isAutoRepeat()) return false;
    if (event->key() == Qt::Key_R && m_rotateKeyHeld) {
        m_rotateKeyHeld = false;
        return true;
    }
    return m_flyKeys.remove(event->key());
}

void SelectionTool::focusOut() {
    // A key released in another window never reaches us.
    m_flyKeys.clear();
    m_rotateKeyHeld = false;
}

void SelectionTool::flyTick() {
    const float seconds = static_cast<float>(m_flyClock.restart()) * 1e-3f;
    glm::vec3 move(0.0f);  // (right, up, forward)
    if (m_flyKeys.contains(Qt::Key_D)) move.x += 1.0f;
    if (m_flyKeys.contains(Qt::Key_A)) move.x -= 1.0f;
    if (m_flyKeys.contains(Qt::Key_E)) move.y += 1.0f;
    if (m_flyKeys.contains(Qt::Key_Q)) move.y -= 1.0f;
    if (m_flyKeys.contains(Qt::Key_W)) move.z += 1.0f;
    if (m_flyKeys.contains(Qt::Key_S)) move.z -= 1.0f;
    if (move == glm::vec3(0.0f)) return;
    Camera& camera = m_viewport.camera();
    const float speed = kFlySpeedPerMetre * std::max(camera.distance(), 2.0f) *
                        (m_flyKeys.contains(Qt::Key_Shift) ? kFlyBoost : 1.0f);
    camera.fly(glm::normalize(move) * speed * std::min(seconds, 0.1f));
    emit cameraChanged();
    emit repaintNeeded();
}

}  // namespace interplay
