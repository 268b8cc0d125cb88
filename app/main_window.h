#pragma once
// The editor's main window: wires the document, the simulation controller and the viewport
// together and hosts the menus, toolbar and status bar. Panels (docks) plug in here later; each
// talks to the document and controller, not to the other panels.

#include <QMainWindow>
#include <QString>

class QAction;
class QLabel;

namespace interplay {

class SceneDocument;
class SimulationController;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    SimulationController* simulation() const { return m_simulation; }
    Viewport* viewport() const { return m_viewport; }

    // Loads a scene file into the document; on failure the document is unchanged and *error says
    // why (the caller decides how to show it).
    bool openFile(const QString& path, QString* error = nullptr);
    void openDefaultScene();

private slots:
    void openWithDialog();
    void updateTitle();
    void updateStatus();
    void showSimulationError(const QString& message);

private:
    void createActions();
    void createMenusAndToolBar();
    void createStatusBar();
    void documentSceneReplaced();

    SceneDocument* m_document = nullptr;
    SimulationController* m_simulation = nullptr;
    Viewport* m_viewport = nullptr;

    QAction* m_openAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_resetAction = nullptr;

    QLabel* m_timeLabel = nullptr;
    QLabel* m_costLabel = nullptr;
    QLabel* m_bodiesLabel = nullptr;
};

}  // namespace interplay
