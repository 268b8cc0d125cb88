#pragma once
// The editor's main window: wires the document, the simulation controller, the viewport and the
// dock panels together and hosts the menus, toolbars and status bar. Panels talk to the document
// and the controller, never to each other. File handling is the DocumentManager's and the scene's
// edit actions are SceneActions' (both in the model layer); the window answers the manager's
// prompts with dialogs, which tests replace so that nothing waits on a modal dialog.

#include <QMainWindow>
#include <QString>

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QTreeView;

namespace interplay {

class AccuracyPanel;
class CameraBookmarks;
class DebugDrawOptions;
class DocumentManager;
class InspectorPanel;
class LiveStatePanel;
class ProfilerPanel;
class SceneActions;
class SceneDocument;
class SceneTreeModel;
class SimulationController;
class SimulationSettingsModel;
class SimulationSettingsPanel;
class TimelineBar;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    DocumentManager* documentManager() const { return m_files; }
    SceneActions* sceneActions() const { return m_sceneActions; }
    SimulationController* simulation() const { return m_simulation; }
    Viewport* viewport() const { return m_viewport; }
    SceneTreeModel* sceneTreeModel() const { return m_sceneTreeModel; }
    QTreeView* sceneTree() const { return m_sceneTree; }
    InspectorPanel* inspector() const { return m_inspector; }
    SimulationSettingsPanel* settingsPanel() const { return m_settingsPanel; }
    ProfilerPanel* profiler() const { return m_profiler; }
    LiveStatePanel* liveState() const { return m_liveState; }
    TimelineBar* timelineBar() const { return m_timelineBar; }
    AccuracyPanel* accuracyPanel() const { return m_accuracy; }
    DebugDrawOptions* debugDrawOptions() const { return m_debugDraw; }
    CameraBookmarks* cameraBookmarks() const { return m_bookmarks; }
    QAction* action(const QString& objectName) const;  // e.g. "play", "save", "addBox"
    // The built-in scene, as at start-up without a file.
    void openDefaultScene();

    // The default arrangement: every dock shown, sized to leave the viewport most of the window
    // (the first start's layout, and the one --window-screenshot uses).
    void arrangeDefaultLayout();

protected:
    // Undo and Redo reach the document unless a text field has typing of its own to undo; Space
    // plays unless the focus is in a text field or drop-down.
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private slots:
    void updateTitle();
    void updateStatus();
    void showSimulationError(const QString& message);

private:
    void createActions();
    void createMenusAndToolBars();
    void createHelpMenu();
    void createDocks();
    void createStatusBar();
    QDockWidget* addDock(const QString& objectName, const QString& title, QWidget* widget, Qt::DockWidgetArea area);

    // A new scene (new, opened, reverted, recovered): the world is rebuilt from it and framed.
    void documentSceneReplaced();
    void syncTreeSelection();
    void applySimulatedPose();
    void throwBody();
    void rebuildRecentMenu();
    void rebuildExamplesMenu();
    void restoreLayout();
    void saveLayout();

    SceneDocument* m_document = nullptr;
    DocumentManager* m_files = nullptr;
    SceneActions* m_sceneActions = nullptr;
    SimulationController* m_simulation = nullptr;
    Viewport* m_viewport = nullptr;
    DebugDrawOptions* m_debugDraw = nullptr;
    SimulationSettingsModel* m_settingsModel = nullptr;
    SceneTreeModel* m_sceneTreeModel = nullptr;
    QTreeView* m_sceneTree = nullptr;
    InspectorPanel* m_inspector = nullptr;
    SimulationSettingsPanel* m_settingsPanel = nullptr;
    ProfilerPanel* m_profiler = nullptr;
    LiveStatePanel* m_liveState = nullptr;
    TimelineBar* m_timelineBar = nullptr;
    AccuracyPanel* m_accuracy = nullptr;
    CameraBookmarks* m_bookmarks = nullptr;

    QMenu* m_viewMenu = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_examplesMenu = nullptr;
    QActionGroup* m_throwShapes = nullptr;
    QAction* m_playAction = nullptr;

    QLabel* m_timeLabel = nullptr;
    QLabel* m_rateLabel = nullptr;  // while playing: the real-time factor
    QLabel* m_costLabel = nullptr;
    QLabel* m_bodiesLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;

    bool m_syncingSelection = false;
};

}  // namespace interplay
