// The menu bar and the tool bars: where each of MainWindow's actions (main_window.cpp) is offered.
#include "app/main_window.h"

#include "app/document/scene_actions.h"
#include "app/viewport/camera_bookmarks.h"

#include <QActionGroup>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QToolBar>
#include <QToolButton>

namespace interplay {

void MainWindow::createMenusAndToolBars() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(action(QStringLiteral("new")));
    file->addAction(action(QStringLiteral("open")));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
    m_examplesMenu = file->addMenu(tr("E&xamples"));
    m_examplesMenu->setObjectName(QStringLiteral("examplesMenu"));
    rebuildExamplesMenu();
    file->addAction(action(QStringLiteral("import")));
    file->addAction(action(QStringLiteral("importGeometry")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("save")));
    file->addAction(action(QStringLiteral("saveAs")));
    file->addAction(action(QStringLiteral("revert")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("quit")));
    rebuildRecentMenu();

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(action(QStringLiteral("undo")));
    edit->addAction(action(QStringLiteral("redo")));
    edit->addSeparator();
    edit->addAction(m_sceneActions->cutAction());
    edit->addAction(m_sceneActions->copyAction());
    edit->addAction(m_sceneActions->pasteAction());
    edit->addAction(m_sceneActions->duplicateAction());
    edit->addAction(m_sceneActions->deleteAction());
    edit->addSeparator();
    edit->addAction(m_sceneActions->selectAllAction());
    edit->addAction(m_sceneActions->selectNoneAction());
    edit->addAction(m_sceneActions->invertSelectionAction());
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("applyPose")));
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("preferences")));

    // Menu order: the box first (the actions themselves are in ShapeType order).
    using simcore::ShapeType;
    const ShapeType addOrder[] = {ShapeType::Box, ShapeType::Sphere, ShapeType::Capsule, ShapeType::Cylinder,
                                  ShapeType::ConvexHull};
    QMenu* add = menuBar()->addMenu(tr("&Add"));
    for (ShapeType type : addOrder) add->addAction(m_sceneActions->addBodyAction(type));
    add->addSeparator();
    QMenu* joints = add->addMenu(tr("Add &Joint"));
    joints->setObjectName(QStringLiteral("addJointMenu"));
    joints->setToolTipsVisible(true);  // a disabled entry says what selection it needs
    joints->addActions(m_sceneActions->addJointActions());

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    simulation->addAction(m_playAction);
    simulation->addAction(action(QStringLiteral("stepBack")));
    simulation->addAction(action(QStringLiteral("step")));
    simulation->addAction(action(QStringLiteral("reset")));
    simulation->addSeparator();
    simulation->addAction(action(QStringLiteral("exploreAccuracy")));
    simulation->addSeparator();
    simulation->addAction(action(QStringLiteral("throw")));
    QMenu* throwShape = simulation->addMenu(tr("Throw S&hape"));
    throwShape->addActions(m_throwShapes->actions());

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(action(QStringLiteral("frameSelection")));
    m_viewMenu->addAction(action(QStringLiteral("frameAll")));
    m_viewMenu->addSeparator();
    for (const char* name : {"viewFront", "viewBack", "viewRight", "viewLeft", "viewTop", "viewBottom", "orthographic"}) {
        m_viewMenu->addAction(action(QString::fromLatin1(name)));
    }
    m_viewMenu->addMenu(m_bookmarks->menu());
    m_viewMenu->addSeparator();
    const char* gizmoActions[] = {"gizmoMove", "gizmoRotate", "gizmoLocal", "gizmoSnap"};
    for (const char* name : gizmoActions) m_viewMenu->addAction(action(QString::fromLatin1(name)));
    m_viewMenu->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) m_viewMenu->addAction(dock->toggleViewAction());

    QToolBar* fileBar = addToolBar(tr("File"));
    fileBar->setObjectName(QStringLiteral("fileToolBar"));
    fileBar->addAction(action(QStringLiteral("new")));
    fileBar->addAction(action(QStringLiteral("open")));
    fileBar->addAction(action(QStringLiteral("save")));
    fileBar->addSeparator();
    fileBar->addAction(action(QStringLiteral("undo")));
    fileBar->addAction(action(QStringLiteral("redo")));

    QToolBar* simulationBar = addToolBar(tr("Simulation"));
    simulationBar->setObjectName(QStringLiteral("simulationToolBar"));
    simulationBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    simulationBar->addAction(m_playAction);
    simulationBar->addAction(action(QStringLiteral("stepBack")));
    simulationBar->addAction(action(QStringLiteral("step")));
    simulationBar->addAction(action(QStringLiteral("reset")));
    auto* throwButton = new QToolButton;
    throwButton->setDefaultAction(action(QStringLiteral("throw")));
    throwButton->setMenu(throwShape);
    throwButton->setPopupMode(QToolButton::MenuButtonPopup);
    simulationBar->addWidget(throwButton);

    QToolBar* addBar = addToolBar(tr("Add"));
    addBar->setObjectName(QStringLiteral("addToolBar"));
    addBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    // One word per button (the actions' icon texts) keeps every toolbar on one row at 1400 px.
    auto* addLabel = new QLabel(tr("Add:"));
    addLabel->setContentsMargins(6, 0, 2, 0);
    addBar->addWidget(addLabel);
    for (ShapeType type : addOrder) addBar->addAction(m_sceneActions->addBodyAction(type));
    auto* jointButton = new QToolButton;
    jointButton->setText(tr("Joint"));
    jointButton->setToolTip(tr("Add a joint between the selected bodies, or from one body to the world"));
    jointButton->setMenu(joints);
    jointButton->setPopupMode(QToolButton::InstantPopup);
    addBar->addWidget(jointButton);
    addBar->addSeparator();
    addBar->addAction(m_sceneActions->duplicateAction());
    addBar->addAction(m_sceneActions->deleteAction());

    // The View menu's gizmo actions, as buttons that show which are on.
    QToolBar* gizmoBar = addToolBar(tr("Gizmo"));
    gizmoBar->setObjectName(QStringLiteral("gizmoToolBar"));
    gizmoBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (const char* name : gizmoActions) gizmoBar->addAction(action(QString::fromLatin1(name)));
}

}  // namespace interplay
