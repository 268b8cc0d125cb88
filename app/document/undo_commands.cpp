#include "app/document/undo_commands.h"

#include "app/document/scene_edits.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace interplay {

QString bodiesLabel(const SceneDocument& document, const QList<int>& indices) {
    if (indices.size() == 1) return document.bodyName(indices.first());
    return QCoreApplication::translate("interplay::undo", "%n Bodies", nullptr, static_cast<int>(indices.size()));
}

QString jointsLabel(const SceneDocument& document, const QList<int>& indices) {
    if (indices.size() == 1) return document.jointName(indices.first());
    return QCoreApplication::translate("interplay::undo", "%n Joints", nullptr, static_cast<int>(indices.size()));
}

bool sameSceneJoint(const simcore::SceneJoint& a, const simcore::SceneJoint& b) {
    const simcore::JointCreationSettings& x = a.joint;
    const simcore::JointCreationSettings& y = b.joint;
    return a.bodyA == b.bodyA && a.bodyB == b.bodyB && x.name == y.name && x.type == y.type && x.anchor == y.anchor &&
           x.anchorB == y.anchorB && x.axis == y.axis && x.limits == y.limits && x.motor == y.motor &&
           x.spring == y.spring && x.minLength == y.minLength && x.maxLength == y.maxLength &&
           x.collideConnected == y.collideConnected;
}

bool sameSceneBody(const simcore::SceneBody& a, const simcore::SceneBody& b) {
    const simcore::BodyCreationSettings& x = a.body;
    const simcore::BodyCreationSettings& y = b.body;
    const bool sameShape = x.shape.type == y.shape.type && x.shape.halfExtents == y.shape.halfExtents &&
                           x.shape.radius == y.shape.radius && x.shape.halfHeight == y.shape.halfHeight &&
                           x.shape.hull == y.shape.hull && x.shape.compound == y.shape.compound &&
                           x.shape.mesh == y.shape.mesh && x.shape.heightField == y.shape.heightField;
    return sameShape && x.name == y.name && x.motion == y.motion && x.position == y.position &&
           x.orientation == y.orientation && x.linearVelocity == y.linearVelocity &&
           x.angularVelocity == y.angularVelocity && x.mass == y.mass && x.density == y.density &&
           x.friction == y.friction && x.restitution == y.restitution && x.rollingResistance == y.rollingResistance &&
           x.ccd == y.ccd && a.color == b.color && a.meshFile == b.meshFile;
}

// ---- AddBodies ----------------------------------------------------------------------------------

