#include "app/document/undo_commands.h"

#include <QCoreApplication>

#include <algorithm>

namespace interplay {

QString bodiesLabel(const SceneDocument& document, const QList<int>& indices) {
    if (indices.size() == 1) return document.bodyName(indices.first());
    return QCoreApplication::translate("interplay::undo", "%n Bodies", nullptr, static_cast<int>(indices.size()));
}

bool sameSceneBody(const simcore::SceneBody& a, const simcore::SceneBody& b) {
    const simcore::BodyCreationSettings& x = a.body;
    const simcore::BodyCreationSettings& y = b.body;
    const bool sameShape = x.shape.type == y.shape.type && x.shape.halfExtents == y.shape.halfExtents &&
                           x.shape.radius == y.shape.radius && x.shape.halfHeight == y.shape.halfHeight &&
                           x.shape.hull == y.shape.hull;
    return sameShape && x.name == y.name && x.motion == y.motion && x.position == y.position &&
           x.orientation == y.orientation && x.linearVelocity == y.linearVelocity &&
           x.angularVelocity == y.angularVelocity && x.mass == y.mass && x.density == y.density &&
           x.friction == y.friction && x.restitution == y.restitution && x.ccd == y.ccd && a.color == b.color;
}

// ---- AddBodies ----------------------------------------------------------------------------------

AddBodies::AddBodies(SceneDocument* document, const QString& text, QList<int> indices,
                     std::vector<simcore::SceneBody> bodies)
    : QUndoCommand(text), m_document(document), m_indices(std::move(indices)), m_bodies(std::move(bodies)) {
    Q_ASSERT(static_cast<std::size_t>(m_indices.size()) == m_bodies.size());
    Q_ASSERT(std::is_sorted(m_indices.begin(), m_indices.end()));
}

void AddBodies::redo() {
    // Ascending: each index is final once the bodies before it are in place.
    for (qsizetype i = 0; i < m_indices.size(); ++i) m_document->insertBody(m_indices[i], m_bodies[static_cast<std::size_t>(i)]);
    m_document->setSelectedBodies(m_indices);
}

void AddBodies::undo() {
    for (qsizetype i = m_indices.size() - 1; i >= 0; --i) m_document->takeBody(m_indices[i]);
}

// ---- RemoveBodies -------------------------------------------------------------------------------

RemoveBodies::RemoveBodies(SceneDocument* document, QList<int> indices)
    : m_document(document), m_indices(std::move(indices)) {
    std::sort(m_indices.begin(), m_indices.end());
    m_indices.erase(std::unique(m_indices.begin(), m_indices.end()), m_indices.end());
    setText(QCoreApplication::translate("interplay::undo", "Delete %1").arg(bodiesLabel(*document, m_indices)));
}

void RemoveBodies::redo() {
    // Joints first: a joint without its body would refer to whatever takes the body's place.
    QList<int> joints;
    for (int body : m_indices) joints << m_document->jointsOf(body);
    std::sort(joints.begin(), joints.end());
    joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
    m_joints.clear();
    for (qsizetype i = joints.size() - 1; i >= 0; --i) m_joints.emplace_back(joints[i], m_document->takeJoint(joints[i]));
    std::reverse(m_joints.begin(), m_joints.end());

    m_bodies.assign(static_cast<std::size_t>(m_indices.size()), {});
    // Descending, so the indices still to remove do not shift.
    for (qsizetype i = m_indices.size() - 1; i >= 0; --i) {
        m_bodies[static_cast<std::size_t>(i)] = m_document->takeBody(m_indices[i]);
    }
}

void RemoveBodies::undo() {
    for (qsizetype i = 0; i < m_indices.size(); ++i) m_document->insertBody(m_indices[i], m_bodies[static_cast<std::size_t>(i)]);
    for (const auto& [index, joint] : m_joints) m_document->insertJoint(index, joint);
    m_document->setSelectedBodies(m_indices);
}

// ---- ReorderBody --------------------------------------------------------------------------------

ReorderBody::ReorderBody(SceneDocument* document, int from, int to)
    : QUndoCommand(QCoreApplication::translate("interplay::undo", "Reorder %1").arg(document->bodyName(from))),
      m_document(document), m_from(from), m_to(to) {
    setObsolete(from == to);
}

void ReorderBody::redo() {
    m_document->moveBody(m_from, m_to);
}

void ReorderBody::undo() {
    m_document->moveBody(m_to, m_from);
}

// ---- ChangeBodies -------------------------------------------------------------------------------

ChangeBodies::ChangeBodies(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
                           std::vector<simcore::SceneBody> after, bool mergeable)
    : QUndoCommand(text), m_document(document), m_field(field), m_indices(std::move(indices)),
      m_after(std::move(after)), m_mergeable(mergeable) {
    Q_ASSERT(static_cast<std::size_t>(m_indices.size()) == m_after.size());
    m_before.reserve(m_after.size());
    for (int index : m_indices) m_before.push_back(document->body(index));
    updateObsolete();
}

bool ChangeBodies::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const ChangeBodies*>(other);
    if (!next->m_mergeable || next->m_field != m_field || next->m_indices != m_indices) return false;
    m_after = next->m_after;
    updateObsolete();
    return true;
}

void ChangeBodies::redo() {
    apply(m_after);
}

void ChangeBodies::undo() {
    apply(m_before);
}

void ChangeBodies::apply(const std::vector<simcore::SceneBody>& values) {
    for (qsizetype i = 0; i < m_indices.size(); ++i) m_document->setBody(m_indices[i], values[static_cast<std::size_t>(i)], m_field);
}

void ChangeBodies::updateObsolete() {
    bool unchanged = true;
    for (std::size_t i = 0; i < m_before.size() && unchanged; ++i) unchanged = sameSceneBody(m_before[i], m_after[i]);
    setObsolete(unchanged);
}

// ---- ChangeSettings -----------------------------------------------------------------------------

ChangeSettings::ChangeSettings(SceneDocument* document, const QString& text, QString key,
                               const simcore::WorldSettings& after, bool mergeable)
    : QUndoCommand(text), m_document(document), m_key(std::move(key)), m_before(document->scene().settings),
      m_after(after), m_mergeable(mergeable) {
    setObsolete(m_before == m_after);
}

bool ChangeSettings::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const ChangeSettings*>(other);
    if (!next->m_mergeable || next->m_key != m_key) return false;
    m_after = next->m_after;
    setObsolete(m_before == m_after);
    return true;
}

void ChangeSettings::redo() {
    m_document->setSettings(m_after);
}

void ChangeSettings::undo() {
    m_document->setSettings(m_before);
}

}  // namespace interplay
