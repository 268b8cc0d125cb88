#include "app/main_window.h"

#include "app/document/body_templates.h"
#include "app/document/document_manager.h"
#include "app/document/geometry_import.h"
#include "app/document/scene_actions.h"
#include "app/document/scene_document.h"
#include "app/document/scene_tree_model.h"
#include "app/help_dialog.h"
#include "app/panels/accuracy_panel.h"
#include "app/panels/import_geometry_dialog.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/live_state_panel.h"
#include "app/panels/preferences_dialog.h"
#include "app/panels/profiler_panel.h"
#include "app/panels/simulation_settings_model.h"
#include "app/panels/simulation_settings_panel.h"
#include "app/panels/timeline_bar.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/camera_bookmarks.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCursor>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QQuickItem>
#include <QQuickWidget>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>
#include <QVBoxLayout>

namespace interplay {
namespace {

constexpr float kThrowSpeed = 14.0f;  // m/s along the view
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");
const QString kSceneFilter = QStringLiteral("Scenes (*.json);;All files (*)");

// The manager's questions as the dialogs a desktop user expects.
DocumentManager::Prompts dialogPrompts(QWidget* parent) {
    DocumentManager::Prompts prompts;
    prompts.unsavedChanges = [parent](const QString& name) {
        const auto answer = QMessageBox::warning(
            parent, QCoreApplication::applicationName(), MainWindow::tr("Save changes to \"%1\"?").arg(name),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        if (answer == QMessageBox::Save) return DocumentManager::UnsavedChoice::Save;
        if (answer == QMessageBox::Discard) return DocumentManager::UnsavedChoice::Discard;
        return DocumentManager::UnsavedChoice::Cancel;
    };
    prompts.confirm = [parent](const QString& title, const QString& question) {
        return QMessageBox::question(parent, title, question, QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes) ==
               QMessageBox::Yes;
    };
    prompts.error = [parent](const QString& title, const QString& text, const QString& details) {
        // Headline in the text, the diagnostics (file, JSON path, reason) below it.
        QMessageBox box(QMessageBox::Warning, title, text, QMessageBox::Ok, parent);
        box.setInformativeText(details);
        box.exec();
    };
    prompts.chooseFile = [parent](DocumentManager::FileChoice choice, const QString& title, const QString& directory) {
        return choice == DocumentManager::FileChoice::Open
                   ? QFileDialog::getOpenFileName(parent, title, directory, kSceneFilter)
                   : QFileDialog::getSaveFileName(parent, title, directory, kSceneFilter);
    };
    return prompts;
}

// Whether a text field has typing of its own to undo (or redo): QLineEdit's, or Qt Quick's
// TextInput's canUndo. A field whose text is committed has none (showing a value resets it).
bool hasOwnTextHistory(const QObject* target, bool undo) {
    if (const auto* edit = qobject_cast<const QLineEdit*>(target)) {
        return undo ? edit->isUndoAvailable() : edit->isRedoAvailable();
    }
    const QVariant quick = target->property(undo ? "canUndo" : "canRedo");
    return quick.isValid() && quick.toBool();
}

// One window of its kind, raised again on later presses, that stays open while the user tries
// what it says or sets.
template <typename Dialog>
void showSingleDialog(QWidget* parent) {
    auto* dialog = parent->findChild<Dialog*>();
    if (!dialog) dialog = new Dialog(parent);
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

bool isDropDown(const QObject* target) {
    return qobject_cast<const QComboBox*>(target) || target->inherits("QQuickComboBox");
}

// Import Geometry's dialog for `path`; on OK the body is added as one undo entry, or a message
// says why it cannot be and nothing changes.
void importGeometry(QWidget* parent, SceneDocument* document, const QString& path) {
    auto* dialog = new ImportGeometryDialog(path, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QDialog::accepted, parent, [parent, document, dialog] {
        QString error;
        QUndoCommand* command =
            importGeometryCommand(document, dialog->path(), dialog->preview(), dialog->kind(), dialog->options(), &error);
        if (command) document->undoStack()->push(command);
        else QMessageBox::warning(parent, MainWindow::tr("Import Geometry"), error);
    });
    dialog->open();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new SceneDocument(this)),
      m_files(new DocumentManager(m_document, this)),
      m_sceneActions(new SceneActions(m_document, this)),
      m_simulation(new SimulationController(this)),
      m_viewport(new Viewport(this)),
      m_debugDraw(new DebugDrawOptions(this)),
      m_settingsModel(new SimulationSettingsModel(m_document, this)),
      m_sceneTreeModel(new SceneTreeModel(m_document, this)) {
    m_files->prompts() = dialogPrompts(this);
    m_sceneActions->setPlacement([this](float bodyHalfHeight) { return m_viewport->placementPoint(bodyHalfHeight); });
    // Paste puts bodies where the cursor points while it is over the view.
    m_sceneActions->setPastePoint([this]() -> std::optional<simcore::Vec3> {
        const QPoint pixel = m_viewport->mapFromGlobal(QCursor::pos());
        if (!m_viewport->rect().contains(pixel)) return std::nullopt;
        return m_viewport->surfacePointAt(pixel);
    });
    // The timeline bar sits under the viewport, as a video editor's does.
    auto* central = new QWidget;
    auto* centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->setSpacing(0);
    centralLayout->addWidget(m_viewport, 1);
    m_timelineBar = new TimelineBar(m_simulation);
    centralLayout->addWidget(m_timelineBar);
    setCentralWidget(central);
    m_viewport->setSimulation(m_simulation);
    m_viewport->setDocument(m_document);
    m_viewport->setDebugDrawOptions(m_debugDraw);
    setAcceptDrops(true);
    setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);

    createActions();
    createDocks();
    createMenusAndToolBars();
    createHelpMenu();
    createStatusBar();

    connect(m_document, &SceneDocument::sceneReplaced, this, &MainWindow::documentSceneReplaced);
    connect(m_document, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_files, &DocumentManager::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
    // Each change of the document reaches the running world as it happens, in place: a run paused
    // mid-way keeps its state, and a drag moves one body instead of rebuilding the world.
    m_simulation->followDocument(m_document);
    connect(m_simulation, &SimulationController::editFailed, this, &MainWindow::showSimulationError);
    connect(m_document, &SceneDocument::selectionChanged, this, &MainWindow::syncTreeSelection);
    const auto showRejection = [this](const QString& message) { statusBar()->showMessage(message, 8000); };
    connect(m_settingsModel, &SimulationSettingsModel::rejected, this, showRejection);
    connect(m_inspector, &InspectorPanel::rejected, this, showRejection);
    connect(m_sceneActions, &SceneActions::rejected, this, showRejection);
    connect(m_bookmarks, &CameraBookmarks::rejected, this, showRejection);
    connect(m_files, &DocumentManager::statusMessage, statusBar(), &QStatusBar::showMessage);
    // A long message (several load warnings, the speed bound) is cut at the permanent labels:
    // hovering the status bar shows all of it.
    connect(statusBar(), &QStatusBar::messageChanged, statusBar(), &QWidget::setToolTip);

    connect(m_simulation, &SimulationController::stepped, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::worldRebuilt, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::bodiesEdited, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::playingChanged, this, &MainWindow::updateStatus);
    connect(m_simulation, &SimulationController::simulationError, this, &MainWindow::showSimulationError);
    connect(m_simulation, &SimulationController::simulationWarning, this,
            [this](const QString& summary, const QString& details) {
                statusBar()->showMessage(summary, 15000);
                statusBar()->setToolTip(summary + QStringLiteral(".\n") + details);
            });

    // Text fields claim Ctrl+Z even with nothing of theirs to undo, and Space reaches the play
    // shortcut before a focused drop-down: the filter decides who gets these keys (eventFilter).
    qApp->installEventFilter(this);

    resize(1440, 900);
    restoreLayout();
    updateTitle();
    updateStatus();
}

MainWindow::~MainWindow() {
    qApp->removeEventFilter(this);  // it reads the panels destroyed below
    // The document is a child, destroyed after this destructor with its siblings: nothing it emits
    // on the way may reach the window or a listener half destroyed.
    m_document->disconnect();
    // The QML panel goes first: its bindings read the settings model and the controller, which
    // are children of this window and would otherwise be destroyed under it.
    delete m_settingsPanel;
}

// ---- Actions, menus, docks ----------------------------------------------------------------------

QAction* MainWindow::action(const QString& objectName) const {
    return findChild<QAction*>(objectName);
}

void MainWindow::openDefaultScene() { m_document->newDefault(); }

void MainWindow::createActions() {
    QStyle* s = style();
    // File.
    QAction* a = createAction(this, QStringLiteral("new"), tr("&New"), QKeySequence::New, tr("Start an empty scene"));
    a->setIcon(QIcon::fromTheme(QStringLiteral("document-new"), s->standardIcon(QStyle::SP_FileIcon)));
    connect(a, &QAction::triggered, m_files, &DocumentManager::newScene);
    a = createAction(this, QStringLiteral("open"), tr("&Open…"), QKeySequence::Open,
                     tr("Open a scene file (Interplay or thesis format)"));
    a->setIcon(QIcon::fromTheme(QStringLiteral("document-open"), s->standardIcon(QStyle::SP_DialogOpenButton)));
    connect(a, &QAction::triggered, m_files, &DocumentManager::openChosenFile);
    a = createAction(this, QStringLiteral("import"), tr("&Import Thesis Scene…"), {},
                     tr("Open a scene of the 2018 thesis app; it is saved as a new Interplay scene"));
    connect(a, &QAction::triggered, m_files, &DocumentManager::importThesisScene);
    a = createAction(this, QStringLiteral("importGeometry"), tr("Import &Geometry…"), {},
                     tr("Add a body made from an OBJ, STL, glTF or GLB file: a static mesh or a convex hull"));
    connect(a, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import Geometry"), QString(),
                                                          tr("Meshes (*.obj *.stl *.gltf *.glb);;All files (*)"));
        if (!path.isEmpty()) importGeometry(this, m_document, path);
    });
    a = createAction(this, QStringLiteral("save"), tr("&Save"), QKeySequence::Save, tr("Save the scene"));
    a->setIcon(QIcon::fromTheme(QStringLiteral("document-save"), s->standardIcon(QStyle::SP_DialogSaveButton)));
    connect(a, &QAction::triggered, m_files, &DocumentManager::save);
    // The generic X11 key scheme (XFCE, LXDE and Openbox sessions get it) binds no Save As key.
    const QKeySequence saveAsKey = QKeySequence(QKeySequence::SaveAs).isEmpty()
                                       ? QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)
                                       : QKeySequence(QKeySequence::SaveAs);
    a = createAction(this, QStringLiteral("saveAs"), tr("Save &As…"), saveAsKey, tr("Save the scene to a new file"));
    connect(a, &QAction::triggered, m_files, &DocumentManager::saveAs);
    a = createAction(this, QStringLiteral("revert"), tr("Re&vert"), {},
                     tr("Go back to the saved file (asks first; Undo brings the changes back)"));
    connect(a, &QAction::triggered, m_files, &DocumentManager::revert);
    a = createAction(this, QStringLiteral("quit"), tr("&Quit"), QKeySequence::Quit, tr("Quit Interplay"));
    a->setMenuRole(QAction::QuitRole);
    connect(a, &QAction::triggered, this, &QWidget::close);

