#include "app/viewport/gizmo_tool.h"

#include "app/document/undo_commands.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include <QSettings>
#include <QUndoStack>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <utility>

namespace interplay {

double preferredGizmoStep(const char* key, double fallback) {
    bool ok = false;
    const double value = QSettings().value(QLatin1String(key), fallback).toDouble(&ok);
    return ok && std::isfinite(value) && value > 0.0 ? value : fallback;
}

void GizmoTool::setDocument(SceneDocument* document) {
    if (m_document) disconnect(m_document, nullptr, this, nullptr);
    if (isDragging()) abandon();
    m_document = document;
    if (!m_document) return;
    // The drag's body indices would name other bodies, or none.
    connect(m_document, &SceneDocument::sceneReplaced, this, &GizmoTool::abandon);
    connect(m_document, &SceneDocument::bodyAboutToBeInserted, this, &GizmoTool::abandon);
    connect(m_document, &SceneDocument::bodyAboutToBeRemoved, this, &GizmoTool::abandon);
    connect(m_document, &SceneDocument::bodyAboutToBeMoved, this, &GizmoTool::abandon);
}

void GizmoTool::setMode(std::optional<gizmo::Mode> mode) {
    if (m_mode == mode) return;
    if (isDragging()) cancel();
    m_mode = mode;
    m_highlighted = gizmo::Handle::None;
    emit repaintNeeded();
}

void GizmoTool::setSpace(gizmo::Space space) {
    if (m_space == space) return;
    if (isDragging()) cancel();
    m_space = space;
    emit repaintNeeded();
}

std::optional<gizmo::Placement> GizmoTool::placement() const {
    if (!m_mode || !m_document || !m_simulation) return std::nullopt;
    // At the bodies as they are drawn (the snapshot): their live poses, which a run moves away
    // from the authored.
    const WorldSnapshot& snapshot = m_simulation->snapshot();
    const auto& ids = m_simulation->bodyIds();
    glm::vec3 sum(0.0f);
    int count = 0;
    glm::quat activeOrientation(1.0f, 0.0f, 0.0f, 0.0f);
    for (int index : m_document->selectedBodies()) {
        if (index < 0 || index >= static_cast<int>(ids.size())) continue;
        const WorldSnapshot::Body* body = snapshot.find(ids[static_cast<std::size_t>(index)]);
        if (!body) continue;
        sum += body->transform.position;
        ++count;
        activeOrientation = body->transform.rotation;
    }
    if (count == 0) return std::nullopt;
    const glm::mat3 axes = m_space == gizmo::Space::Local ? glm::mat3_cast(activeOrientation) : glm::mat3(1.0f);
    return gizmo::place(m_viewport.camera(), static_cast<float>(m_viewport.height()), sum / static_cast<float>(count),
                        axes);
}

bool GizmoTool::press(const QPointF& position) {
    const auto where = placement();
    if (!where) return false;
    const auto [origin, direction] = m_viewport.rayThrough(position);
    const gizmo::Ray ray{origin, direction};
    m_drag = gizmo::Drag::begin(gizmo::pick(*m_mode, *where, ray), *where, ray);
    if (!m_drag) return false;
    m_highlighted = m_drag->handle();
    m_snapSteps = {static_cast<float>(preferredGizmoStep(kGizmoGridStepKey, kDefaultGizmoGridStep)),
                   glm::radians(static_cast<float>(preferredGizmoStep(kGizmoAngleStepKey, kDefaultGizmoAngleStep)))};
    m_indices = m_document->selectedBodies();
    m_startBodies.clear();
    for (int index : m_indices) m_startBodies.push_back(m_document->body(index));
    // One body turns about its own centre (its position stays); several about their centre, which
    // moves each of them too.
    m_field = *m_mode == gizmo::Mode::Move ? BodyField::Position
              : m_indices.size() == 1      ? BodyField::Orientation
                                           : BodyField::Turn;
    m_pushed = false;
    emit repaintNeeded();
    return true;
}

void GizmoTool::drag(const QPointF& position, Qt::KeyboardModifiers modifiers) {
    if (!m_drag) return;
    const auto [origin, direction] = m_viewport.rayThrough(position);
    // Ctrl snaps, as in Blender and Godot, or drags freely where snapping is on (Blender's).
    const bool snapping = m_snapping != bool(modifiers & Qt::ControlModifier);
    const gizmo::Snap snap = snapping ? m_snapSteps : gizmo::Snap{};
    gizmo::Motion motion = m_drag->update({origin, direction}, snap);
    std::vector<simcore::SceneBody> after = m_startBodies;
    if (m_field == BodyField::Position) {
        // The same offset for each, so a run's live bodies follow as the authored ones go.
        for (simcore::SceneBody& body : after) body.body.position += motion.translation;
    } else {
        if (m_field == BodyField::Turn) {
            // About the authored centre, as the command sets authored poses (the same point as the
            // gizmo's live centre until a run moves the bodies).
            glm::vec3 center(0.0f);
            for (const simcore::SceneBody& body : m_startBodies) center += body.body.position;
            motion.pivot = center / static_cast<float>(m_startBodies.size());
        }
        for (simcore::SceneBody& body : after) {
            body.body.orientation = glm::normalize(motion.rotation * body.body.orientation);
            if (m_field == BodyField::Turn) body.body.position = motion.apply(body.body.position);
        }
    }
    push(std::move(after));
}

void GizmoTool::push(std::vector<simcore::SceneBody> after) {
    const QString verb = m_field == BodyField::Position ? tr("Move %1") : tr("Rotate %1");
    // The first command of a drag starts a history entry; the rest merge into it.
    m_document->undoStack()->push(new MoveBodies(m_document, verb.arg(bodiesLabel(*m_document, m_indices)), m_field,
                                                 m_indices, std::move(after), std::exchange(m_pushed, true)));
}

void GizmoTool::release() {
    m_drag.reset();
    m_highlighted = gizmo::Handle::None;  // the next mouse move finds what is under the cursor
    m_startBodies.clear();
    m_indices.clear();
    emit repaintNeeded();
}

void GizmoTool::cancel() {
    // Back where the drag began: merged into the drag's entry, which then changes nothing and
    // leaves the history.
    if (m_drag && m_pushed) push(m_startBodies);
    release();
}

void GizmoTool::abandon() {
    if (isDragging()) release();
}

void GizmoTool::hover(const QPointF& position) {
    gizmo::Handle hovered = gizmo::Handle::None;
    if (const auto where = placement()) {
        const auto [origin, direction] = m_viewport.rayThrough(position);
        hovered = gizmo::pick(*m_mode, *where, {origin, direction});
    }
    if (hovered == m_highlighted) return;
    m_highlighted = hovered;
    emit repaintNeeded();
}

void GizmoTool::clearHover() {
    if (isDragging() || m_highlighted == gizmo::Handle::None) return;
    m_highlighted = gizmo::Handle::None;
    emit repaintNeeded();
}

}  // namespace interplay
