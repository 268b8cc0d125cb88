#pragma once
// The scene's edit actions: Add (one per shape), Add Joint (one per type, enabled by the
// selection, with a tip saying what it lacks), Copy, Cut, Paste (through the system clipboard, as
// scene file text: scene_clipboard.h), Duplicate (Ctrl+D), Delete, Select All (the platform's
// standard keys), Select None (Ctrl+Shift+A: Alt+A opens the Add menu) and Invert Selection (Ctrl+I). Each is a QAction (QtGui), and each edit one undo command on the
// document's stack. The window puts them in its menus and toolbars; tests trigger them without one.

#include "simcore/io/scene.h"

#include <QList>
#include <QObject>

#include <functional>
#include <optional>

class QAction;
class QKeySequence;

namespace interplay {

class SceneDocument;

// An action owned by `owner`, named so that MainWindow::action() and tests find it.
QAction* createAction(QObject* owner, const QString& objectName, const QString& text, const QKeySequence& shortcut,
                      const QString& statusTip);

class SceneActions : public QObject {
    Q_OBJECT

public:
    // Where a new body of the given half height goes (the window asks its viewport for the point
    // the camera looks at); without one, bodies are added with their base at the origin.
    using Placement = std::function<simcore::Vec3(float bodyHalfHeight)>;

    // Where pasted bodies go: the point on the surface under the cursor while it is over the view
    // (the window asks its viewport), else nothing, and they go beside the bodies they copy.
    using PastePoint = std::function<std::optional<simcore::Vec3>()>;

    explicit SceneActions(SceneDocument* document, QObject* parent = nullptr);

    void setPlacement(Placement placement) { m_placement = std::move(placement); }
    void setPastePoint(PastePoint pastePoint) { m_pastePoint = std::move(pastePoint); }

    // Object names "addSphere", "addBox", "addCapsule", "addCylinder", "addHull".
    QAction* addBodyAction(simcore::ShapeType type) const;
    // Object names "addBallJoint", "addHingeJoint", ..., in menu order.
    const QList<QAction*>& addJointActions() const { return m_addJoint; }
    QAction* duplicateAction() const { return m_duplicate; }
    QAction* deleteAction() const { return m_delete; }
    QAction* selectAllAction() const { return m_selectAll; }
    QAction* selectNoneAction() const { return m_selectNone; }
    QAction* invertSelectionAction() const { return m_invertSelection; }
    QAction* copyAction() const { return m_copy; }
    QAction* cutAction() const { return m_cut; }
    QAction* pasteAction() const { return m_paste; }

    void addBody(simcore::ShapeType type);
    void addJoint(simcore::JointType type);
    // Copies the selected bodies, with the joints among them, beside them ("Box 3" becomes the
    // next free "Box N"); one undo entry.
    void duplicateSelection();
    // The selected bodies with their joints, and the selected joints, in one undo entry.
    void deleteSelection();
    // The selected bodies and the joints among them onto the system clipboard.
    void copySelection();
    // Copy, then Delete of the selected bodies (with all their joints), as one undo entry "Cut ...".
    void cutSelection();
    // Adds the clipboard's bodies and joints (renamed where their names are taken) at the paste
    // point, else beside where they were copied from; one undo entry, and they become the
    // selection. The fragment's settings are not applied: a paste adds bodies and joints only.
    // Text that is no scene changes nothing and is rejected with the loader's reason.
    void paste();
    void selectAll();
    void selectNone();
    // Selects the bodies not selected; the selected joints stay.
    void invertSelection();

signals:
    // An edit that was not made, and why (for a status bar).
    void rejected(const QString& message);

private:
    void updateJointActions();  // Add Joint fits a selection of one or two bodies

    SceneDocument* m_document;
    Placement m_placement;
    PastePoint m_pastePoint;
    QList<QAction*> m_addBody;  // by ShapeType
    QList<QAction*> m_addJoint;
    QAction* m_duplicate = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_selectAll = nullptr;
    QAction* m_selectNone = nullptr;
    QAction* m_invertSelection = nullptr;
    QAction* m_copy = nullptr;
    QAction* m_cut = nullptr;
    QAction* m_paste = nullptr;
};

}  // namespace interplay