    // Edit.
    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"), s->standardIcon(QStyle::SP_ArrowBack)));
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redo"));
    // Ctrl+Y and Ctrl+Shift+Z both, whatever the platform's own binding is (Blender, Godot and
    // Windows users reach for either).
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& key : {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)}) {
        if (!redoKeys.contains(key)) redoKeys << key;
    }
    redo->setShortcuts(redoKeys);
    redo->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"), s->standardIcon(QStyle::SP_ArrowForward)));
    // The scene's edit actions are SceneActions'; the window gives them its theme's icons.
    m_sceneActions->deleteAction()->setIcon(
        QIcon::fromTheme(QStringLiteral("edit-delete"), s->standardIcon(QStyle::SP_TrashIcon)));
    a = createAction(
        this, QStringLiteral("applyPose"), tr("Apply &Simulated Pose"), {},
        tr("Make the bodies' simulated positions, orientations and velocities (of the frame shown) the authored scene"));
    connect(a, &QAction::triggered, this, &MainWindow::applySimulatedPose);

    // View.
    a = createAction(this, QStringLiteral("frameSelection"), tr("Frame &Selection"), Qt::Key_F,
                     tr("Aim the camera at the selected bodies (F)"));
    connect(a, &QAction::triggered, m_viewport, &Viewport::frameSelection);
    a = createAction(this, QStringLiteral("frameAll"), tr("Frame &All"), Qt::Key_Home,
                     tr("Aim the camera at every body (Home, or F with nothing selected)"));
    connect(a, &QAction::triggered, m_viewport, &Viewport::frameAll);
    // Blender's numpad views; Ctrl looks the opposite way.
    struct AxisViewAction {
        const char* name;
        const char* text;
        QKeySequence shortcut;
        Viewport::AxisView view;
    };
    const AxisViewAction axisViews[] = {
        {"viewFront", QT_TR_NOOP("&Front"), Qt::KeypadModifier | Qt::Key_1, Viewport::AxisView::Front},
        {"viewBack", QT_TR_NOOP("&Back"), Qt::ControlModifier | Qt::KeypadModifier | Qt::Key_1, Viewport::AxisView::Back},
        {"viewRight", QT_TR_NOOP("&Right"), Qt::KeypadModifier | Qt::Key_3, Viewport::AxisView::Right},
        {"viewLeft", QT_TR_NOOP("&Left"), Qt::ControlModifier | Qt::KeypadModifier | Qt::Key_3, Viewport::AxisView::Left},
        {"viewTop", QT_TR_NOOP("&Top"), Qt::KeypadModifier | Qt::Key_7, Viewport::AxisView::Top},
        {"viewBottom", QT_TR_NOOP("B&ottom"), Qt::ControlModifier | Qt::KeypadModifier | Qt::Key_7, Viewport::AxisView::Bottom},
    };
    for (const AxisViewAction& view : axisViews) {
        a = createAction(this, QString::fromLatin1(view.name), tr(view.text), view.shortcut,
                         tr("Look at the scene from the %1").arg(tr(view.text).remove(QLatin1Char('&')).toLower()));
        connect(a, &QAction::triggered, m_viewport, [this, axis = view.view] { m_viewport->lookAlong(axis); });
    }
    a = createAction(this, QStringLiteral("orthographic"), tr("Ort&hographic"), Qt::KeypadModifier | Qt::Key_5,
                     tr("Switch between orthographic and perspective projection (numpad 5)"));
    a->setCheckable(true);
    connect(a, &QAction::toggled, m_viewport, &Viewport::setOrthographic);
    // A bookmark shown may switch the projection: the check mark follows the camera.
    connect(m_viewport, &Viewport::cameraChanged, a, [this, a] { a->setChecked(m_viewport->camera().isOrthographic()); });
    m_bookmarks = new CameraBookmarks(m_document, m_viewport, this);
    // The transform gizmo: W and E as in Godot and Unity (R held already turns a dragged body);
    // neither checked shows none. L for local axes, which Godot and Unity give no one key.
    auto* gizmoModes = new QActionGroup(this);
    gizmoModes->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    QAction* moveGizmo = createAction(gizmoModes, QStringLiteral("gizmoMove"), tr("&Move Gizmo"), Qt::Key_W,
                                      tr("Show arrows and plane handles on the selection to move it (W)"));
    QAction* rotateGizmo = createAction(gizmoModes, QStringLiteral("gizmoRotate"), tr("Rotate &Gizmo"), Qt::Key_E,
                                        tr("Show rings on the selection to turn it (E)"));
    moveGizmo->setIconText(tr("Move"));
    rotateGizmo->setIconText(tr("Rotate"));
    for (QAction* mode : {moveGizmo, rotateGizmo}) {
        mode->setCheckable(true);
        gizmoModes->addAction(mode);
    }
    moveGizmo->setChecked(m_viewport->gizmoMode() == gizmo::Mode::Move);
    rotateGizmo->setChecked(m_viewport->gizmoMode() == gizmo::Mode::Rotate);
    connect(gizmoModes, &QActionGroup::triggered, m_viewport, [this, moveGizmo, rotateGizmo] {
        m_viewport->setGizmoMode(moveGizmo->isChecked()     ? std::optional(gizmo::Mode::Move)
                                 : rotateGizmo->isChecked() ? std::optional(gizmo::Mode::Rotate)
                                                            : std::nullopt);
    });
    a = createAction(this, QStringLiteral("gizmoLocal"), tr("Lo&cal Gizmo Axes"), Qt::Key_L,
                     tr("Align the gizmo with the active body's axes instead of the world's (L)"));
    a->setCheckable(true);
    a->setIconText(tr("Local"));
    connect(a, &QAction::toggled, m_viewport,
            [this](bool local) { m_viewport->setGizmoSpace(local ? gizmo::Space::Local : gizmo::Space::World); });
    // Y as in Godot; Ctrl held inverts it for one drag.
    a = createAction(this, QStringLiteral("gizmoSnap"), tr("S&nap Gizmo"), Qt::Key_Y,
                     tr("Snap gizmo drags to the grid and angle steps of the Preferences; Ctrl inverts it (Y)"));
    a->setIconText(tr("Snap"));
    a->setCheckable(true);
    connect(a, &QAction::toggled, m_viewport, &Viewport::setGizmoSnapping);
    // The platform's key, else Ctrl+, (GNOME's, KDE's and, as Cmd+, macOS's): X11 alone has none.
    a = createAction(this, QStringLiteral("preferences"), tr("Pre&ferences…"),
                     QKeySequence::keyBindings(QKeySequence::Preferences).value(0, QKeySequence(Qt::CTRL | Qt::Key_Comma)),
                     tr("The editor's settings: the gizmo's snapping steps"));
    a->setMenuRole(QAction::PreferencesRole);
    connect(a, &QAction::triggered, this, [this] { showSingleDialog<PreferencesDialog>(this); });

    // Simulation.
    m_playAction = createAction(this, QStringLiteral("play"), tr("&Play"), Qt::Key_Space,
                                tr("Run or pause the simulation (Space)"));
    m_playAction->setIcon(s->standardIcon(QStyle::SP_MediaPlay));
    m_playAction->setCheckable(true);
    connect(m_playAction, &QAction::toggled, m_simulation, &SimulationController::setPlaying);
    connect(m_simulation, &SimulationController::playingChanged, this, [this](bool playing) {
        m_playAction->setChecked(playing);
        m_playAction->setText(playing ? tr("&Pause") : tr("&Play"));
        m_playAction->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    a = createAction(this, QStringLiteral("step"), tr("&Step"), Qt::Key_Period,
                     tr("Advance one time step and pause (.)"));
    a->setIcon(s->standardIcon(QStyle::SP_MediaSeekForward));
    connect(a, &QAction::triggered, m_simulation, &SimulationController::stepOnce);
    a = createAction(this, QStringLiteral("stepBack"), tr("Step &Back"), Qt::Key_Comma,
                     tr("Show the recorded frame before this one and pause (,)"));
    a->setIcon(s->standardIcon(QStyle::SP_MediaSeekBackward));
    connect(a, &QAction::triggered, m_simulation, &SimulationController::stepBack);
    a = createAction(this, QStringLiteral("reset"), tr("&Reset"), Qt::CTRL | Qt::Key_R,
                     tr("Return to the authored scene (Ctrl+R)"));
    a->setIcon(s->standardIcon(QStyle::SP_MediaSkipBackward));
    connect(a, &QAction::triggered, m_simulation, &SimulationController::reset);
    a = createAction(this, QStringLiteral("throw"), tr("&Throw"), Qt::Key_T,
                     tr("Throw a body from the camera along the view (T); it lives until Reset"));
    connect(a, &QAction::triggered, this, &MainWindow::throwBody);
    a = createAction(this, QStringLiteral("exploreAccuracy"), tr("Explore &Accuracy"), {},
                     tr("Sweep the scene over a grid of settings in the background: what accuracy costs in time"));
    connect(a, &QAction::triggered, this, [this] {
        auto* dock = findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
        dock->show();
        dock->raise();
        m_accuracy->explore();
    });
    m_throwShapes = new QActionGroup(this);
    for (int type = 0; type < simcore::kShapeTypeCount; ++type) {
        QAction* choice = m_throwShapes->addAction(shapeDisplayName(static_cast<simcore::ShapeType>(type)));
        choice->setCheckable(true);
        choice->setData(type);
        choice->setChecked(static_cast<simcore::ShapeType>(type) == simcore::ShapeType::Sphere);
    }
}

QDockWidget* MainWindow::addDock(const QString& objectName, const QString& title, QWidget* widget,
                                 Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(objectName);  // for saveState/restoreState
    dock->setWidget(widget);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks() {
    m_sceneTree = new QTreeView;
    m_sceneTree->setObjectName(QStringLiteral("sceneTree"));
    m_sceneTree->setModel(m_sceneTreeModel);
    m_sceneTree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_sceneTree->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_sceneTree->setDragDropMode(QAbstractItemView::InternalMove);
    m_sceneTree->setDefaultDropAction(Qt::MoveAction);
    m_sceneTree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                 QAbstractItemView::SelectedClicked);
    m_sceneTree->setUniformRowHeights(true);
    // Names are what a user reads the tree for: their column fits them whole, and Details (the
    // long column) takes what is left and is cut instead; a narrow dock scrolls sideways.
    m_sceneTree->header()->setSectionResizeMode(SceneTreeModel::NameColumn, QHeaderView::ResizeToContents);
    m_sceneTree->header()->setSectionResizeMode(SceneTreeModel::TypeColumn, QHeaderView::ResizeToContents);
    m_sceneTree->header()->setSectionResizeMode(SceneTreeModel::DetailsColumn, QHeaderView::Stretch);
    m_sceneTree->expandAll();
    connect(m_sceneTreeModel, &QAbstractItemModel::modelReset, m_sceneTree, &QTreeView::expandAll);
    connect(m_sceneTree->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (m_syncingSelection) return;
        QList<int> bodies, joints;
        for (const QModelIndex& index : m_sceneTree->selectionModel()->selectedRows()) {
            if (const int body = m_sceneTreeModel->bodyIndexOf(index); body >= 0) bodies << body;
            if (const int joint = m_sceneTreeModel->jointIndexOf(index); joint >= 0) joints << joint;
        }
        m_syncingSelection = true;
        m_document->setSelection(bodies, joints);
        m_syncingSelection = false;
    });

    m_inspector = new InspectorPanel(m_document);
    m_settingsPanel = new SimulationSettingsPanel(m_settingsModel, m_simulation, m_debugDraw);
    m_profiler = new ProfilerPanel(m_simulation);
    m_liveState = new LiveStatePanel(m_document, m_simulation);
    m_liveState->watchHover(m_viewport);
    m_accuracy = new AccuracyPanel(m_document, m_settingsModel);
    auto* history = new QUndoView(m_document->undoStack());
    history->setObjectName(QStringLiteral("historyView"));
    history->setEmptyLabel(tr("<opened>"));
    history->setCleanIcon(QIcon::fromTheme(QStringLiteral("document-save"), style()->standardIcon(QStyle::SP_DialogSaveButton)));

    QDockWidget* scene = addDock(QStringLiteral("sceneDock"), tr("Scene"), m_sceneTree, Qt::LeftDockWidgetArea);
    QDockWidget* historyDock = addDock(QStringLiteral("historyDock"), tr("History"), history, Qt::LeftDockWidgetArea);
    QDockWidget* inspector = addDock(QStringLiteral("inspectorDock"), tr("Inspector"), m_inspector, Qt::RightDockWidgetArea);
    QDockWidget* settings = addDock(QStringLiteral("settingsDock"), tr("Simulation"), m_settingsPanel, Qt::RightDockWidgetArea);
    QDockWidget* profiler = addDock(QStringLiteral("profilerDock"), tr("Profiler"), m_profiler, Qt::BottomDockWidgetArea);
    QDockWidget* liveState = addDock(QStringLiteral("liveStateDock"), tr("Live State"), m_liveState, Qt::RightDockWidgetArea);
    QDockWidget* accuracy = addDock(QStringLiteral("accuracyDock"), tr("Accuracy"), m_accuracy, Qt::BottomDockWidgetArea);
    splitDockWidget(inspector, liveState, Qt::Vertical);  // before tabifying: a tab group would take it as a tab
    tabifyDockWidget(profiler, accuracy);
    profiler->raise();
    tabifyDockWidget(inspector, settings);
    inspector->raise();
    splitDockWidget(scene, historyDock, Qt::Vertical);
    for (QDockWidget* dock : {scene, historyDock, inspector, settings, profiler, liveState, accuracy}) {
        dock->toggleViewAction()->setObjectName(dock->objectName() + QStringLiteral("Toggle"));
    }
    arrangeDefaultLayout();
}

