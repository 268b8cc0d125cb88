// Over 800 lines because it is one fixture, a real window with a GL context under Xvfb, that
// every case needs and that costs seconds to make; Qt Test runs one test class per program, and
// the GUI suites take turns for the display, so a second program would add its start-up to CI.
// The whole editor window, with real OpenGL under Xvfb: title and modified marker, the
// unsaved-changes prompt (answered by a test hook, never a modal dialog), open/save/revert through
// the window, recent files, autosave and recovery, a file changed by another program, a failing
// save; clicking a body's pixel selects it and dragging moves it as one undo entry (in place, even
// among a thousand bodies); Play, Step and Reset leave the authored scene as it was; edits while a
// run is paused reach the running world without disturbing the other bodies; joints are added
// from the selection, selected in the tree or by clicking near their anchors in the viewport, drawn
// highlighted and deleted with their bodies; the toolbar's edit actions; the QML settings panel
// loads and its controls change the running world; every demo scene renders.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/scene_tree_model.h"
#include "app/document/undo_commands.h"
#include "app/main_window.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/number_field.h"
#include "app/panels/profiler_panel.h"
#include "app/panels/simulation_settings_panel.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"
#include "simcore/settings_schema.h"
#include "simcore/world/world.h"
#include "support/editor_window.h"
#include "support/isolated_settings.h"
#include "support/fault_injection.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QQuickItem>
#include <QQuickWidget>
#include <QStatusBar>
#include <QToolBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <limits>
#include <map>
#include <memory>
#include <set>

using interplay::DocumentManager;
using interplay::MainWindow;

namespace {

std::string sceneText(const simcore::Scene& scene) {
    return simcore::serializeScene(scene);
}

int distinctColors(const QImage& image) {
    std::set<QRgb> colors;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) colors.insert(image.pixel(x, y) & 0xFFFFFFu);
    }
    return static_cast<int>(colors.size());
}

// Records what the window asked, and answers as told.
struct ScriptedPrompts {
    DocumentManager::UnsavedChoice unsavedAnswer = DocumentManager::UnsavedChoice::Cancel;
    bool confirmAnswer = true;
    QString fileAnswer;
    int unsavedAsked = 0;
    QStringList questions;
    QStringList errors;

    void install(MainWindow& window) {
        auto& p = window.documentManager()->prompts();
        p.unsavedChanges = [this](const QString&) {
            ++unsavedAsked;
            return unsavedAnswer;
        };
        p.confirm = [this](const QString&, const QString& question) {
            questions << question;
            return confirmAnswer;
        };
        p.error = [this](const QString&, const QString& text, const QString& details) { errors << text + '\n' + details; };
        p.chooseFile = [this](DocumentManager::FileChoice, const QString&, const QString&) { return fileAnswer; };
    }
};

// A body's centre on screen (widget pixels), as the viewport's camera projects it.
QPoint pixelOf(const interplay::Viewport& viewport, const simcore::Vec3& point) {
    const glm::vec3 p = viewport.camera().project(point, float(viewport.width()), float(viewport.height()));
    return {int(std::lround(p.x)), int(std::lround(p.y))};
}

// Items by objectName through the visual tree: a Repeater's items have no QObject parent to find.
QQuickItem* findItem(QQuickItem* root, const QString& name) {
    if (root->objectName() == name) return root;
    for (QQuickItem* child : root->childItems()) {
        if (QQuickItem* found = findItem(child, name)) return found;
    }
    return nullptr;
}

// Where every body of the running world is and how it moves, by world id.
struct LiveState {
    simcore::Vec3 position, linearVelocity;
    simcore::Quat orientation;
    bool operator==(const LiveState&) const = default;
};
std::map<std::string, LiveState> liveStates(const simcore::World& world) {
    std::map<std::string, LiveState> states;
    for (simcore::BodyId id : world.bodyIds()) {
        states[world.name(id)] = {world.position(id), world.linearVelocity(id), world.orientation(id)};
    }
    return states;
}

void typeInto(QLineEdit* field, const QString& text) {
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

simcore::Vec3 bodyCenter(const interplay::SceneDocument& document, int index) {
    const simcore::BodyCreationSettings& b = document.body(index).body;
    return simcore::worldBounds(b.shape, {b.position, b.orientation}).center();
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void titleShowsNameAndModifiedMarker();
    void docksHaveNamesAndViewMenuEntries();
    void unsavedChangesPrompt_data();
    void unsavedChangesPrompt();
    void openErrorIsReportedAndDocumentKept();
    void saveAsOpenRevertRoundTrip();
    void failingSaveLeavesOldFileAndTellsTheUser();
    void recentFilesAreAbsoluteDeduplicatedAndCapped();
    void autosaveIsOfferedForRecovery();
    void fileChangedOnDiskOffersReload();
    void speedBoundWarningFitsTheStatusBar();

    void droppingASceneFileOpensIt();
    void clickingABodySelectsIt();
    void flyModeMovesTheCamera();
    void frameSelectionAimsAtTheSelectedBody();
    void draggingABodyMovesItAsOneUndoEntry();
    void playStepResetLeaveTheAuthoredSceneIntact();
    void nonFiniteStateStopsPlaybackWithAMessage();
    void grabbingWhilePlayingPullsTheBody();
    void applySimulatedPoseIsUndoable();
    void addDuplicateDeleteActions();
    void shortcutsReachTheSceneActionsAndFileCommands();
    void treeSelectionFollowsTheDocument();
    void throwSpawnsIntoTheRunningWorldOnly();
    void editsWhilePausedKeepTheRun();
    void jointAddedWhilePausedHoldsTheBodiesWhereTheyAre();
    void draggingInABigSceneMovesOneBodyInPlace();

    void addJointActionsFollowTheSelection();
    void deletingABodyTakesItsJointsInOneStep();
    void jointsAreSelectedInTheTreeAndDrawnHighlighted();
    void clickingAJointSelectsIt();

    void overlaysAndSleepingTintAreDrawn();
    void qmlPanelLoadsAndChangesTheWorld();
    void profilerShowsTheLatestStep();
    void statusBarAndProfilerCountTheSameBodies();
    void everyToolbarButtonShowsAt1400Pixels();
    void everyDemoSceneRenders_data();
    void everyDemoSceneRenders();

private:
    std::unique_ptr<MainWindow> m_window;
    ScriptedPrompts m_prompts;
    QTemporaryDir m_dir;
};

void TestMainWindow::initTestCase() {
    test_support::isolateSettings("test_main_window");
    QVERIFY(m_dir.isValid());
}

void TestMainWindow::cleanupTestCase() {
    test_support::removeSettings();
}

void TestMainWindow::init() {
    test_support::clearSettings();
    m_prompts = ScriptedPrompts{};
    m_window = std::make_unique<MainWindow>();
    m_prompts.install(*m_window);
    m_window->openDefaultScene();
    m_window->resize(1400, 900);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->viewport()->grabViewport();  // first frame: the camera frames the scene
}

void TestMainWindow::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestMainWindow::titleShowsNameAndModifiedMarker() {
    QCOMPARE(m_window->windowTitle(), QString("[*]Untitled — Interplay"));
    QVERIFY(!m_window->isWindowModified());
    m_window->action("addBox")->trigger();
    QVERIFY(m_window->isWindowModified());
    m_window->document()->undoStack()->undo();
    QVERIFY(!m_window->isWindowModified());
    m_window->document()->setSelectedBodies({1, 2});
    QVERIFY(!m_window->isWindowModified());  // selecting is not editing
}

void TestMainWindow::docksHaveNamesAndViewMenuEntries() {
    QStringList names;
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>()) {
        QVERIFY(!dock->objectName().isEmpty());
        names << dock->objectName();
        QVERIFY(m_window->findChild<QAction*>(dock->objectName() + "Toggle"));
    }
    names.sort();
    QCOMPARE(names, (QStringList{"accuracyDock", "historyDock", "inspectorDock", "liveStateDock", "profilerDock", "sceneDock",
                                 "settingsDock"}));

    // The layout survives a restart through QSettings.
    auto* profiler = m_window->findChild<QDockWidget*>("profilerDock");
    profiler->hide();
    m_window->close();
    m_window = std::make_unique<MainWindow>();
    QVERIFY(m_window->findChild<QDockWidget*>("profilerDock")->isHidden());
    QVERIFY(!m_window->findChild<QDockWidget*>("sceneDock")->isHidden());
    // Standard shortcuts.
    QCOMPARE(m_window->action("save")->shortcut(), QKeySequence(QKeySequence::Save));
    QCOMPARE(m_window->action("open")->shortcut(), QKeySequence(QKeySequence::Open));
    QCOMPARE(m_window->action("duplicate")->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_D));
    QCOMPARE(m_window->action("play")->shortcut(), QKeySequence(Qt::Key_Space));
    QCOMPARE(m_window->action("frameSelection")->shortcut(), QKeySequence(Qt::Key_F));
}

