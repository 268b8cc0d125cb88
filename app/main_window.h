#pragma once
// The editor's main window: wires the document, the simulation controller, the viewport and the
// dock panels together and hosts the menus, toolbars and status bar. Panels talk to the document
// and the controller, never to each other. Questions to the user (unsaved changes, reload,
// recovery, errors, file choice) go through replaceable Prompts, so tests answer them without a
// modal dialog.

#include <QMainWindow>
#include <QString>
#include <QStringList>

#include <functional>

class QAction;
class QActionGroup;
class QDockWidget;
class QFileSystemWatcher;
class QLabel;
class QMenu;
class QTimer;
class QTreeView;

namespace interplay {

class DebugDrawOptions;
class InspectorPanel;
class ProfilerPanel;
class SceneDocument;
class SceneTreeModel;
class SimulationController;
class SimulationSettingsModel;
class SimulationSettingsPanel;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    enum class UnsavedChoice { Save, Discard, Cancel };
    enum class FileChoice { Open, Save };
    struct Prompts {
        // "Save changes to NAME?" before they would be lost.
        std::function<UnsavedChoice(const QString& documentName)> unsavedChanges;
        // A yes/no question (reload a file changed on disk, recover an autosave).
        std::function<bool(const QString& title, const QString& question)> confirm;
        // Something failed: a headline and the details (file, JSON path, reason).
        std::function<void(const QString& title, const QString& text, const QString& details)> error;
        // A file to open or save as; empty when cancelled.
        std::function<QString(FileChoice choice, const QString& title, const QString& directory)> chooseFile;
    };

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    SimulationController* simulation() const { return m_simulation; }
    Viewport* viewport() const { return m_viewport; }
    SceneTreeModel* sceneTreeModel() const { return m_sceneTreeModel; }
    QTreeView* sceneTree() const { return m_sceneTree; }
    InspectorPanel* inspector() const { return m_inspector; }
    SimulationSettingsPanel* settingsPanel() const { return m_settingsPanel; }
    ProfilerPanel* profiler() const { return m_profiler; }
    DebugDrawOptions* debugDrawOptions() const { return m_debugDraw; }
    QAction* action(const QString& objectName) const;  // e.g. "play", "save", "addBox"

    Prompts& prompts() { return m_prompts; }

    // Loads a scene file into the document without asking anything; on failure the document is
    // unchanged and *error says why (the caller decides how to show it).
    bool openFile(const QString& path, QString* error = nullptr);
    void openDefaultScene();

    // The interactive file commands, as the menus run them: they ask before losing changes and
    // report failures through the prompts. Each returns whether it went through.
    bool newScene();
    bool open(const QString& path);
    bool save();
    bool saveAs();
    bool revert();
    // Asks to save unsaved changes; false when the user cancels (the caller must not go on).
    bool maybeSave();

    QStringList recentFiles() const;
    void clearRecentFiles();
    static constexpr int kMaxRecentFiles = 10;
    // Where the example scenes are (the repository's scenes/ folder, or one beside the program).
    static QString examplesDirectory();

    // Crash recovery: the unsaved document is written to recoveryFilePath() every interval.
    static QString recoveryFilePath();
    void setAutosaveInterval(int milliseconds);
    void autosaveNow();
    // At start-up: if an earlier session left a recovery file, offers to restore it. Returns
    // whether a scene was recovered.
    bool offerRecovery();

    // The default arrangement: every dock shown, sized to leave the viewport most of the window
    // (the first start's layout, and the one --window-screenshot uses).
    void arrangeDefaultLayout();

protected:
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
    void createDocks();
    void createStatusBar();
    QAction* makeAction(const QString& objectName, const QString& text, const QKeySequence& shortcut,
                        const QString& statusTip);
    QDockWidget* addDock(const QString& objectName, const QString& title, QWidget* widget, Qt::DockWidgetArea area);

    // Brings the running world up to date with an edit of the document, in place (`edit` returns
    // false with the engine's reason when it cannot), or else by rebuilding it from the document.
    void documentSceneReplaced();
    void syncTreeSelection();
    void addBody(int shapeType);
    void addJoint(int jointType);
    void updateJointActions();  // Add Joint fits a selection of one or two bodies
    void deleteSelection();
    void duplicateSelection();
    void applySimulatedPose();
    void throwBody();
    void importThesisScene();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void rebuildExamplesMenu();
    void watchDocumentFile();
    void documentFileChanged(const QString& path);
    void removeRecoveryFile();
    void restoreLayout();
    void saveLayout();

    SceneDocument* m_document = nullptr;
    SimulationController* m_simulation = nullptr;
    Viewport* m_viewport = nullptr;
    DebugDrawOptions* m_debugDraw = nullptr;
    SimulationSettingsModel* m_settingsModel = nullptr;
    SceneTreeModel* m_sceneTreeModel = nullptr;
    QTreeView* m_sceneTree = nullptr;
    InspectorPanel* m_inspector = nullptr;
    SimulationSettingsPanel* m_settingsPanel = nullptr;
    ProfilerPanel* m_profiler = nullptr;

    QMenu* m_viewMenu = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_examplesMenu = nullptr;
    QActionGroup* m_throwShapes = nullptr;
    QAction* m_playAction = nullptr;

    QLabel* m_timeLabel = nullptr;
    QLabel* m_costLabel = nullptr;
    QLabel* m_bodiesLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;

    Prompts m_prompts;
    QTimer* m_autosaveTimer = nullptr;
    QFileSystemWatcher* m_watcher = nullptr;
    QString m_expectedFileStamp;  // size and time of the file as we last read or wrote it
    bool m_syncingSelection = false;
};

}  // namespace interplay