void MainWindow::arrangeDefaultLayout() {
    auto* scene = findChild<QDockWidget*>(QStringLiteral("sceneDock"));
    auto* history = findChild<QDockWidget*>(QStringLiteral("historyDock"));
    auto* inspector = findChild<QDockWidget*>(QStringLiteral("inspectorDock"));
    auto* profiler = findChild<QDockWidget*>(QStringLiteral("profilerDock"));
    auto* liveState = findChild<QDockWidget*>(QStringLiteral("liveStateDock"));
    for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->show();
    resizeDocks({scene, inspector}, {300, 340}, Qt::Horizontal);
    resizeDocks({scene, history}, {420, 220}, Qt::Vertical);
    resizeDocks({profiler}, {200}, Qt::Vertical);
    resizeDocks({inspector, liveState}, {460, 300}, Qt::Vertical);
}

// Last, so it stays the rightmost menu whatever the others add.
void MainWindow::createHelpMenu() {
    QAction* controls = createAction(this, QStringLiteral("helpControls"), tr("&Keyboard and Mouse"),
                                     QKeySequence::HelpContents, tr("List the editor's keyboard and mouse controls"));
    connect(controls, &QAction::triggered, this, [this] { showSingleDialog<HelpDialog>(this); });
    QAction* about = createAction(this, QStringLiteral("about"), tr("&About Interplay"), {},
                                  tr("Version, Qt version and engine"));
    about->setMenuRole(QAction::AboutRole);
    connect(about, &QAction::triggered, this, [this] { showAboutInterplay(this); });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    help->addAction(controls);
    help->addSeparator();
    help->addAction(about);
}

