#pragma once
// Every edit of a SceneDocument is one of these commands, pushed on the document's undo stack.
// ChangeBodies is the one generic property command (after Tiled's ChangeValue): it swaps whole
// SceneBody values, so any field or combination of fields of any set of bodies is one command,
// and continuous edits of the same field of the same bodies merge into one history entry.

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
};

// "Box 3" for one body, "3 Bodies" for several: the object part of a command's name.
QString bodiesLabel(const SceneDocument& document, const QList<int>& indices);

// Whether two authored bodies are identical in every field (a change to them is a no-op).
bool sameSceneBody(const simcore::SceneBody& a, const simcore::SceneBody& b);

// Adds bodies at the given ascending indices (each index as it is after the insertion). Used by
// Add, Duplicate and Paste-like edits; the new bodies become the selection.
class AddBodies : public QUndoCommand {
public:
    AddBodies(SceneDocument* document, const QString& text, QList<int> indices, std::vector<simcore::SceneBody> bodies);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    QList<int> m_indices;
    std::vector<simcore::SceneBody> m_bodies;
};

// Removes bodies (any order of indices) and the joints attached to them; undo puts both back
// where they were.
class RemoveBodies : public QUndoCommand {
public:
    RemoveBodies(SceneDocument* document, QList<int> indices);
    void redo() override;
    void undo() override;

private:
    SceneDocument* m_document;
    QList<int> m_indices;                     // ascending
    std::vector<simcore::SceneBody> m_bodies; // filled by redo, in m_indices order
    std::vector<std::pair<int, simcore::SceneJoint>> m_joints;  // (index, joint), ascending; by redo
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

// Replaces the given bodies with new values of one field (`after[i]` for `indices[i]`). A command
// created with `mergeable` continues the previous one when it edits the same field of the same
// bodies (a drag, a slider): the history keeps one entry holding the first "before" and the last
// "after". A change back to the starting values makes the entry obsolete.
class ChangeBodies : public QUndoCommand {
public:
    ChangeBodies(SceneDocument* document, const QString& text, BodyField field, QList<int> indices,
                 std::vector<simcore::SceneBody> after, bool mergeable = false);
    int id() const override { return static_cast<int>(CommandId::ChangeBodies); }
    bool mergeWith(const QUndoCommand* other) override;
    void redo() override;
    void undo() override;

private:
    void apply(const std::vector<simcore::SceneBody>& values);
    void updateObsolete();

    SceneDocument* m_document;
    BodyField m_field;
    QList<int> m_indices;
    std::vector<simcore::SceneBody> m_before;
    std::vector<simcore::SceneBody> m_after;
    bool m_mergeable;
};

// Replaces the world settings. Like ChangeBodies, a mergeable command continues the previous one
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

}  // namespace interplay