AddBodies::AddBodies(SceneDocument* document, const QString& text, QList<int> indices,
                     std::vector<simcore::SceneBody> bodies, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_indices(std::move(indices)), m_bodies(std::move(bodies)) {
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

RemoveBodies::RemoveBodies(SceneDocument* document, QList<int> indices, QList<int> joints)
    : m_document(document), m_indices(std::move(indices)), m_selectedJoints(std::move(joints)) {
    for (QList<int>* list : {&m_indices, &m_selectedJoints}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    QStringList what;
    if (!m_indices.isEmpty()) what << bodiesLabel(*document, m_indices);
    if (!m_selectedJoints.isEmpty()) what << jointsLabel(*document, m_selectedJoints);
    setText(QCoreApplication::translate("interplay::undo", "Delete %1")
                .arg(what.join(QCoreApplication::translate("interplay::undo", " and "))));
}

void RemoveBodies::redo() {
    // Joints first: a joint without its body would refer to whatever takes the body's place.
    QList<int> joints = m_selectedJoints;
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
    m_document->setSelection(m_indices, m_selectedJoints);
}

// ---- AddJoint -----------------------------------------------------------------------------------

AddJoint::AddJoint(SceneDocument* document, const QString& text, int index, simcore::SceneJoint joint,
                   QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_index(index), m_joint(std::move(joint)) {}

void AddJoint::redo() {
    m_document->insertJoint(m_index, m_joint);
    m_document->setSelectedJoints({m_index});
}

void AddJoint::undo() {
    m_document->takeJoint(m_index);
}

// ---- AddFragment --------------------------------------------------------------------------------

AddFragment::AddFragment(SceneDocument* document, const QString& text, simcore::Scene fragment)
    : QUndoCommand(text), m_document(document) {
    const std::size_t firstBody = static_cast<std::size_t>(document->bodyCount());
    for (std::size_t i = 0; i < fragment.bodies.size(); ++i) m_bodyIndices << static_cast<int>(firstBody + i);
    new AddBodies(document, text, m_bodyIndices, std::move(fragment.bodies), this);
    int jointIndex = document->jointCount();
    for (simcore::SceneJoint& joint : fragment.joints) {
        joint.bodyA += firstBody;
        if (joint.bodyB) *joint.bodyB += firstBody;
        new AddJoint(document, text, jointIndex++, std::move(joint), this);
    }
}

void AddFragment::redo() {
    QUndoCommand::redo();  // the bodies, then their joints (each joint selects itself)
    m_document->setSelectedBodies(m_bodyIndices);
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

// ---- ChangeObjects ------------------------------------------------------------------------------

template <typename Object>
ChangeObjects<Object>::ChangeObjects(SceneDocument* document, const QString& text, Field field, QList<int> indices,
                                     std::vector<Object> after, bool mergeable, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_field(field), m_indices(std::move(indices)),
      m_after(std::move(after)), m_mergeable(mergeable) {
    Q_ASSERT(static_cast<std::size_t>(m_indices.size()) == m_after.size());
    m_before.reserve(m_after.size());
    for (int index : m_indices) m_before.push_back(ObjectAccess<Object>::get(*document, index));
    updateObsolete();
}

template <typename Object>
bool ChangeObjects<Object>::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const ChangeObjects*>(other);
    if (!next->m_mergeable || next->m_field != m_field || next->m_indices != m_indices) return false;
    m_after = next->m_after;
    updateObsolete();
    return true;
}

template <typename Object>
void ChangeObjects<Object>::redo() {
    apply(m_after);
}

template <typename Object>
void ChangeObjects<Object>::undo() {
    apply(m_before);
}

template <typename Object>
void ChangeObjects<Object>::apply(const std::vector<Object>& values) {
    for (qsizetype i = 0; i < m_indices.size(); ++i) {
        ObjectAccess<Object>::set(*m_document, m_indices[i], values[static_cast<std::size_t>(i)], m_field);
    }
}

template <typename Object>
void ChangeObjects<Object>::updateObsolete() {
    bool unchanged = true;
    for (std::size_t i = 0; i < m_before.size() && unchanged; ++i) unchanged = ObjectAccess<Object>::same(m_before[i], m_after[i]);
    setObsolete(unchanged);
}

template class ChangeObjects<simcore::SceneBody>;
template class ChangeObjects<simcore::SceneJoint>;

// ---- MoveBodies ---------------------------------------------------------------------------------

MoveBodies::MoveBodies(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
                       std::vector<simcore::SceneBody> after, bool mergeable)
    : QUndoCommand(text), m_field(field), m_indices(indices), m_mergeable(mergeable) {
    Q_ASSERT(isPlacementField(field));
    // Carried from where the bodies are now: a merged drag carries the joints step by step, as the
    // bodies go.
    std::vector<std::pair<int, simcore::SceneJoint>> carried = jointsCarriedWith(document->scene(), indices, after);
    // Bodies before joints: undo runs the children in reverse, so the joints go back first.
    m_bodies = new ChangeBodies(document, text, field, std::move(indices), std::move(after), mergeable, this);
    if (!carried.empty()) {
        std::vector<simcore::SceneJoint> joints;
        for (auto& [index, joint] : carried) {
            m_jointIndices << index;
            joints.push_back(std::move(joint));
        }
        m_joints = new ChangeJoints(document, text, JointField::Placement, m_jointIndices, std::move(joints), mergeable, this);
    }
    updateObsolete();
}

bool MoveBodies::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const MoveBodies*>(other);
    // Checked here, so that the children below either both merge or neither does.
    if (!next->m_mergeable || next->m_field != m_field || next->m_indices != m_indices || next->m_jointIndices != m_jointIndices)
        return false;
    m_bodies->mergeWith(next->m_bodies);
    if (m_joints) m_joints->mergeWith(next->m_joints);
    // Back where the drag began, the joints go back exactly: carried there and back step by step
    // they would be rounded, and the document would differ from its history.
    if (m_joints && m_bodies->isObsolete()) m_joints->undo();
    updateObsolete();
    return true;
}

void MoveBodies::updateObsolete() {
    setObsolete(m_bodies->isObsolete());  // the joints only follow the bodies
}

QUndoCommand* changeBodiesCommand(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
                                  std::vector<simcore::SceneBody> after, bool mergeable) {
    if (isPlacementField(field))
        return new MoveBodies(document, text, field, std::move(indices), std::move(after), mergeable);
    return new ChangeBodies(document, text, field, std::move(indices), std::move(after), mergeable);
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

// ---- ChangeCameraBookmarks ----------------------------------------------------------------------

ChangeCameraBookmarks::ChangeCameraBookmarks(SceneDocument* document, const QString& text,
                                             std::vector<simcore::CameraBookmark> after)
    : QUndoCommand(text), m_document(document), m_before(document->scene().editor.cameraBookmarks),
      m_after(std::move(after)) {
    setObsolete(m_before == m_after);
}

void ChangeCameraBookmarks::redo() {
    m_document->setCameraBookmarks(m_after);
}

void ChangeCameraBookmarks::undo() {
    m_document->setCameraBookmarks(m_before);
}

}  // namespace interplay