void MainWindow::createStatusBar() {
    m_timeLabel = new QLabel(this);
    m_rateLabel = new QLabel(this);
    m_rateLabel->setObjectName(QStringLiteral("realTimeLabel"));
    m_rateLabel->setToolTip(tr("Simulated seconds per wall-clock second over the last second of playback"));
    m_costLabel = new QLabel(this);
    m_bodiesLabel = new QLabel(this);
    m_bodiesLabel->setObjectName(QStringLiteral("awakeBodiesLabel"));
    m_bodiesLabel->setToolTip(tr("Dynamic bodies awake, of all dynamic bodies"));
    m_fpsLabel = new QLabel(this);
    // Fixed digits keep the labels from jittering while running.
    for (QLabel* label : {m_timeLabel, m_rateLabel, m_costLabel, m_bodiesLabel, m_fpsLabel}) {
        label->setFont(QFont(QStringLiteral("monospace")));
        label->setContentsMargins(8, 0, 8, 0);
        statusBar()->addPermanentWidget(label);
    }
    // The frame rate is a property of the display, not of a step: sample it twice a second.
    auto* fpsTimer = new QTimer(this);
    connect(fpsTimer, &QTimer::timeout, this,
            [this] { m_fpsLabel->setText(tr("%1 fps").arg(m_viewport->framesPerSecond(), 3)); });
    fpsTimer->start(500);
}

