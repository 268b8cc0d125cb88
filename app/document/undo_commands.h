#pragma once
// Every edit of a SceneDocument is one of these commands, pushed on the document's undo stack.
// ChangeObjects is the one generic property command (after Tiled's ChangeValue): it swaps whole
// SceneBody (ChangeBodies) or SceneJoint (ChangeJoints) values, so any field or combination of
// fields of any set of bodies or joints is one command, and continuous edits of the same field of
// the same objects merge into one history entry.

#include "app/document/scene_document.h"

#include "simcore/io/scene.h"

#include <QList>
#include <QUndoCommand>

#include <vector>

namespace interplay {

// QUndoCommand::id() values: commands with the same id may merge.
enum class CommandId : int {
    ChangeBodies = 1,
    ChangeSettings,
    ChangeJoints,
    MoveBodies,
};

// "Box 3" for one body, "3 Bodies" for several: the object part of a command's name.
QString bodiesLabel(const SceneDocument& document, const QList<int>& indices);
// "Joint 2" for one joint, "3 Joints" for several.
QString jointsLabel(const SceneDocument& document, const QList<int>& indices);

// Whether two authored bodies (joints) are identical in every field (a change to them is a no-op).
bool sameSceneBody(const simcore::SceneBody& a, const simcore::SceneBody& b);
bool sameSceneJoint(const simcore::SceneJoint& a, const simcore::SceneJoint& b);

// Adds bodies at the given ascending indices (each index as it is after the insertion). Used by
// Add, Duplicate and Paste-like edits; the new bodies become the selection.
class AddBodies : public QUndoCommand {
public:
    AddBodies(SceneDocument* document, const QString& text, QList<int> indices, std::vector<simcore::SceneBody> bodies,
              QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    QList<int> m_indices;
    std::vector<simcore::SceneBody> m_bodies;
};

// Removes bodies (any order of indices), the joints attached to them and the given `joints`
// (Delete on a selection of bodies, joints or both) as one step; undo puts all of them back where
// they were and selects them again.
class RemoveBodies : public QUndoCommand {
public:
    RemoveBodies(SceneDocument* document, QList<int> indices, QList<int> joints = {});
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    QList<int> m_indices;                     // ascending
    QList<int> m_selectedJoints;              // ascending: the joints named, not those attached
    std::vector<simcore::SceneBody> m_bodies; // filled by redo, in m_indices order
    std::vector<std::pair<int, simcore::SceneJoint>> m_joints;  // (index, joint), ascending; by redo
};

// Adds one joint at `index` ("Add Hinge Joint"); it becomes the selection.
class AddJoint : public QUndoCommand {
public:
    AddJoint(SceneDocument* document, const QString& text, int index, simcore::SceneJoint joint,
             QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    int m_index;
    simcore::SceneJoint m_joint;
};

// Adds a scene fragment's bodies after the document's and its joints after the document's joints
// (Paste, Duplicate): one AddBodies and one AddJoint per joint as children, so one history entry;
// the added bodies become the selection.
class AddFragment : public QUndoCommand {
public:
    AddFragment(SceneDocument* document, const QString& text, simcore::Scene fragment);
    void redo() override;

private:
    SceneDocument* m_document;
    QList<int> m_bodyIndices;
};

// Moves one body in the scene's order (drag to reorder in the scene tree).
class ReorderBody : public QUndoCommand {
public:
    ReorderBody(SceneDocument* document, int from, int to);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    int m_from, m_to;
};

// How ChangeObjects reads, writes and compares one kind of object of the document.
template <typename Object>
struct ObjectAccess;

template <>
struct ObjectAccess<simcore::SceneBody> {
    using Field = BodyField;
    static constexpr CommandId kCommandId = CommandId::ChangeBodies;
    static const simcore::SceneBody& get(const SceneDocument& document, int index) { return document.body(index); }
    static void set(SceneDocument& document, int index, const simcore::SceneBody& body, BodyField field) {
        document.setBody(index, body, field);
    }
    static bool same(const simcore::SceneBody& a, const simcore::SceneBody& b) { return sameSceneBody(a, b); }
};

template <>
struct ObjectAccess<simcore::SceneJoint> {
    using Field = JointField;
    static constexpr CommandId kCommandId = CommandId::ChangeJoints;
    static const simcore::SceneJoint& get(const SceneDocument& document, int index) { return document.joint(index); }
    static void set(SceneDocument& document, int index, const simcore::SceneJoint& joint, JointField field) {
        document.setJoint(index, joint, field);
    }
    static bool same(const simcore::SceneJoint& a, const simcore::SceneJoint& b) { return sameSceneJoint(a, b); }
};

// Replaces the given objects with new values of one field (`after[i]` for `indices[i]`). A command
// created with `mergeable` continues the previous one when it edits the same field of the same
// objects (a drag, a slider): the history keeps one entry holding the first "before" and the last
// "after". A change back to the starting values makes the entry obsolete.
template <typename Object>
class ChangeObjects : public QUndoCommand {
public:
    using Field = typename ObjectAccess<Object>::Field;