void TestMainWindow::unsavedChangesPrompt_data() {
    QTest::addColumn<int>("answer");
    QTest::addColumn<bool>("proceeds");
    QTest::newRow("cancel") << int(DocumentManager::UnsavedChoice::Cancel) << false;
    QTest::newRow("discard") << int(DocumentManager::UnsavedChoice::Discard) << true;
    QTest::newRow("save") << int(DocumentManager::UnsavedChoice::Save) << true;
}

void TestMainWindow::unsavedChangesPrompt() {
    QFETCH(int, answer);
    QFETCH(bool, proceeds);
    const QString path = m_dir.filePath(QString("prompt-%1.json").arg(answer));
    m_prompts.fileAnswer = path;  // Save on an untitled scene asks where
    m_window->action("addSphere")->trigger();
    const std::string edited = sceneText(m_window->document()->scene());
    m_prompts.unsavedAnswer = static_cast<DocumentManager::UnsavedChoice>(answer);

    // New, Open and closing all ask.
    QCOMPARE(m_window->documentManager()->newScene(), proceeds);
    QCOMPARE(m_prompts.unsavedAsked, 1);
    if (!proceeds) {
        QCOMPARE(sceneText(m_window->document()->scene()), edited);
        QVERIFY(m_window->document()->isModified());
        QVERIFY(!m_window->documentManager()->open(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
        QCOMPARE(m_prompts.unsavedAsked, 2);
        QVERIFY(!m_window->close());
        QCOMPARE(m_prompts.unsavedAsked, 3);
        QVERIFY(m_window->isVisible());
        return;
    }
    QVERIFY(!m_window->document()->isModified());
    QCOMPARE(m_window->document()->bodyCount(), 1);  // New: the ground only
    if (answer == int(DocumentManager::UnsavedChoice::Save)) {
        QVERIFY(QFile::exists(path));
        interplay::SceneDocument saved;
        QVERIFY(saved.load(path));
        QCOMPARE(sceneText(saved.scene()), edited);
    } else {
        QVERIFY(!QFile::exists(path));
    }
    // Nothing to lose: no question.
    QVERIFY(m_window->documentManager()->open(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    QCOMPARE(m_prompts.unsavedAsked, 1);
}

void TestMainWindow::openErrorIsReportedAndDocumentKept() {
    const QString path = m_dir.filePath("bad.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "interplay.scene", "version": 1, "bodies": [{"shape": {"type": "box", "halfExtents": [1, "x", 1]}}]})");
    file.close();
    const std::string before = sceneText(m_window->document()->scene());
    QVERIFY(!m_window->documentManager()->open(path));
    QCOMPARE(m_prompts.errors.size(), 1);
    QVERIFY2(m_prompts.errors.first().contains("bad.json") && m_prompts.errors.first().contains("/bodies/0/shape/halfExtents"),
             qPrintable(m_prompts.errors.first()));
    QCOMPARE(sceneText(m_window->document()->scene()), before);
    QCOMPARE(m_window->windowTitle(), QString("[*]Untitled — Interplay"));
}

void TestMainWindow::saveAsOpenRevertRoundTrip() {
    const QString path = m_dir.filePath("roundtrip");
    m_prompts.fileAnswer = path;
    m_window->action("addCapsule")->trigger();
    QVERIFY(m_window->documentManager()->saveAs());
    QCOMPARE(m_window->document()->filePath(), path + ".json");  // the extension is added
    QCOMPARE(m_window->windowTitle(), QString("[*]roundtrip.json — Interplay"));
    QVERIFY(!m_window->isWindowModified());
    const std::string saved = sceneText(m_window->document()->scene());

    m_window->action("addBox")->trigger();
    QVERIFY(m_window->isWindowModified());
    QVERIFY(m_window->documentManager()->revert());
    QCOMPARE(sceneText(m_window->document()->scene()), saved);
    QVERIFY(!m_window->isWindowModified());

    QVERIFY(m_window->documentManager()->newScene());
    QVERIFY(m_window->documentManager()->open(path + ".json"));
    QCOMPARE(sceneText(m_window->document()->scene()), saved);
    // Ctrl+S on a file with a path writes without asking.
    m_prompts.fileAnswer.clear();
    m_window->action("addHull")->trigger();
    m_window->action("save")->trigger();
    QVERIFY(!m_window->isWindowModified());
    interplay::SceneDocument reread;
    QVERIFY(reread.load(path + ".json"));
    QCOMPARE(reread.bodyCount(), m_window->document()->bodyCount());
}

void TestMainWindow::failingSaveLeavesOldFileAndTellsTheUser() {
    m_prompts.fileAnswer = "/proc/version";  // a read-only file system, even for root
    QFile before("/proc/version");
    QVERIFY(before.open(QIODevice::ReadOnly));
    const QByteArray original = before.readAll();
    m_window->action("addBox")->trigger();
    QVERIFY(!m_window->documentManager()->saveAs());
    QCOMPARE(m_prompts.errors.size(), 1);
    QVERIFY2(m_prompts.errors.first().contains("unchanged"), qPrintable(m_prompts.errors.first()));
    QFile after("/proc/version");
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), original);
    QVERIFY(m_window->isWindowModified());
}

void TestMainWindow::recentFilesAreAbsoluteDeduplicatedAndCapped() {
    QDir::setCurrent(INTERPLAY_SOURCE_DIR);
    QVERIFY(m_window->documentManager()->open("scenes/incline.json"));  // relative: stored absolute
    QVERIFY(m_window->documentManager()->open(INTERPLAY_SOURCE_DIR "/scenes/tumbling.json"));
    QVERIFY(m_window->documentManager()->open(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    const QStringList recent = m_window->documentManager()->recentFiles();
    QCOMPARE(recent.size(), 2);
    QCOMPARE(recent.first(), QString(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    for (const QString& path : recent) QVERIFY(QDir::isAbsolutePath(path));

    const QStringList scenes = QDir(INTERPLAY_SOURCE_DIR "/scenes").entryList({"*.json"}, QDir::Files);
    QVERIFY(scenes.size() > DocumentManager::kMaxRecentFiles);
    for (const QString& name : scenes)
        QVERIFY(m_window->documentManager()->open(INTERPLAY_SOURCE_DIR "/scenes/" + name));
    QCOMPARE(m_window->documentManager()->recentFiles().size(), DocumentManager::kMaxRecentFiles);

    auto* menu = m_window->findChild<QMenu*>("recentMenu");
    emit menu->aboutToShow();
    QCOMPARE(menu->actions().size(), DocumentManager::kMaxRecentFiles + 2);  // files, separator, Clear
    m_window->findChild<QAction*>("clearRecent")->trigger();
    QVERIFY(m_window->documentManager()->recentFiles().isEmpty());
    QVERIFY(!m_window->findChild<QAction*>("clearRecent")->isEnabled());

    // The Examples menu lists the demo scenes.
    auto* examples = m_window->findChild<QMenu*>("examplesMenu");
    QStringList titles;
    for (QAction* a : examples->actions()) titles << a->text();
    QVERIFY2(titles.contains("pyramid10") && titles.contains("Thesis"), qPrintable(titles.join(", ")));
}

void TestMainWindow::autosaveIsOfferedForRecovery() {
    const QString path = m_dir.filePath("recover.json");
    QVERIFY(m_window->document()->save(path));
    m_window->action("addCylinder")->trigger();
    const std::string edited = sceneText(m_window->document()->scene());
    m_window->documentManager()->setAutosaveInterval(50);
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(DocumentManager::recoveryFilePath()), 5000);

    // "Crash": the window goes away without closing (no prompt, no clean-up).
    m_window->document()->undoStack()->setClean();
    m_window.release()->deleteLater();  // as if the process ended here
    QVERIFY(QFile::exists(DocumentManager::recoveryFilePath()));

    m_window = std::make_unique<MainWindow>();
    m_prompts.install(*m_window);
    m_prompts.confirmAnswer = true;
    QVERIFY(m_window->documentManager()->offerRecovery());
    QCOMPARE(m_prompts.questions.size(), 1);
    QVERIFY2(m_prompts.questions.first().contains("recover.json"), qPrintable(m_prompts.questions.first()));
    QCOMPARE(sceneText(m_window->document()->scene()), edited);
    QCOMPARE(m_window->document()->filePath(), path);
    QVERIFY(m_window->document()->isModified());

    // Saving clears the recovery file; a normal close leaves none.
    QVERIFY(m_window->documentManager()->save());
    QVERIFY(!QFile::exists(DocumentManager::recoveryFilePath()));
    QVERIFY(!m_window->documentManager()->offerRecovery());
}

void TestMainWindow::fileChangedOnDiskOffersReload() {
    const QString path = m_dir.filePath("watched.json");
    QVERIFY(m_window->document()->save(path));
    m_window->show();
    // Our own save is not "changed by another program".
    m_window->action("addBox")->trigger();
    QVERIFY(m_window->documentManager()->save());
    QTest::qWait(300);
    QVERIFY(m_prompts.questions.isEmpty());

    // Another program writes a different scene.
    interplay::SceneDocument other;
    QVERIFY(other.load(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QByteArray::fromStdString(sceneText(other.scene())));
    file.close();
    m_prompts.confirmAnswer = true;
    QTRY_COMPARE_WITH_TIMEOUT(m_prompts.questions.size(), 1, 5000);
    QVERIFY(m_prompts.questions.first().contains("watched.json"));
    QCOMPARE(sceneText(m_window->document()->scene()), sceneText(other.scene()));
}

void TestMainWindow::speedBoundWarningFitsTheStatusBar() {
    // The torn rope of test_editor_soak: the light box is flung at the bound within a few steps.
    const simcore::SceneLoadResult torn = simcore::parseScene(R"({"format": "interplay.scene", "version": 1,
        "bodies": [
          {"name": "light", "shape": {"type": "box", "halfExtents": [0.36, 0.25, 0.063]}, "mass": 18, "position": [0, 5, 0]},
          {"name": "heavy", "shape": {"type": "sphere", "radius": 0.61}, "mass": 1400, "position": [0, 5, 1000]}],
        "joints": [{"type": "distance", "bodyA": "light", "bodyB": "heavy", "anchor": [8, 5, 0],
                    "anchorB": [0, 5, 1000], "minLength": 0, "maxLength": 1}]})", "torn");
    QVERIFY(torn.ok());
    m_window->document()->restoreRecovered(*torn.scene, QString());
    m_window->resize(1280, 800);  // the editor's smallest default size (main.cpp)
    QTest::qWait(50);
    m_window->simulation()->stepFrames(60);
    QStatusBar* bar = m_window->statusBar();
    const QString message = bar->currentMessage();
    QVERIFY2(message.contains(QStringLiteral("speed limit")), qPrintable(message));

    // The message is drawn left of the permanent labels (time, cost, bodies, frame rate).
    int labelsLeft = bar->width();
    for (const QLabel* label : bar->findChildren<QLabel*>())
        if (label->isVisible()) labelsLeft = std::min(labelsLeft, label->geometry().left());
    QVERIFY2(bar->fontMetrics().horizontalAdvance(message) < labelsLeft,
             qPrintable(QStringLiteral("%1 px of message, %2 px before the labels")
                            .arg(bar->fontMetrics().horizontalAdvance(message))
                            .arg(labelsLeft)));
    QVERIFY2(bar->toolTip().contains(QStringLiteral("more substeps")), qPrintable(bar->toolTip()));
}

void TestMainWindow::droppingASceneFileOpensIt() {
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(INTERPLAY_SOURCE_DIR "/scenes/tumbling.json")});
    QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &data, Qt::LeftButton, {});
    QApplication::sendEvent(m_window.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &data, Qt::LeftButton, {});
    QApplication::sendEvent(m_window.get(), &drop);
    QTRY_COMPARE(m_window->document()->displayName(), QString("tumbling.json"));

    QMimeData text;
    text.setUrls({QUrl::fromLocalFile(INTERPLAY_SOURCE_DIR "/README.md")});
    QDragEnterEvent refused(QPoint(50, 50), Qt::CopyAction, &text, Qt::LeftButton, {});
    QApplication::sendEvent(m_window.get(), &refused);
    QVERIFY(!refused.isAccepted());
}

void TestMainWindow::flyModeMovesTheCamera() {
    interplay::Viewport* viewport = m_window->viewport();
    const QPoint centre(viewport->width() / 2, viewport->height() / 2);
    const glm::vec3 eye = viewport->camera().eye();
    const glm::vec3 forward = viewport->camera().forward();
    QTest::mousePress(viewport, Qt::RightButton, {}, centre);
    QTest::keyPress(viewport, Qt::Key_W);
    QTRY_VERIFY(glm::dot(viewport->camera().eye() - eye, forward) > 0.5f);  // flew forward
    QTest::keyRelease(viewport, Qt::Key_W);
    // Looking around turns the view about the eye, which stays put.
    const glm::vec3 flown = viewport->camera().eye();
    QTest::mouseMove(viewport, centre + QPoint(60, 0));
    QVERIFY(glm::length(viewport->camera().eye() - flown) < 1e-3f);
    QVERIFY(glm::dot(viewport->camera().forward(), forward) < 0.999f);
    QTest::mouseRelease(viewport, Qt::RightButton, {}, centre + QPoint(60, 0));
    QCOMPARE(m_window->document()->undoStack()->count(), 0);
}

void TestMainWindow::frameSelectionAimsAtTheSelectedBody() {
    interplay::Viewport* viewport = m_window->viewport();
    m_window->document()->setSelectedBodies({5});  // the rock, at one end of the row
    const float before = glm::length(viewport->camera().target() - bodyCenter(*m_window->document(), 5));
    m_window->action("frameSelection")->trigger();
    const float after = glm::length(viewport->camera().target() - bodyCenter(*m_window->document(), 5));
    QVERIFY2(before > 1.0f && after < 0.2f, qPrintable(QString("target %1 m, then %2 m from the rock").arg(before).arg(after)));
    // The rock fills a good part of the view now.
    viewport->grabViewport();
    QCOMPARE(viewport->sceneBodyAt(QPoint(viewport->width() / 2, viewport->height() / 2)), 5);
}

void TestMainWindow::clickingABodySelectsIt() {
    interplay::Viewport* viewport = m_window->viewport();
    interplay::SceneDocument* document = m_window->document();
    const QPoint sphere = pixelOf(*viewport, bodyCenter(*document, 2));
    QCOMPARE(viewport->sceneBodyAt(sphere), 2);  // the ray cast agrees with the projection
    QTest::mouseClick(viewport, Qt::LeftButton, {}, sphere);
    QCOMPARE(document->selectedBodies(), QList<int>{2});

    const QPoint cylinder = pixelOf(*viewport, bodyCenter(*document, 4));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier, cylinder);
    QCOMPARE(document->selectedBodies(), (QList<int>{2, 4}));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, sphere);  // toggles off
    QCOMPARE(document->selectedBodies(), QList<int>{4});

    // The sky above the scene: nothing there, the selection clears.
    QCOMPARE(viewport->sceneBodyAt(QPoint(viewport->width() / 2, 3)), -1);
    QTest::mouseClick(viewport, Qt::LeftButton, {}, QPoint(viewport->width() / 2, 3));
    QVERIFY(document->selectedBodies().isEmpty());
    QCOMPARE(document->undoStack()->count(), 0);

    // The selection is drawn: the outline changes pixels around the body.
    const QImage plain = viewport->grabViewport();
    document->setSelectedBodies({2});
    const QImage outlined = viewport->grabViewport();
    QVERIFY(plain != outlined);
}