// ---- File menus ----------------------------------------------------------------------------------

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = m_files->recentFiles();
    for (int i = 0; i < files.size(); ++i) {
        const QString& path = files[i];
        // &1..&9 as keyboard accelerators, as most editors do.
        QAction* a = m_recentMenu->addAction(i < 9 ? tr("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName())
                                                   : QFileInfo(path).fileName());
        a->setStatusTip(path);
        a->setToolTip(path);
        connect(a, &QAction::triggered, m_files, [this, path] { m_files->open(path); });
    }
    if (!files.isEmpty()) m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("&Clear Menu"), m_files, &DocumentManager::clearRecentFiles);
    clear->setObjectName(QStringLiteral("clearRecent"));
    clear->setEnabled(!files.isEmpty());
}

void MainWindow::rebuildExamplesMenu() {
    m_examplesMenu->clear();
    const QDir dir(DocumentManager::examplesDirectory());
    const auto addScenes = [this](QMenu* menu, const QDir& folder) {
        for (const QFileInfo& info : folder.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            const QString path = info.absoluteFilePath();
            connect(menu->addAction(info.completeBaseName()), &QAction::triggered, m_files,
                    [this, path] { m_files->openExample(path); });
        }
    };
    addScenes(m_examplesMenu, dir);
    if (dir.exists(QStringLiteral("thesis"))) addScenes(m_examplesMenu->addMenu(tr("Thesis")), QDir(dir.filePath(QStringLiteral("thesis"))));
    m_examplesMenu->setEnabled(!m_examplesMenu->isEmpty());
}