    ChangeObjects(SceneDocument* document, const QString& text, Field field, QList<int> indices, std::vector<Object> after,
                  bool mergeable = false, QUndoCommand* parent = nullptr);
    int id() const override { return static_cast<int>(ObjectAccess<Object>::kCommandId); }
    bool mergeWith(const QUndoCommand* other) override;
    void redo() override;
    void undo() override;

private:
    void apply(const std::vector<Object>& values);
    void updateObsolete();

    SceneDocument* m_document;
    Field m_field;
    QList<int> m_indices;
    std::vector<Object> m_before;
    std::vector<Object> m_after;
    bool m_mergeable;
};

using ChangeBodies = ChangeObjects<simcore::SceneBody>;
using ChangeJoints = ChangeObjects<simcore::SceneJoint>;
extern template class ChangeObjects<simcore::SceneBody>;
extern template class ChangeObjects<simcore::SceneJoint>;

// Moves or turns bodies (a drag, the Inspector's position and rotation, Apply Simulated Pose) with
// the joints that ride on them (jointsCarriedWith), as one command: a ChangeBodies of `field`
// (isPlacementField) and a ChangeJoints of their Placement. Merges like ChangeObjects,
// so a drag is one history entry with its joints.
class MoveBodies : public QUndoCommand {
public:
    MoveBodies(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
               std::vector<simcore::SceneBody> after, bool mergeable = false);
    int id() const override { return static_cast<int>(CommandId::MoveBodies); }
    bool mergeWith(const QUndoCommand* other) override;

private:
    void updateObsolete();

    BodyField m_field;
    QList<int> m_indices;
    QList<int> m_jointIndices;
    bool m_mergeable;
    ChangeBodies* m_bodies;             // child
    ChangeJoints* m_joints = nullptr;   // child, when joints ride on the bodies
};

// The command for an edit of `field` of bodies: a MoveBodies for their pose (so joints follow),
// else a ChangeBodies.
QUndoCommand* changeBodiesCommand(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
                                  std::vector<simcore::SceneBody> after, bool mergeable = false);

// Replaces the world settings. Like ChangeObjects, a mergeable command continues the previous one
// when it has the same `key` (the settings field a control edits, e.g. "gravity").
class ChangeSettings : public QUndoCommand {
public:
    ChangeSettings(SceneDocument* document, const QString& text, QString key, const simcore::WorldSettings& after,
                   bool mergeable = false);
    int id() const override { return static_cast<int>(CommandId::ChangeSettings); }
    bool mergeWith(const QUndoCommand* other) override;
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    QString m_key;
    simcore::WorldSettings m_before;
    simcore::WorldSettings m_after;
    bool m_mergeable;
};

// Replaces the scene's camera bookmarks (added, renamed, deleted or re-aimed): an edit of the
// document like any other, though the world never sees it.
class ChangeCameraBookmarks : public QUndoCommand {
public:
    ChangeCameraBookmarks(SceneDocument* document, const QString& text, std::vector<simcore::CameraBookmark> after);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    std::vector<simcore::CameraBookmark> m_before;
    std::vector<simcore::CameraBookmark> m_after;
};

}  // namespace interplay
