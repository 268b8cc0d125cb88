#include "app/main_window.h"

#include "app/document/scene_document.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

namespace interplay {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new SceneDocument(this)),
      m_simulation(new SimulationController(this)),
      m_viewport(new Viewport(this)) {
    setCentralWidget(m_viewport);
    m_viewport->setSimulation(m_simulation);

    createActions();
    createMenusAndToolBar();
    createStatusBar();

    connect(m_document, &SceneDocument::sceneReplaced, this, &MainWindow::documentSceneReplaced);
    connect(m_document, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_simulation, &SimulationController::stepped, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::worldRebuilt, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::simulationError, this, &MainWindow::showSimulationError);

    resize(1280, 800);
    updateTitle();
    updateStatus();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions() {
    m_openAction = new QAction(QIcon::fromTheme(QStringLiteral("document-open")), tr("&Open…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a scene file (Interplay or thesis format)"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openWithDialog);

    m_quitAction = new QAction(QIcon::fromTheme(QStringLiteral("application-exit")), tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_playAction = new QAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("&Play"), this);
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(Qt::Key_Space);
    m_playAction->setStatusTip(tr("Run or pause the simulation (Space)"));
    connect(m_playAction, &QAction::toggled, m_simulation, &SimulationController::setPlaying);
    connect(m_simulation, &SimulationController::playingChanged, this, [this](bool playing) {
        m_playAction->setChecked(playing);
        m_playAction->setText(playing ? tr("&Pause") : tr("&Play"));
        m_playAction->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });

    m_stepAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("&Step"), this);
    m_stepAction->setShortcut(Qt::Key_Period);
    m_stepAction->setStatusTip(tr("Advance one time step and pause (.)"));
    connect(m_stepAction, &QAction::triggered, m_simulation, &SimulationController::stepOnce);

    m_resetAction = new QAction(style()->standardIcon(QStyle::SP_MediaSkipBackward), tr("&Reset"), this);
    m_resetAction->setShortcut(Qt::CTRL | Qt::Key_R);
    m_resetAction->setStatusTip(tr("Return to the authored scene (Ctrl+R)"));
    connect(m_resetAction, &QAction::triggered, m_simulation, &SimulationController::reset);
}

void MainWindow::createMenusAndToolBar() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->addAction(m_openAction);
    fileMenu->addSeparator();
    fileMenu->addAction(m_quitAction);

    QMenu* simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    simulationMenu->addAction(m_playAction);
    simulationMenu->addAction(m_stepAction);
    simulationMenu->addAction(m_resetAction);

    QToolBar* toolBar = addToolBar(tr("Simulation"));
    toolBar->setObjectName(QStringLiteral("simulationToolBar"));  // for saveState/restoreState
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolBar->addAction(m_playAction);
    toolBar->addAction(m_stepAction);
    toolBar->addAction(m_resetAction);
}

void MainWindow::createStatusBar() {
    m_timeLabel = new QLabel(this);
    m_costLabel = new QLabel(this);
    m_bodiesLabel = new QLabel(this);
    // Fixed digits keep the labels from jittering while running.
    for (QLabel* label : {m_timeLabel, m_costLabel, m_bodiesLabel}) {
        label->setFont(QFont(QStringLiteral("monospace")));
        label->setContentsMargins(8, 0, 8, 0);
        statusBar()->addPermanentWidget(label);
    }
}

bool MainWindow::openFile(const QString& path, QString* error) {
    return m_document->load(path, error);
}

void MainWindow::openDefaultScene() {
    m_document->newDefault();
}

void MainWindow::openWithDialog() {
    const QString startDir = m_document->filePath().isEmpty() ? QString() : QFileInfo(m_document->filePath()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), startDir,
                                                      tr("Scenes (*.json);;All files (*)"));
    if (path.isEmpty()) return;
    QString error;
    if (!openFile(path, &error)) {
        // Headline in the text, the loader's diagnostics (file, JSON path, reason) below it.
        QMessageBox box(QMessageBox::Warning, tr("Open Scene"),
                        tr("The scene \"%1\" could not be opened.").arg(QFileInfo(path).fileName()), QMessageBox::Ok,
                        this);
        box.setInformativeText(error);
        box.exec();
    }
}

void MainWindow::documentSceneReplaced() {
    QString error;
    if (!m_simulation->setScene(m_document->scene(), &error)) {
        QMessageBox::warning(this, tr("Scene"), tr("The scene cannot be simulated: %1").arg(error));
        return;
    }
    m_viewport->frameScene();
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("[*]%1 — Interplay").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::updateStatus() {
    const simcore::World* world = m_simulation->world();
    if (!world) {
        m_timeLabel->setText(tr("t = –"));
        m_costLabel->setText(QString());
        m_bodiesLabel->setText(tr("no scene"));
        return;
    }
    m_timeLabel->setText(tr("t = %1 s").arg(world->simulatedTime(), 0, 'f', 2));
    m_costLabel->setText(tr("%1 ms/step").arg(world->lastStepProfile().totalMs, 0, 'f', 3));
    const auto count = static_cast<int>(world->bodyCount());
    m_bodiesLabel->setText(count == 1 ? tr("1 body") : tr("%1 bodies").arg(count));
}

void MainWindow::showSimulationError(const QString& message) {
    statusBar()->showMessage(message, 10000);
    QMessageBox::warning(this, tr("Simulation"), message);
}

}  // namespace interplay