// ---- Editing --------------------------------------------------------------------------------------

void MainWindow::applySimulatedPose() {
    QString error;
    if (QUndoCommand* command = m_simulation->simulatedPoseCommand(m_document, &error))
        m_document->undoStack()->push(command);
    else
        statusBar()->showMessage(error, 8000);
}

void MainWindow::throwBody() {
    const auto type = static_cast<simcore::ShapeType>(m_throwShapes->checkedAction()->data().toInt());
    const Camera& camera = m_viewport->camera();
    const int thrown = static_cast<int>(m_simulation->bodyIds().size() - m_simulation->authoredScene().bodies.size());
    simcore::SceneBody body = templateBody(type, tr("Thrown %1").arg(thrown + 1), camera.eye() + camera.forward() * 1.5f);
    body.body.linearVelocity = camera.forward() * kThrowSpeed;
    QString error;
    if (!m_simulation->spawn(body, &error).isValid()) {
        statusBar()->showMessage(tr("Could not throw: %1").arg(error), 8000);
        return;
    }
    m_simulation->play();  // a throw is meant to fly
}

// ---- Keeping things in step ------------------------------------------------------------------------

void MainWindow::documentSceneReplaced() {
    QString error;
    if (!m_simulation->setScene(m_document->scene(), &error)) {
        m_files->prompts().error(tr("Scene"), tr("The scene cannot be simulated."), error);
        return;
    }
    m_viewport->frameScene();
}