void TestMainWindow::draggingABodyMovesItAsOneUndoEntry() {
    interplay::Viewport* viewport = m_window->viewport();
    interplay::SceneDocument* document = m_window->document();
    const simcore::Vec3 start = document->body(2).body.position;
    const QPoint from = pixelOf(*viewport, bodyCenter(*document, 2));
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport, from + QPoint(8 * i, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, from + QPoint(80, 0));

    const simcore::Vec3 end = document->body(2).body.position;
    QVERIFY2(glm::length(end - start) > 0.2f, "the body should have moved");
    QCOMPARE(end.y, start.y);  // on a horizontal plane
    QCOMPARE(document->undoStack()->count(), 1);
    QCOMPARE(document->undoStack()->undoText(), QString("Move %1").arg(document->bodyName(2)));
    // The running world shows the new authored position.
    const simcore::BodyId id = m_window->simulation()->bodyIds()[2];
    QVERIFY(glm::length(m_window->simulation()->world()->position(id) - end) < 1e-4f);
    document->undoStack()->undo();
    QCOMPARE(document->body(2).body.position, start);
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::playStepResetLeaveTheAuthoredSceneIntact() {
    interplay::SimulationController* simulation = m_window->simulation();
    const std::string authored = sceneText(m_window->document()->scene());
    m_window->action("step")->trigger();
    QCOMPARE(simulation->world()->stepCount(), std::uint64_t(1));
    m_window->action("play")->trigger();
    QVERIFY(simulation->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(simulation->world()->stepCount() > 20, 5000);
    m_window->action("play")->trigger();
    QVERIFY(!simulation->isPlaying());
    const simcore::BodyId box = simulation->bodyIds()[1];
    QVERIFY(glm::length(simulation->world()->position(box) - m_window->document()->body(1).body.position) > 0.01f);
    QCOMPARE(sceneText(m_window->document()->scene()), authored);
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->document()->undoStack()->count(), 0);

    m_window->action("reset")->trigger();
    QCOMPARE(simulation->world()->stepCount(), std::uint64_t(0));
    QVERIFY(glm::length(simulation->world()->position(box) - m_window->document()->body(1).body.position) < 1e-5f);
    QCOMPARE(sceneText(m_window->document()->scene()), authored);
}

// The last line of defence. No valid scene takes the engine to a non-finite state any more (the
// joint solver drops an overflowing result and every velocity is bounded: test_joints, test_limits
// and the soak check that), so the fault is injected: a NaN written into the live world's storage,
// as a future engine bug would leave it (support/fault_injection.h). The window must stop playing,
// say which body went wrong, and leave the document as it was; Reset gives a clean world back.
void TestMainWindow::nonFiniteStateStopsPlaybackWithAMessage() {
    interplay::SimulationController* simulation = m_window->simulation();
    const std::string authored = sceneText(m_window->document()->scene());
    m_window->action("step")->trigger();
    const simcore::BodyId box = simulation->bodyIds()[1];
    simcore::WorldFaultInjection::poisonLinearVelocity(const_cast<simcore::World&>(*simulation->world()), box);

    m_window->action("play")->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!simulation->isPlaying(), 5000);
    QCOMPARE(m_prompts.errors.size(), 1);
    const QString name = QString::fromStdString(simulation->world()->name(box));
    QVERIFY2(m_prompts.errors[0].contains("non-finite") && m_prompts.errors[0].contains('"' + name + '"'),
             qPrintable(m_prompts.errors[0]));
    QCOMPARE(sceneText(m_window->document()->scene()), authored);
    QVERIFY(!m_window->isWindowModified());

    m_window->action("reset")->trigger();
    QVERIFY(!simulation->world()->findNonFiniteBody());
    QCOMPARE(simulation->world()->stepCount(), std::uint64_t(0));
}

