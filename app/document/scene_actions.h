#pragma once
// The scene's edit actions: Add (one per shape), Add Joint (one per type, enabled by the
// selection, with a tip saying what it lacks), Duplicate (Ctrl+D), Delete and Select All (the
// platform's standard keys). Each is a QAction (QtGui), and each edit one undo command on the
// document's stack. The window puts them in its menus and toolbars; tests trigger them without one.

#include "simcore/io/scene.h"

#include <QList>
#include <QObject>

#include <functional>

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

    explicit SceneActions(SceneDocument* document, QObject* parent = nullptr);

    void setPlacement(Placement placement) { m_placement = std::move(placement); }

    // Object names "addSphere", "addBox", "addCapsule", "addCylinder", "addHull".
    QAction* addBodyAction(simcore::ShapeType type) const;
    // Object names "addBallJoint", "addHingeJoint", ..., in menu order.
    const QList<QAction*>& addJointActions() const { return m_addJoint; }
    QAction* duplicateAction() const { return m_duplicate; }
    QAction* deleteAction() const { return m_delete; }
    QAction* selectAllAction() const { return m_selectAll; }

    void addBody(simcore::ShapeType type);
    void addJoint(simcore::JointType type);
    // Copies the selected bodies beside them ("Box 3" becomes the next free "Box N").
    void duplicateSelection();
    // The selected bodies with their joints, and the selected joints, in one undo entry.
    void deleteSelection();
    void selectAll();

signals:
    // An edit that was not made, and why (for a status bar).
    void rejected(const QString& message);

private:
    void updateJointActions();  // Add Joint fits a selection of one or two bodies

    SceneDocument* m_document;
    Placement m_placement;
    QList<QAction*> m_addBody;  // by ShapeType
    QList<QAction*> m_addJoint;
    QAction* m_duplicate = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_selectAll = nullptr;
};

}  // namespace interplay