void MainWindow::syncTreeSelection() {
    if (m_syncingSelection) return;
    m_syncingSelection = true;
    QItemSelection selection;
    for (int body : m_document->selectedBodies()) {
        selection.select(m_sceneTreeModel->indexOfBody(body, 0),
                         m_sceneTreeModel->indexOfBody(body, SceneTreeModel::ColumnCount - 1));
    }
    for (int joint : m_document->selectedJoints()) {
        selection.select(m_sceneTreeModel->indexOfJoint(joint, 0),
                         m_sceneTreeModel->indexOfJoint(joint, SceneTreeModel::ColumnCount - 1));
    }
    m_sceneTree->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
    if (!m_document->selectedBodies().isEmpty()) {
        m_sceneTree->scrollTo(m_sceneTreeModel->indexOfBody(m_document->selectedBodies().first()));
    } else if (!m_document->selectedJoints().isEmpty()) {
        m_sceneTree->scrollTo(m_sceneTreeModel->indexOfJoint(m_document->selectedJoints().first()));
    }
    m_syncingSelection = false;
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("[*]%1 — Interplay").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
    action(QStringLiteral("revert"))->setEnabled(!m_document->filePath().isEmpty());
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
    m_rateLabel->setVisible(m_simulation->isPlaying());
    if (const auto rate = m_simulation->playbackRate()) {
        const QString factor = tr("Real time ×%1").arg(rate->factor, 0, 'f', 2);
        m_rateLabel->setText(rate->keepingUp ? factor : tr("%1 — cannot keep up").arg(factor));
    } else {
        m_rateLabel->setText(tr("Real time ×–"));  // measured once a quarter second has run
    }
    m_costLabel->setText(tr("%1 ms/step").arg(world->lastStepProfile().totalMs, 0, 'f', 3));
    const SimulationController::AwakeCount bodies = m_simulation->awakeCount();
    m_bodiesLabel->setText(tr("%1 / %2 awake").arg(bodies.awake).arg(bodies.dynamic));
}