void TestMainWindow::grabbingWhilePlayingPullsTheBody() {
    interplay::SimulationController* simulation = m_window->simulation();
    interplay::Viewport* viewport = m_window->viewport();
    simulation->stepFrames(90);  // let everything land
    const simcore::BodyId sphere = simulation->bodyIds()[2];
    const simcore::Vec3 before = simulation->world()->position(sphere);
    const QPoint at = pixelOf(*viewport, simulation->world()->centerOfMass(sphere));
    QVERIFY(viewport->pick(at).has_value());
    simulation->play();
    QTest::mousePress(viewport, Qt::LeftButton, {}, at);
    QVERIFY(simulation->isGrabbing());
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport, at - QPoint(0, 10 * i));  // pull up
    QTRY_VERIFY_WITH_TIMEOUT(simulation->world()->position(sphere).y > before.y + 0.3f, 5000);
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, at - QPoint(0, 100));
    QVERIFY(!simulation->isGrabbing());
    simulation->pause();
    QCOMPARE(m_window->document()->undoStack()->count(), 0);  // grabbing is not an edit
}

void TestMainWindow::applySimulatedPoseIsUndoable() {
    interplay::SimulationController* simulation = m_window->simulation();
    const simcore::Vec3 authored = m_window->document()->body(1).body.position;
    simulation->stepFrames(60);
    const simcore::Vec3 simulated = simulation->world()->position(simulation->bodyIds()[1]);
    m_window->action("applyPose")->trigger();
    QCOMPARE(m_window->document()->body(1).body.position, simulated);
    QCOMPARE(m_window->document()->undoStack()->undoText(), QString("Apply Simulated Pose"));
    QVERIFY(m_window->isWindowModified());
    m_window->document()->undoStack()->undo();
    QCOMPARE(m_window->document()->body(1).body.position, authored);
}

void TestMainWindow::addDuplicateDeleteActions() {
    interplay::SceneDocument* document = m_window->document();
    QUndoStack* stack = document->undoStack();
    const int count = document->bodyCount();
    m_window->action("addBox")->trigger();
    QCOMPARE(document->bodyCount(), count + 1);
    QCOMPARE(document->bodyName(count), QString("Box 1"));
    QCOMPARE(stack->undoText(), QString("Add Box 1"));
    QCOMPARE(m_window->simulation()->bodyIds().size(), std::size_t(count + 1));  // the world follows

    m_window->action("duplicate")->trigger();
    QCOMPARE(document->bodyName(count + 1), QString("Box 2"));
    QCOMPARE(stack->undoText(), QString("Duplicate Box 1"));
    QCOMPARE(document->selectedBodies(), QList<int>{count + 1});
    // Beside the original, not inside it.
    QVERIFY(document->body(count + 1).body.position.x - document->body(count).body.position.x >= 1.0f);

    document->setSelectedBodies({1, count});
    m_window->action("delete")->trigger();
    QCOMPARE(document->bodyCount(), count);
    QCOMPARE(stack->undoText(), QString("Delete 2 Bodies"));
    QCOMPARE(stack->count(), 3);
    stack->undo();
    QCOMPARE(document->bodyCount(), count + 2);
    QCOMPARE(m_window->simulation()->bodyIds().size(), std::size_t(count + 2));
}

// The keys a user presses, through Qt's shortcut map to SceneActions and the DocumentManager.
void TestMainWindow::shortcutsReachTheSceneActionsAndFileCommands() {
    interplay::SceneDocument* document = m_window->document();
    QUndoStack* stack = document->undoStack();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    const int count = document->bodyCount();
    document->setSelectedBodies({1});
    const QString name = document->bodyName(1);

    QTest::keyClick(m_window.get(), Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(document->bodyCount(), count + 1);
    QCOMPARE(stack->undoText(), "Duplicate " + name);
    QCOMPARE(document->selectedBodies(), QList<int>{count});
    const QString copy = document->bodyName(count);
    QTest::keyClick(m_window.get(), Qt::Key_Delete);
    QCOMPARE(document->bodyCount(), count);
    QCOMPARE(stack->undoText(), "Delete " + copy);
    QTest::keyClick(m_window.get(), Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(document->selectedBodies().size(), count);

    // Ctrl+S on an untitled scene asks where, saves there and lists the file under Open Recent.
    const QString path = m_dir.filePath("shortcut.json");
    m_prompts.fileAnswer = path;
    QTest::keyClick(m_window.get(), Qt::Key_S, Qt::ControlModifier);
    QCOMPARE(document->filePath(), path);
    QVERIFY(!m_window->isWindowModified());
    auto* recent = m_window->findChild<QMenu*>("recentMenu");
    QCOMPARE(recent->actions().first()->toolTip(), path);

    // Ctrl+N starts an untitled scene; the recent entry brings the saved one back; Ctrl+O opens another.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier);
    QVERIFY(document->filePath().isEmpty());
    QCOMPARE(m_window->windowTitle(), QString("[*]Untitled — Interplay"));
    recent->actions().first()->trigger();
    QCOMPARE(document->filePath(), path);
    QCOMPARE(document->bodyCount(), count);
    m_prompts.fileAnswer = INTERPLAY_SOURCE_DIR "/scenes/incline.json";
    QTest::keyClick(m_window.get(), Qt::Key_O, Qt::ControlModifier);
    QCOMPARE(document->filePath(), m_prompts.fileAnswer);
    QCOMPARE(m_window->documentManager()->recentFiles(), (QStringList{m_prompts.fileAnswer, path}));
    QCOMPARE(m_prompts.unsavedAsked, 0);  // nothing was unsaved at any point
}

void TestMainWindow::treeSelectionFollowsTheDocument() {
    QTreeView* tree = m_window->sceneTree();
    interplay::SceneTreeModel* model = m_window->sceneTreeModel();
    m_window->document()->setSelectedBodies({3});
    const QModelIndexList rows = tree->selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(model->bodyIndexOf(rows.first()), 3);
    tree->selectionModel()->select(model->indexOfBody(1), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QCOMPARE(m_window->document()->selectedBodies(), QList<int>{1});
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::throwSpawnsIntoTheRunningWorldOnly() {
    interplay::SimulationController* simulation = m_window->simulation();
    const std::string authored = sceneText(m_window->document()->scene());
    const std::size_t before = simulation->bodyIds().size();
    m_window->action("throw")->trigger();
    QCOMPARE(simulation->bodyIds().size(), before + 1);
    QVERIFY(simulation->isPlaying());
    const simcore::BodyId thrown = simulation->bodyIds().back();
    const simcore::Vec3 velocity = simulation->world()->linearVelocity(thrown);
    QVERIFY(glm::dot(glm::normalize(velocity), m_window->viewport()->camera().forward()) > 0.99f);
    QCOMPARE(simulation->sceneIndexOf(thrown), -1);
    QCOMPARE(sceneText(m_window->document()->scene()), authored);
    m_window->action("reset")->trigger();
    QCOMPARE(simulation->bodyIds().size(), before);
}

void TestMainWindow::editsWhilePausedKeepTheRun() {
    interplay::SimulationController* simulation = m_window->simulation();
    interplay::SceneDocument* document = m_window->document();
    interplay::InspectorPanel* inspector = m_window->inspector();
    simulation->stepFrames(40);  // mid-fall: every dynamic body is moving
    const simcore::World* world = simulation->world();
    QSignalSpy rebuilt(simulation, &interplay::SimulationController::worldRebuilt);
    const auto run = liveStates(*world);
    const std::string sphereName = document->body(2).body.name;
    const simcore::BodyId sphereId = simulation->bodyIds()[2];
    // Every body of the run but the sphere and `edited` is where the run left it.
    const auto othersUnchanged = [&](const std::map<std::string, LiveState>& now, const std::string& edited = {}) {
        for (const auto& [name, state] : run) {
            if (name != sphereName && name != edited && now.count(name) && !(now.at(name) == state)) return false;
        }
        return true;
    };

    // Friction: the live sphere takes the new friction and keeps its id and state.
    document->setSelectedBodies({2});
    typeInto(inspector->numberField("friction"), "0.05");
    QCOMPARE(document->body(2).body.friction, 0.05f);
    QCOMPARE(simulation->world(), world);
    QCOMPARE(world->stepCount(), std::uint64_t(40));
    const simcore::BodyId sphere = simulation->bodyIds()[2];
    QCOMPARE(world->friction(sphere), 0.05f);
    QCOMPARE(simulation->bodyIds()[2], sphereId);
    QVERIFY(liveStates(*world) == run);  // nobody moved, the sphere included

    // Rolling resistance: the same, with the new coefficient.
    typeInto(inspector->numberField("rollingResistance"), "0.2");
    QCOMPARE(document->body(2).body.rollingResistance, 0.2f);
    QCOMPARE(simulation->world(), world);
    QCOMPARE(simulation->bodyIds()[2], sphereId);
    QCOMPARE(world->rollingResistance(sphereId), 0.2f);
    QVERIFY(liveStates(*world) == run);

    // Colour: drawn differently, nothing else.
    simcore::SceneBody red = document->body(2);
    red.color = simcore::Vec3(1, 0, 0);
    document->undoStack()->push(new interplay::ChangeBodies(document, "Colour", interplay::BodyField::Color, {2}, {red}));
    QCOMPARE(simulation->authoredColors()[2], std::optional<simcore::Vec3>(simcore::Vec3(1, 0, 0)));
    QVERIFY(liveStates(*world) == run);

    // A move moves the sphere from where the run left it, by as much as the authored one moved.
    const simcore::Vec3 liveBefore = world->position(simulation->bodyIds()[2]);
    typeInto(inspector->numberField("position.x"), QString::number(document->body(2).body.position.x + 1.5f));
    const simcore::Vec3 liveAfter = world->position(simulation->bodyIds()[2]);
    QVERIFY2(glm::length(liveAfter - (liveBefore + simcore::Vec3(1.5f, 0, 0))) < 1e-4f, "moved by the edit");
    QVERIFY(othersUnchanged(liveStates(*world)));

    // Adding and deleting bodies: only they come and go.
    m_window->action("addBox")->trigger();
    QCOMPARE(world->bodyCount(), run.size() + 1);
    QVERIFY(world->contains(simulation->bodyIds().back()));
    QCOMPARE(world->position(simulation->bodyIds().back()), document->body(document->bodyCount() - 1).body.position);
    QVERIFY(othersUnchanged(liveStates(*world)));
    const std::string capsule = document->body(3).body.name;
    const simcore::Vec3 capsuleLive = world->position(simulation->bodyIds()[3]);
    document->setSelectedBodies({3});
    m_window->action("delete")->trigger();
    QCOMPARE(world->bodyCount(), run.size());
    auto afterDelete = liveStates(*world);
    QVERIFY(!afterDelete.count(capsule));
    QVERIFY(othersUnchanged(afterDelete));
    // Undo brings the capsule back where the run had it; the rest of the run goes on from where it was.
    document->undoStack()->undo();
    QCOMPARE(world->position(simulation->bodyIds()[3]), capsuleLive);
    QVERIFY(capsuleLive != document->body(3).body.position);
    QVERIFY(othersUnchanged(liveStates(*world), capsule));
    QCOMPARE(rebuilt.count(), 0);
    QCOMPARE(world->stepCount(), std::uint64_t(40));
    // The scene Reset returns to is the document's.
    QCOMPARE(sceneText(simulation->authoredScene()), sceneText(document->scene()));
    m_window->action("reset")->trigger();
    QCOMPARE(simulation->world()->position(simulation->bodyIds()[2]), document->body(2).body.position);
}

void TestMainWindow::jointAddedWhilePausedHoldsTheBodiesWhereTheyAre() {
    interplay::SimulationController* simulation = m_window->simulation();
    interplay::SceneDocument* document = m_window->document();
    simulation->stepFrames(60);  // landed, turned, away from their authored poses
    const simcore::World* world = simulation->world();
    const auto run = liveStates(*world);
    document->setSelectedBodies({2, 3});  // sphere and capsule
    m_window->action("addBallJoint")->trigger();
    QCOMPARE(document->jointCount(), 1);
    QCOMPARE(world->jointCount(), std::size_t(1));
    QCOMPARE(world->stepCount(), std::uint64_t(60));
    QVERIFY(liveStates(*world) == run);
    // The anchor sits on the sphere where it was authored relative to it, carried to its live pose.
    const simcore::SceneJoint& joint = document->joint(0);
    const simcore::BodyCreationSettings& sphere = document->body(2).body;
    const simcore::Vec3 authoredLocal = glm::inverse(sphere.orientation) * (joint.joint.anchor - sphere.position);
    const simcore::JointId live = simulation->jointIds()[0];
    const simcore::BodyId liveA = world->jointBodyA(live);
    const simcore::Vec3 liveAnchor = world->centerOfMass(liveA) + world->orientation(liveA) * world->jointLocalAnchorA(live);
    const simcore::Vec3 liveLocal = glm::inverse(world->orientation(liveA)) * (liveAnchor - world->position(liveA));
    QVERIFY2(glm::length(liveLocal - authoredLocal) < 1e-4f, "the anchor follows body A");
    QVERIFY(world->jointError(simulation->jointIds()[0]).position < 1e-4f);  // satisfied where the bodies are
    // A change of the joint reaches the live one through its setter; undo and redo follow.
    simcore::SceneJoint rigid = joint;
    rigid.joint.collideConnected = true;
    document->undoStack()->push(new interplay::ChangeJoints(document, "Collide", interplay::JointField::CollideConnected, {0}, {rigid}));
    QCOMPARE(world->jointCollidesConnected(simulation->jointIds()[0]), true);
    document->undoStack()->undo();
    document->undoStack()->undo();
    QCOMPARE(world->jointCount(), std::size_t(0));
    QVERIFY(liveStates(*world) == run);
}

void TestMainWindow::draggingInABigSceneMovesOneBodyInPlace() {
    QString error;
    QVERIFY2(m_window->documentManager()->openFile(INTERPLAY_SOURCE_DIR "/scenes/pile1k.json", &error),
             qPrintable(error));
    interplay::Viewport* viewport = m_window->viewport();
    interplay::SceneDocument* document = m_window->document();
    interplay::SimulationController* simulation = m_window->simulation();
    QVERIFY(document->bodyCount() >= 1000);
    viewport->grabViewport();  // frames the scene
    QPoint from;
    int dragged = -1;
    for (int y = viewport->height() / 3; y < viewport->height() && dragged < 1; y += 9) {
        for (int x = viewport->width() / 3; x < 2 * viewport->width() / 3 && dragged < 1; x += 9) {
            from = QPoint(x, y);
            dragged = viewport->sceneBodyAt(from);
        }
    }
    QVERIFY2(dragged >= 1, "a body under the cursor");
    const simcore::World* world = simulation->world();
    const auto before = liveStates(*world);
    const std::string name = document->body(dragged).body.name;
    QSignalSpy rebuilt(simulation, &interplay::SimulationController::worldRebuilt);
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    for (int i = 1; i <= 20; ++i) QTest::mouseMove(viewport, from + QPoint(3 * i, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, from + QPoint(60, 0));

    // One undo entry, the same world, one body moved: no rebuild on any mouse move.
    QCOMPARE(document->undoStack()->count(), 1);
    QCOMPARE(rebuilt.count(), 0);
    QCOMPARE(simulation->world(), world);
    const simcore::BodyId id = simulation->bodyIds()[std::size_t(dragged)];
    QVERIFY(glm::length(world->position(id) - document->body(dragged).body.position) < 1e-4f);
    QVERIFY(glm::length(world->position(id) - before.at(name).position) > 0.1f);
    auto after = liveStates(*world);
    after.erase(name);
    auto others = before;
    others.erase(name);
    QVERIFY(after == others);

    // The first step runs the edited scene exactly as saved: the world is built afresh once.
    simulation->stepFrames(1);
    QCOMPARE(rebuilt.count(), 1);
    simcore::Scene scene = document->scene();
    simcore::BuiltWorld fresh = simcore::buildWorld(scene);
    fresh.world.step();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        QCOMPARE(simulation->world()->position(simulation->bodyIds()[i]), fresh.world.position(fresh.bodyIds[i]));
    }
}

void TestMainWindow::addJointActionsFollowTheSelection() {
    interplay::SceneDocument* document = m_window->document();
    QAction* hinge = m_window->action("addHingeJoint");
    QVERIFY(hinge);
    document->setSelectedBodies({});
    QVERIFY(!hinge->isEnabled());
    QVERIFY2(hinge->statusTip().contains("Select two bodies"), qPrintable(hinge->statusTip()));
    document->setSelectedBodies({1, 2, 3});
    QVERIFY(!hinge->isEnabled());
    document->setSelectedBodies({0});  // the ground: nothing for a joint to move
    QVERIFY(!hinge->isEnabled());
    QVERIFY2(hinge->statusTip().contains("dynamic"), qPrintable(hinge->statusTip()));

    document->setSelectedBodies({1, 2});
    QVERIFY(hinge->isEnabled());
    QCOMPARE(hinge->statusTip(), QString("Join %1 and %2 with a hinge joint").arg(document->bodyName(1), document->bodyName(2)));
    hinge->trigger();
    QCOMPARE(document->jointCount(), 1);
    QCOMPARE(document->undoStack()->undoText(), QString("Add Hinge Joint"));
    QCOMPARE(document->selectedJoints(), QList<int>{0});
    QCOMPARE(m_window->simulation()->world()->jointCount(), std::size_t(1));
    QVERIFY(m_window->inspector()->numberField("axis.x")->isVisibleTo(m_window->inspector()));

    document->setSelectedBodies({4});
    QVERIFY(m_window->action("addSliderJoint")->statusTip().contains("to the world"));
    m_window->action("addSliderJoint")->trigger();
    QCOMPARE(document->jointCount(), 2);
    QVERIFY(!document->joint(1).bodyB);
    // The Add menu lists every kind.
    auto* menu = m_window->findChild<QMenu*>("addJointMenu");
    QVERIFY(menu);
    QCOMPARE(menu->actions().size(), 5);

    document->undoStack()->undo();
    document->undoStack()->undo();
    QCOMPARE(m_window->simulation()->world()->jointCount(), std::size_t(0));
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::deletingABodyTakesItsJointsInOneStep() {
    interplay::SceneDocument* document = m_window->document();
    const simcore::World* world = m_window->simulation()->world();
    document->setSelectedBodies({1, 2});
    m_window->action("addHingeJoint")->trigger();
    document->setSelectedBodies({2, 3});
    m_window->action("addDistanceJoint")->trigger();
    QCOMPARE(world->jointCount(), std::size_t(2));
    const int entries = document->undoStack()->count();

    document->setSelectedBodies({2});  // the sphere: in both joints
    m_window->action("delete")->trigger();
    QCOMPARE(document->jointCount(), 0);
    QCOMPARE(world->jointCount(), std::size_t(0));
    QCOMPARE(document->undoStack()->count(), entries + 1);
    document->undoStack()->undo();
    QCOMPARE(document->jointCount(), 2);
    QCOMPARE(world->jointCount(), std::size_t(2));
    QCOMPARE(document->joint(1).bodyA, std::size_t(2));

    // Delete on a selected joint deletes just it.
    document->setSelectedJoints({1});
    m_window->action("delete")->trigger();
    QCOMPARE(document->undoStack()->undoText(), QString("Delete Joint 2"));
    QCOMPARE(document->jointCount(), 1);
    QCOMPARE(document->bodyCount(), 6);
    QCOMPARE(world->jointCount(), std::size_t(1));
}

void TestMainWindow::jointsAreSelectedInTheTreeAndDrawnHighlighted() {
    interplay::SceneDocument* document = m_window->document();
    QTreeView* tree = m_window->sceneTree();
    interplay::SceneTreeModel* model = m_window->sceneTreeModel();
    interplay::Viewport* viewport = m_window->viewport();
    document->setSelectedBodies({1, 2});
    m_window->action("addHingeJoint")->trigger();
    document->setSelection({}, {});
    const QImage plain = viewport->grabViewport();

    tree->selectionModel()->select(model->indexOfJoint(0), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QCOMPARE(document->selectedJoints(), QList<int>{0});
    QVERIFY(document->selectedBodies().isEmpty());
    const QImage highlighted = viewport->grabViewport();
    int differing = 0;
    for (int y = 0; y < plain.height(); ++y) {
        for (int x = 0; x < plain.width(); ++x) differing += plain.pixel(x, y) != highlighted.pixel(x, y);
    }
    QVERIFY2(differing > 50, qPrintable(QString("%1 pixels differ").arg(differing)));

    // And back: the document's selection shows in the tree.
    document->setSelectedBodies({3});
    document->setSelectedJoints({0});
    const QModelIndexList rows = tree->selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(model->jointIndexOf(rows.first()), 0);
    QCOMPARE(document->undoStack()->count(), 1);
}

void TestMainWindow::clickingAJointSelectsIt() {
    interplay::SceneDocument* document = m_window->document();
    interplay::Viewport* viewport = m_window->viewport();
    QTreeView* tree = m_window->sceneTree();
    interplay::SceneTreeModel* model = m_window->sceneTreeModel();
    document->setSelectedBodies({1, 2});
    m_window->action("addHingeJoint")->trigger();  // anchored midway between the two bodies
    document->setSelectedBodies({4});
    m_window->action("addDistanceJoint")->trigger();  // hangs the cylinder from a point above it
    document->setSelection({}, {});
    const int entries = document->undoStack()->count();

    // The hinge's anchor is drawn over the floor: the joint wins the click over the body behind it.
    const QPoint hinge = pixelOf(*viewport, document->joint(0).joint.anchor);
    QCOMPARE(viewport->sceneBodyAt(hinge), 0);
    QTest::mouseClick(viewport, Qt::LeftButton, {}, hinge);
    QCOMPARE(document->selectedJoints(), QList<int>{0});
    QVERIFY(document->selectedBodies().isEmpty());
    // As a selection made in the tree: the tree shows the joint's row, the Inspector its form.
    const QModelIndexList rows = tree->selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(model->jointIndexOf(rows.first()), 0);
    QVERIFY(m_window->inspector()->jointNameField()->isVisibleTo(m_window->inspector()));
    QCOMPARE(m_window->inspector()->jointNameField()->text(), document->jointName(0));

    // A body away from the joints is picked as before.
    const QPoint sphere = pixelOf(*viewport, bodyCenter(*document, 2));
    QVERIFY(!viewport->pickJoint(sphere));
    QTest::mouseClick(viewport, Qt::LeftButton, {}, sphere);
    QCOMPARE(document->selectedBodies(), QList<int>{2});
    QVERIFY(document->selectedJoints().isEmpty());

    // A few pixels off the anchor still picks the joint (a dozen do not); Ctrl-click adds the
    // distance joint, picked on its rod between the anchors, and Shift-click takes the hinge out.
    QVERIFY(!viewport->pickJoint(hinge + QPoint(12, 0)));
    QTest::mouseClick(viewport, Qt::LeftButton, {}, hinge + QPoint(5, -4));
    QCOMPARE(document->selectedJoints(), QList<int>{0});
    const simcore::JointCreationSettings& rod = document->joint(1).joint;
    const QPoint alongRod = pixelOf(*viewport, glm::mix(rod.anchor, rod.anchorB, 0.75f));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier, alongRod);
    QCOMPARE(document->selectedJoints(), (QList<int>{0, 1}));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, hinge);
    QCOMPARE(document->selectedJoints(), QList<int>{1});

    // Dragging from a joint turns the camera; it moves no body.
    const std::string authored = sceneText(document->scene());
    const glm::vec3 eye = viewport->camera().eye();
    QTest::mousePress(viewport, Qt::LeftButton, {}, hinge);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(viewport, hinge + QPoint(8 * i, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, hinge + QPoint(40, 0));
    QVERIFY(glm::length(viewport->camera().eye() - eye) > 1e-3f);
    QCOMPARE(sceneText(document->scene()), authored);
    QCOMPARE(document->selectedJoints(), QList<int>{1});  // a drag is no click

    // The sky, far from every joint and body: the selection clears.
    const QPoint sky(viewport->width() / 2, 3);
    QVERIFY(!viewport->pickJoint(sky));
    QCOMPARE(viewport->sceneBodyAt(sky), -1);
    QTest::mouseClick(viewport, Qt::LeftButton, {}, sky);
    QVERIFY(document->selectedJoints().isEmpty());
    QVERIFY(document->selectedBodies().isEmpty());
    QCOMPARE(document->undoStack()->count(), entries);

    // A joint to the world is anchored at its body's origin, inside the body: the body keeps the
    // click there (and can still be dragged from its centre), and a click on it once it is selected
    // picks the joint; the next click goes back to the body.
    document->setSelectedBodies({3});
    m_window->action("addBallJoint")->trigger();
    const int ball = document->jointCount() - 1;
    const QPoint centre = pixelOf(*viewport, document->joint(ball).joint.anchor);
    QVERIFY(viewport->pickJoint(centre));
    document->setSelection({}, {});
    QTest::mouseClick(viewport, Qt::LeftButton, {}, centre);
    QCOMPARE(document->selectedBodies(), QList<int>{3});
    QTest::mouseClick(viewport, Qt::LeftButton, {}, centre);
    QCOMPARE(document->selectedJoints(), QList<int>{ball});
    QVERIFY(document->selectedBodies().isEmpty());
    QTest::mouseClick(viewport, Qt::LeftButton, {}, centre);
    QCOMPARE(document->selectedBodies(), QList<int>{3});
    const simcore::Vec3 before = document->body(3).body.position;
    QTest::mousePress(viewport, Qt::LeftButton, {}, centre);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(viewport, centre + QPoint(8 * i, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, centre + QPoint(40, 0));
    QVERIFY(glm::length(document->body(3).body.position - before) > 0.05f);
}

void TestMainWindow::overlaysAndSleepingTintAreDrawn() {
    interplay::Viewport* viewport = m_window->viewport();
    interplay::DebugDrawOptions* options = m_window->debugDrawOptions();
    const auto differingPixels = [](const QImage& a, const QImage& b) {
        int count = 0;
        for (int y = 0; y < a.height(); y += 2) {
            for (int x = 0; x < a.width(); x += 2) count += a.pixel(x, y) != b.pixel(x, y);
        }
        return count;
    };
    m_window->simulation()->stepFrames(60);  // landed: contacts exist
    const QImage plain = viewport->grabViewport();
    QCOMPARE(differingPixels(plain, viewport->grabViewport()), 0);  // rendering is repeatable
    options->setProperty("aabbs", true);
    QVERIFY(differingPixels(plain, viewport->grabViewport()) > 200);
    options->setProperty("aabbs", false);
    options->setProperty("contactPoints", true);
    options->setProperty("contactNormals", true);
    QVERIFY(m_window->simulation()->world()->contactCount() > 0);
    QVERIFY(differingPixels(plain, viewport->grabViewport()) > 50);
    options->setProperty("contactPoints", false);
    options->setProperty("contactNormals", false);

    // Asleep after a few seconds at rest: the tint greys the bodies.
    m_window->simulation()->stepFrames(400);
    const simcore::World* world = m_window->simulation()->world();
    QVERIFY(!world->isAwake(m_window->simulation()->bodyIds()[2]));
    const QImage tinted = viewport->grabViewport();
    options->setProperty("sleepingTint", false);
    QVERIFY(differingPixels(tinted, viewport->grabViewport()) > 500);
}

void TestMainWindow::qmlPanelLoadsAndChangesTheWorld() {
    interplay::SimulationSettingsPanel* panel = m_window->settingsPanel();
    QQuickWidget* quick = panel->quickWidget();
    QCOMPARE(quick->status(), QQuickWidget::Ready);
    QVERIFY2(panel->errors().isEmpty(), qPrintable(panel->errors().isEmpty() ? QString() : panel->errors().first().toString()));
    QVERIFY(quick->rootObject());
    auto* dock = m_window->findChild<QDockWidget*>("settingsDock");
    dock->show();
    dock->raise();
    QTRY_VERIFY(quick->isVisible() && quick->width() > 100);

    // Scroll the panel until the control is in view, as a user would.
    const auto scrollTo = [](QQuickItem* item) {
        for (QQuickItem* ancestor = item->parentItem(); ancestor; ancestor = ancestor->parentItem()) {
            if (!ancestor->inherits("QQuickFlickable")) continue;
            auto* content = qvariant_cast<QQuickItem*>(ancestor->property("contentItem"));
            const double top = item->mapToItem(content, QPointF(0, 0)).y();
            ancestor->setProperty("contentY", std::max(0.0, top - 20.0));
            break;
        }
        QTest::qWait(50);
    };
    const auto clickItem = [quick, scrollTo](QQuickItem* item, QPointF at) {
        scrollTo(item);
        const QPointF scene = item->mapToScene(at);
        QTest::mouseClick(quick, Qt::LeftButton, {}, scene.toPoint());
    };

    // Every setting of the schema has its editor in the panel (a vector one per component).
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const QString name = "setting_" + QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size()));
        if (info.type != simcore::SettingType::Vec3) QVERIFY2(findItem(quick->rootObject(), name), qPrintable(name));
        for (int i = 0; info.type == simcore::SettingType::Vec3 && i < 3; ++i)
            QVERIFY2(findItem(quick->rootObject(), name + "." + QString::number(i)), qPrintable(name));
    }

    // Typing a value the loader would refuse (the bug report's gravity 1e9) changes nothing and says why.
    auto* gravityY = findItem(quick->rootObject(), "setting_gravity.1");
    QVERIFY(gravityY);
    const float gravityBefore = m_window->document()->scene().settings.gravity.y;
    const int entriesBefore = m_window->document()->undoStack()->count();
    gravityY->setProperty("text", "1e9");
    QVERIFY(QMetaObject::invokeMethod(gravityY, "editingFinished"));
    QCOMPARE(m_window->document()->scene().settings.gravity.y, gravityBefore);
    QCOMPARE(m_window->document()->undoStack()->count(), entriesBefore);
    QVERIFY2(m_window->statusBar()->currentMessage().contains("gravity[1] must be between -10000 and 10000"),
             qPrintable(m_window->statusBar()->currentMessage()));
    QCOMPARE(gravityY->property("text").toString(), QString::number(double(gravityBefore)));

    // Dragging the gravity label sideways scales gravity: the whole drag is one history entry.
    auto* gravityLabel = findItem(quick->rootObject(), "label_gravity");
    QVERIFY(gravityLabel);
    scrollTo(gravityLabel);
    const QPoint from = gravityLabel->mapToScene(QPointF(10, gravityLabel->height() / 2)).toPoint();
    QTest::mousePress(quick, Qt::LeftButton, {}, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(quick, from + QPoint(8 * i, 0));
    QTest::mouseRelease(quick, Qt::LeftButton, {}, from + QPoint(80, 0));
    QTRY_VERIFY(m_window->document()->scene().settings.gravity.y < gravityBefore * 1.2f);
    QCOMPARE(m_window->document()->undoStack()->count(), entriesBefore + 1);
    QCOMPARE(m_window->document()->undoStack()->undoText(), QString("Change Gravity"));
    QCOMPARE(m_window->simulation()->world()->settings().gravity, m_window->document()->scene().settings.gravity);
    m_window->document()->undoStack()->undo();
    QCOMPARE(m_window->document()->scene().settings.gravity.y, gravityBefore);

    // The substeps spin box's "up" indicator: one more substep, in the document and the world.
    auto* substeps = findItem(quick->rootObject(), "setting_substeps");
    QVERIFY(substeps);
    const int before = m_window->document()->scene().settings.substeps;
    QCOMPARE(substeps->property("value").toInt(), before);
    auto* up = qvariant_cast<QQuickItem*>(qvariant_cast<QObject*>(substeps->property("up"))->property("indicator"));
    QVERIFY(up);
    clickItem(up, QPointF(up->width() / 2, up->height() / 2));
    QTRY_COMPARE(m_window->document()->scene().settings.substeps, before + 1);
    QCOMPARE(m_window->simulation()->world()->settings().substeps, before + 1);
    QCOMPARE(m_window->document()->undoStack()->undoText(), QString("Change Substeps"));
    // Undo reaches the panel.
    m_window->document()->undoStack()->undo();
    QTRY_COMPARE(substeps->property("value").toInt(), before);
    QCOMPARE(m_window->simulation()->world()->settings().substeps, before);

    // An effect check box switches the effect off in the running world.
    auto* friction = findItem(quick->rootObject(), "setting_effects.friction");
    QVERIFY(friction);
    QVERIFY(friction->property("checked").toBool());
    clickItem(friction, QPointF(friction->height() / 2, friction->height() / 2));
    QTRY_VERIFY(!m_window->simulation()->world()->settings().effects[simcore::Effect::Friction]);
    QVERIFY(!friction->property("checked").toBool());

    // A debug-draw box is a view option: the viewport draws contacts, the document stays clean of it.
    auto* contacts = findItem(quick->rootObject(), "drawContactPointsCheckBox");
    QVERIFY(contacts);
    const int entries = m_window->document()->undoStack()->count();
    clickItem(contacts, QPointF(contacts->height() / 2, contacts->height() / 2));
    QTRY_VERIFY(m_window->debugDrawOptions()->contactPoints());
    QCOMPARE(m_window->document()->undoStack()->count(), entries);
}

void TestMainWindow::profilerShowsTheLatestStep() {
    interplay::ProfilerPanel* profiler = m_window->profiler();
    QCOMPARE(profiler->figure("msPerStep"), QString("–"));
    m_window->simulation()->stepFrames(5);
    QVERIFY2(profiler->figure("msPerStep").endsWith(" ms"), qPrintable(profiler->figure("msPerStep")));
    QVERIFY(profiler->figure("awakeBodies").contains("of 5 dynamic"));
    QCOMPARE(m_window->simulation()->series().size(), std::size_t(5));
    // The skipped stages are named as the stage table names them, and are the step's.
    QStringList expected;
    const simcore::StepProfile& profile = m_window->simulation()->world()->lastStepProfile();
    for (const simcore::StageInfo& info : simcore::kStages)
        if (profile.skipped[static_cast<std::size_t>(info.stage)] != simcore::StageSkip::Ran)
            expected << QString::fromLatin1(info.name.data(), static_cast<qsizetype>(info.name.size()));
    QCOMPARE(profiler->figure("skippedStages"), expected.isEmpty() ? QString("none") : expected.join(", "));

    // An edit while paused reaches the running world and the figures, without another step.
    const QString before = profiler->figure("potentialEnergy");
    m_window->action("addBox")->trigger();
    const double potential = m_window->simulation()->world()->potentialEnergy();
    QTRY_COMPARE(profiler->figure("potentialEnergy"), QString("%1 J").arg(potential, 0, 'f', 3));
    QVERIFY2(profiler->figure("potentialEnergy") != before, qPrintable(before));
}

void TestMainWindow::statusBarAndProfilerCountTheSameBodies() {
    // The default scene: a static ground and five dynamic bodies. Both places count the dynamic
    // ones, awake of all, before the first step and after.
    interplay::ProfilerPanel* profiler = m_window->profiler();
    auto* status = m_window->statusBar()->findChild<QLabel*>("awakeBodiesLabel");
    QVERIFY(status);
    m_window->action("reset")->trigger();
    QCOMPARE(m_window->simulation()->world()->stepCount(), std::uint64_t(0));
    QCOMPARE(status->text(), QString("5 / 5 awake"));
    QCOMPARE(profiler->figure("awakeBodies"), QString("5 of 5 dynamic"));
    // A body added before the first step is part of the scene the run starts from: no energy change.
    m_window->action("addBox")->trigger();
    QTRY_COMPARE(status->text(), QString("6 / 6 awake"));
    QCOMPARE(profiler->figure("awakeBodies"), QString("6 of 6 dynamic"));
    QCOMPARE(profiler->figure("energyChange"), QString("0.000 J"));
    // Asleep is counted in both: a world stepped until it rests.
    m_window->simulation()->stepFrames(600);
    const interplay::SimulationController::AwakeCount count = m_window->simulation()->awakeCount();
    QVERIFY2(count.awake < count.dynamic, "something in the default scene falls asleep in 10 s");
    QTRY_COMPARE(status->text(), QString("%1 / 6 awake").arg(count.awake));
    QCOMPARE(profiler->figure("awakeBodies"), QString("%1 of 6 dynamic").arg(count.awake));
}

void TestMainWindow::everyToolbarButtonShowsAt1400Pixels() {
    // The window at its tests' 1400 px: no toolbar hides a button behind its overflow arrow.
    QStringList hidden;
    for (QToolBar* bar : m_window->findChildren<QToolBar*>()) {
        for (QAction* action : bar->actions()) {
            if (action->isSeparator()) continue;
            const QWidget* button = bar->widgetForAction(action);
            if (!button || !button->isVisible()) hidden << bar->windowTitle() + ": " + action->iconText();
        }
    }
    QVERIFY2(hidden.isEmpty(), qPrintable(hidden.join(", ")));
}

void TestMainWindow::everyDemoSceneRenders_data() {
    QTest::addColumn<QString>("path");
    QDir dir(INTERPLAY_SOURCE_DIR "/scenes");
    for (const QString& name : dir.entryList({"*.json"}, QDir::Files)) QTest::newRow(qPrintable(name)) << dir.filePath(name);
    QDir thesis(INTERPLAY_SOURCE_DIR "/scenes/thesis");
    for (const QString& name : thesis.entryList({"*.json"}, QDir::Files)) {
        QTest::newRow(qPrintable("thesis/" + name)) << thesis.filePath(name);
    }
}

void TestMainWindow::everyDemoSceneRenders() {
    QFETCH(QString, path);
    QString error;
    QVERIFY2(m_window->documentManager()->openFile(path, &error), qPrintable(error));
    m_window->simulation()->stepFrames(10);
    const QImage image = m_window->viewport()->grabViewport();
    QVERIFY(!image.isNull());
    const int colors = distinctColors(image);
    QVERIFY2(colors > 200, qPrintable(QString("%1: only %2 colours").arg(path).arg(colors)));
    // Something other than sky and floor: a picked ray through the middle third hits a body.
    int hits = 0;
    interplay::Viewport* viewport = m_window->viewport();
    for (int y = 1; y < 6; ++y) {
        for (int x = 1; x < 6; ++x) {
            if (viewport->pick(QPointF(viewport->width() * x / 6.0, viewport->height() * y / 6.0))) ++hits;
        }
    }
    QVERIFY2(hits > 0, qPrintable(path + ": no body in view"));
}

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_main_window.moc"