void MainWindow::showSimulationError(const QString& message) {
    statusBar()->showMessage(message, 10000);
    m_files->prompts().error(tr("Simulation"), message, QString());
}

// ---- Window events ----------------------------------------------------------------------------------

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    // Before any shortcut fires, Qt asks the focus widget whether it wants the key itself.
    if (event->type() != QEvent::ShortcutOverride) return QMainWindow::eventFilter(watched, event);
    // A widget of this window, or an item of its QML panel (QQuickWidget makes its focus item the
    // receiver of keys).
    const auto* widget = qobject_cast<QWidget*>(watched);
    const auto* item = qobject_cast<QQuickItem*>(watched);
    if (!(widget && widget->window() == this) &&
        !(item && item->window() == m_settingsPanel->quickWidget()->quickWindow())) {
        return false;
    }
    auto* key = static_cast<QKeyEvent*>(event);
    const bool undo = key->matches(QKeySequence::Undo);
    const bool redo = action(QStringLiteral("redo"))->shortcuts().contains(QKeySequence(key->keyCombination()));
    if ((undo || redo) && !hasOwnTextHistory(watched, undo)) {
        key->ignore();  // a committed field leaves Undo and Redo to the document's history
        return true;
    }
    if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier && isDropDown(watched)) {
        key->accept();  // a focused drop-down opens on Space instead of playing
        return true;
    }
    return false;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    saveLayout();
    m_files->removeRecoveryFile();  // a normal exit leaves nothing to recover
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    // A scene opens; a mesh file is imported into the scene (Import Geometry's dialog).
    if (urls.size() == 1 && urls.first().isLocalFile() &&
        (urls.first().toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) ||
         isGeometryFile(urls.first().toLocalFile()))) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty()) return;
    event->acceptProposedAction();
    // Opening asks questions (unsaved changes); not while the drag source waits for the drop.
    const QString path = urls.first().toLocalFile();
    if (isGeometryFile(path)) QTimer::singleShot(0, this, [this, path] { importGeometry(this, m_document, path); });
    else QTimer::singleShot(0, m_files, [this, path] { m_files->open(path); });
}

void MainWindow::restoreLayout() {
    QSettings settings;
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
}

void MainWindow::saveLayout() {
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
}

}  // namespace interplay
