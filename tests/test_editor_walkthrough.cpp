// The editor's authoring loop from an empty scene to a reopened file, in the whole window with real
// OpenGL under Xvfb, driven only as a user drives it: QTest mouse presses, moves and releases on the
// viewport at the pixels the camera projects the gizmo's handles and the bodies to, the wheel, key
// sequences for the menu actions, clicks and typing in Inspector fields found by objectName, the
// timeline slider dragged with the mouse. Nothing is edited through the document.
//
// New → Add Box from the Add toolbar → up 1 m with the move gizmo's y arrow → half extents and mass
// typed into the Inspector → box select from the sky → Copy, Paste twice under the cursor → the two
// copies moved with the xz plane handle and one turned with the y ring (Ctrl snaps each to the
// settings' steps, so the authored poses are exact) → a ball joint between the copies from the Add
// menu → Play, pause → scrub back to a middle frame → Apply Simulated Pose → Save As → close, reopen.
// At each point the undo history holds the entries the gestures made; at the end the file holds the
// applied poses, which are physical (boxes on the ground within the contact slop, the joint held),
// and the reopened document serialises to the same file. Menus are reached by Alt and mnemonic
// letters, so first every menu's letters are checked to lead to one entry each.
//
// INTERPLAY_WALKTHROUGH_SCREENSHOTS=<folder> saves the window at four points (built, box select,
// scrubbed, reopened) as walkthrough-<n>-<what>.png.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/main_window.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/number_field.h"
#include "app/panels/timeline_bar.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/gizmo.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"
#include "simcore/shapes/shape.h"
#include "simcore/world/world.h"

#include "support/editor_input.h"
#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QAbstractItemView>
#include <QCursor>
#include <QDir>
#include <QFile>
#include <QMap>
#include <QMenu>
#include <QRegularExpression>
#include <QScreen>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <memory>

using interplay::DocumentManager;
using interplay::MainWindow;
using interplay::Viewport;
using interplay::gizmo::Handle;
using test_support::pixelOf;

namespace {

// How far the y arrow lifts Box 1 (m): with the 0.3 m half height typed in after, its base falls
// 1.7 m, for sqrt(2 · 1.7 m / g) = 0.59 s.
constexpr float kLift = 1.0f;
// Steps played (1.33 s at the default 60 a second); the frame scrubbed back to, two thirds of the
// way, is 0.3 s or more after Box 1 has landed.
constexpr int kPlayedSteps = 80;

// The texts of the undo stack's entries, oldest first.
QStringList history(const QUndoStack& stack) {
    QStringList texts;
    for (int i = 0; i < stack.count(); ++i) texts << stack.text(i);
    return texts;
}

struct Pose {
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
};

// Whether a frame of the run is physical: every box lies on the ground (y = 0), sunk into it by no
// more than the contact slop, the overlap the solver is made to leave (and soft contacts at 60 Hz
// leave far less: g / ω² = 0.07 mm), and within the slop of touching it, at rest after Box 1's
// fall; Box 1, dropped flat, lands where it was lifted; the copies keep the distance their ball
// joint holds, within the slop.
void checkPlausible(const std::map<int, Pose>& frame, const simcore::Shape& shape, float slop, const glm::vec3& lifted,
                    int box1, int box2, int box3, float jointedDistance) {
    for (const auto& [body, pose] : frame) {
        const simcore::Aabb bounds = simcore::worldBounds(shape, {pose.position, pose.orientation});
        QVERIFY2(bounds.min.y > -slop && bounds.min.y < slop,
                 qPrintable(QStringLiteral("body %1: lowest point at y = %2 m").arg(body).arg(bounds.min.y)));
        QVERIFY(std::isfinite(pose.position.x) && std::isfinite(pose.position.z));
    }
    // A flat landing has no sideways force: Box 1 stays where it was lifted, within the slop (it
    // slid 1.9 cm while a manifold's normal rows were solved once each per pass).
    const glm::vec3 landed = frame.at(box1).position;
    const float aside = std::hypot(landed.x - lifted.x, landed.z - lifted.z);
    QVERIFY2(aside < slop, qPrintable(QStringLiteral("Box 1 landed %1 m aside").arg(aside)));
    const float distance = glm::length(frame.at(box3).position - frame.at(box2).position);
    QVERIFY2(std::abs(distance - jointedDistance) < slop,
             qPrintable(QStringLiteral("joined %1 m apart, %2 m authored").arg(distance).arg(jointedDistance)));
}

// The menu entries whose mnemonic letter another entry of the same menu also has ("&Edit: &Paste,
// Apply Simulated &Pose"): Alt and such a letter only cycles the highlight, triggering neither.
QStringList mnemonicClashes(const QWidget& window) {
    QStringList clashes;
    for (const QMenu* menu : window.findChildren<QMenu*>()) {
        QMap<QChar, QStringList> entries;
        for (const QAction* action : menu->actions()) {
            const QString text = action->text();
            const qsizetype amp = text.indexOf(QRegularExpression(QStringLiteral("&[^&]")));
            if (amp >= 0) entries[text.at(amp + 1).toLower()] << text;
        }
        for (auto it = entries.cbegin(); it != entries.cend(); ++it) {
            if (it.value().size() > 1) clashes << QStringLiteral("%1: %2").arg(menu->title(), it.value().join(", "));
        }
    }
    return clashes;
}

}  // namespace

class TestEditorWalkthrough : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void buildPlayApplySaveReopen();

private:
    void openWindow();
    Viewport* viewport() const { return m_window->viewport(); }
    interplay::SceneDocument* document() const { return m_window->document(); }
    QUndoStack* stack() const { return document()->undoStack(); }
    int bodyNamed(const QString& name) const;
    interplay::gizmo::Placement placement() const;
    // Keys reach the window's shortcuts with the focus in the view, as after a click there.
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = {}) { QTest::keyClick(viewport(), key, modifiers); }
    // A menu entry by the keyboard: Alt + the menu's mnemonic, then the entries' mnemonics.
    void chooseFromMenu(Qt::Key menu, const QList<Qt::Key>& entries);
    // Drags `handle` of the gizmo shown from its grab point to where that point would be after
    // `offset`, Ctrl held (snapping to the grid).
    void dragHandleBy(Handle handle, const glm::vec3& offset);
    // Drags the ring about `axis` round by `degrees`, in 5° steps, Ctrl held (snapping to the
    // angle step).
    void dragRingBy(Handle ring, const glm::vec3& axis, float degrees);
    // Clicks into an Inspector field, replaces its text and presses Enter.
    void typeIntoField(const QString& objectName, const QString& text);
    // Clicks an Inspector drop-down open and chooses the entry that reads `text`.
    void chooseInDropDown(const QString& objectName, const QString& text);
    void pointCursorAt(QPoint pixel);
    void screenshot(int n, const char* what);
    Pose authoredPose(int body) const {
        return {document()->body(body).body.position, document()->body(body).body.orientation};
    }

    QTemporaryDir m_dir;
    QString m_fileAnswer;  // what the file dialog answers
    QStringList m_errors;  // what the window would have shown in a message box
    int m_unsavedAsked = 0;
    std::unique_ptr<MainWindow> m_window;
};

void TestEditorWalkthrough::initTestCase() {
    test_support::isolateSettings("test_editor_walkthrough");
    QVERIFY(m_dir.isValid());
}

void TestEditorWalkthrough::cleanupTestCase() { test_support::removeSettings(); }

void TestEditorWalkthrough::init() {
    test_support::clearSettings();
    QGuiApplication::clipboard()->clear();
    openWindow();
}

void TestEditorWalkthrough::cleanup() {
    if (m_window) m_window->simulation()->pause();
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorWalkthrough::openWindow() {
    m_window = std::make_unique<MainWindow>();
    // The file dialog and the message boxes answer without a modal loop; none is expected to ask.
    auto& prompts = m_window->documentManager()->prompts();
    prompts.unsavedChanges = [this](const QString&) {
        ++m_unsavedAsked;
        return DocumentManager::UnsavedChoice::Cancel;
    };
    prompts.error = [this](const QString& title, const QString& text, const QString& details) {
        m_errors << title + ": " + text + '\n' + details;
    };
    prompts.chooseFile = [this](DocumentManager::FileChoice, const QString&, const QString&) { return m_fileAnswer; };
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    viewport()->grabViewport();  // the first frame frames the scene
    viewport()->setFocus();
    QVERIFY(QTest::qWaitFor([this] { return viewport()->hasFocus(); }));
}

int TestEditorWalkthrough::bodyNamed(const QString& name) const {
    for (int i = 0; i < document()->bodyCount(); ++i) {
        if (document()->bodyName(i) == name) return i;
    }
    return -1;
}

interplay::gizmo::Placement TestEditorWalkthrough::placement() const {
    const auto p = viewport()->gizmoPlacement();
    if (!p) qFatal("no gizmo is shown");
    return *p;
}

void TestEditorWalkthrough::chooseFromMenu(Qt::Key menu, const QList<Qt::Key>& entries) {
    QTest::keyClick(m_window.get(), menu, Qt::AltModifier);
    for (Qt::Key entry : entries) {
        QTRY_VERIFY(QApplication::activePopupWidget());
        QTest::keyClick(QApplication::activePopupWidget(), entry);
    }
}

void TestEditorWalkthrough::dragHandleBy(Handle handle, const glm::vec3& offset) {
    viewport()->grabViewport();  // the gizmo is placed where it was last drawn
    const glm::vec3 grabbed = test_support::grabPoint(*viewport(), handle, placement());
    test_support::drag(viewport(), pixelOf(*viewport(), grabbed), pixelOf(*viewport(), grabbed + offset),
                       Qt::ControlModifier);
}

void TestEditorWalkthrough::dragRingBy(Handle ring, const glm::vec3& axis, float degrees) {
    viewport()->grabViewport();
    const interplay::gizmo::Placement p = placement();
    const glm::vec3 arm = test_support::grabPoint(*viewport(), ring, p) - p.center;
    std::vector<QPoint> path;
    const int steps = int(std::ceil(std::abs(degrees) / 5.0f));
    for (int i = 0; i <= steps; ++i) {
        path.push_back(pixelOf(*viewport(), p.center + glm::angleAxis(glm::radians(degrees * float(i) / float(steps)), axis) * arm));
    }
    test_support::dragThrough(viewport(), path, Qt::ControlModifier);
}

void TestEditorWalkthrough::typeIntoField(const QString& objectName, const QString& text) {
    auto* field = m_window->inspector()->findChild<interplay::NumberField*>(objectName);
    QVERIFY2(field && field->isVisible(), qPrintable(objectName));
    QTest::mouseClick(field, Qt::LeftButton);
    QTRY_VERIFY(field->hasFocus());
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

void TestEditorWalkthrough::chooseInDropDown(const QString& objectName, const QString& text) {
    auto* dropDown = m_window->inspector()->findChild<QComboBox*>(objectName);
    QVERIFY2(dropDown && dropDown->isVisible(), qPrintable(objectName));
    const int row = dropDown->findText(text);
    QVERIFY2(row >= 0, qPrintable(text));
    QTest::mouseClick(dropDown, Qt::LeftButton);
    QAbstractItemView* list = dropDown->view();
    QTRY_VERIFY(list->isVisible());
    // The arrow keys to the entry and Enter: a click so soon after the opening one would be taken
    // for a double click, which the popup ignores.
    for (int at = dropDown->currentIndex(); at != row; at += row > at ? 1 : -1)
        QTest::keyClick(list, row > at ? Qt::Key_Down : Qt::Key_Up);
    QTest::keyClick(list, Qt::Key_Return);
    QTRY_VERIFY(!list->isVisible());
}

void TestEditorWalkthrough::pointCursorAt(QPoint pixel) {
    QCursor::setPos(viewport()->mapToGlobal(pixel));
    QTRY_COMPARE(viewport()->mapFromGlobal(QCursor::pos()), pixel);
}

void TestEditorWalkthrough::screenshot(int n, const char* what) {
    const QString folder = qEnvironmentVariable("INTERPLAY_WALKTHROUGH_SCREENSHOTS");
    if (folder.isEmpty()) return;
    test_support::saveScreenshot(*m_window, QDir(folder).filePath(QStringLiteral("walkthrough-%1-%2.png").arg(n).arg(what)));
}

void TestEditorWalkthrough::buildPlayApplySaveReopen() {
    // The menus are reached below by Alt and their entries' letters: each letter leads to one entry.
    const QStringList clashes = mnemonicClashes(*m_window);
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join("; ")));

    // ---- New: the empty scene keeps the ground, and nothing else.
    press(Qt::Key_N, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), 1);
    const int ground = 0;
    QCOMPARE(document()->body(ground).body.motion, simcore::MotionType::Static);
    QCOMPARE(stack()->count(), 0);

    // ---- Add Box from the Add toolbar; F frames it.
    auto* addBar = m_window->findChild<QToolBar*>(QStringLiteral("addToolBar"));
    QVERIFY(addBar);
    QWidget* addBox = addBar->widgetForAction(m_window->action(QStringLiteral("addBox")));
    QVERIFY(addBox && addBox->isVisible());
    QTest::mouseClick(addBox, Qt::LeftButton);
    QCOMPARE(document()->bodyCount(), 2);
    const int box1 = bodyNamed(QStringLiteral("Box 1"));
    QCOMPARE(box1, 1);
    QCOMPARE(document()->selectedBodies(), QList<int>{box1});
    QCOMPARE(history(*stack()), QStringList{QStringLiteral("Add Box 1")});
    viewport()->setFocus();
    press(Qt::Key_F);
    // Back a little, so the drags below stay in view.
    test_support::turnWheel(viewport(), QPoint(viewport()->width() / 2, viewport()->height() / 2), -4);
    const Pose added = authoredPose(box1);

    // ---- Up with the y arrow, snapped to the grid; F frames it where it is now.
    dragHandleBy(Handle::AxisY, glm::vec3(0.0f, kLift, 0.0f));
    const Pose raised = authoredPose(box1);
    QCOMPARE(raised.position.x, added.position.x);
    QCOMPARE(raised.position.z, added.position.z);
    QCOMPARE(raised.orientation, added.orientation);
    QVERIFY2(std::abs(raised.position.y - added.position.y - kLift) < 1e-4f, qPrintable(QString::number(raised.position.y)));
    QCOMPARE(stack()->text(stack()->count() - 1), QStringLiteral("Move Box 1"));
    press(Qt::Key_F);
    test_support::turnWheel(viewport(), QPoint(viewport()->width() / 2, viewport()->height() / 2), -4);

    // ---- Its size and mass in the Inspector.
    typeIntoField(QStringLiteral("halfExtents.x"), QStringLiteral("0.6"));
    typeIntoField(QStringLiteral("halfExtents.y"), QStringLiteral("0.3"));
    chooseInDropDown(QStringLiteral("massMode"), QStringLiteral("Mass (kg)"));
    typeIntoField(QStringLiteral("mass"), QStringLiteral("4"));
    const simcore::BodyCreationSettings sized = document()->body(box1).body;  // a copy: pastes grow the bodies
    QCOMPARE(sized.shape.halfExtents, simcore::Vec3(0.6f, 0.3f, 0.5f));
    QCOMPARE(sized.mass, std::optional(4.0f));
    screenshot(1, "built");

    // ---- Box select: nothing selected, the front view, a drag from the sky above and left of the
    // box to below and right of its centre (the ground's centre, 2.5 m lower, stays outside).
    press(Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(document()->selectedBodies().isEmpty());
    press(Qt::Key_1, Qt::KeypadModifier);
    viewport()->grabViewport();
    const QPoint boxPixel = pixelOf(*viewport(), raised.position);
    const QRect band(boxPixel - QPoint(90, 90), boxPixel + QPoint(90, 40));
    QCOMPARE(viewport()->sceneBodyAt(band.topLeft()), -1);
    QVERIFY(!band.contains(pixelOf(*viewport(), document()->body(ground).body.position)));
    QTest::mousePress(viewport(), Qt::LeftButton, {}, band.topLeft());
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport(), band.topLeft() + (band.bottomRight() - band.topLeft()) * i / 10);
    screenshot(2, "box-select");
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, band.bottomRight());
    QCOMPARE(document()->selectedBodies(), QList<int>{box1});

    // ---- Copy; from the top, paste twice, each under the cursor on the ground beside the box.
    press(Qt::Key_C, Qt::ControlModifier);
    press(Qt::Key_7, Qt::KeypadModifier);
    viewport()->grabViewport();
    const QPoint onBox1 = pixelOf(*viewport(), raised.position);
    QList<int> copies;
    for (const QPoint at : {onBox1 + QPoint(-250, 0), onBox1 + QPoint(250, 0)}) {
        const std::optional<glm::vec3> onGround = viewport()->surfacePointAt(at);
        QVERIFY(onGround && std::abs(onGround->y) < 1e-4f);
        pointCursorAt(at);
        press(Qt::Key_V, Qt::ControlModifier);
        const int copy = document()->bodyCount() - 1;
        copies << copy;
        QCOMPARE(document()->selectedBodies(), QList<int>{copy});
        QCOMPARE(stack()->undoText(), QStringLiteral("Paste %1").arg(document()->bodyName(copy)));
        // It rests on the ground where the cursor points: its centre half its height above.
        const simcore::BodyCreationSettings& pasted = document()->body(copy).body;
        QVERIFY(glm::length(pasted.position - (*onGround + glm::vec3(0.0f, 0.3f, 0.0f))) < 1e-4f);
        QCOMPARE(pasted.shape.halfExtents, sized.shape.halfExtents);
        QCOMPARE(pasted.mass, sized.mass);
    }
    const int box2 = copies[0], box3 = copies[1];
    QCOMPARE(document()->bodyName(box2), QStringLiteral("Box 2"));
    QCOMPARE(document()->bodyName(box3), QStringLiteral("Box 3"));

    // ---- The copies moved on the ground with the xz plane handle (face on from the top), Box 3
    // first (selected after its paste), then Box 2 after a click on it.
    const Pose box3Pasted = authoredPose(box3);
    dragHandleBy(Handle::PlaneXZ, glm::vec3(0.0f, 0.0f, 1.0f));
    QVERIFY(glm::length(authoredPose(box3).position - (box3Pasted.position + glm::vec3(0.0f, 0.0f, 1.0f))) < 1e-5f);
    QCOMPARE(stack()->undoText(), QStringLiteral("Move Box 3"));
    const Pose box2Pasted = authoredPose(box2);
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, pixelOf(*viewport(), box2Pasted.position));
    QCOMPARE(document()->selectedBodies(), QList<int>{box2});
    dragHandleBy(Handle::PlaneXZ, glm::vec3(0.5f, 0.0f, 1.0f));
    QVERIFY(glm::length(authoredPose(box2).position - (box2Pasted.position + glm::vec3(0.5f, 0.0f, 1.0f))) < 1e-5f);
    QCOMPARE(stack()->undoText(), QStringLiteral("Move Box 2"));

    // ---- Box 2 turned 30° about y with the rotate gizmo's ring (E), two snapped steps of 15°.
    press(Qt::Key_E);
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Rotate));
    const Pose box2Moved = authoredPose(box2);
    dragRingBy(Handle::RingY, glm::vec3(0.0f, 1.0f, 0.0f), 30.0f);
    const Pose box2Turned = authoredPose(box2);
    QCOMPARE(box2Turned.position, box2Moved.position);
    const glm::quat turn = box2Turned.orientation * glm::inverse(box2Moved.orientation);
    QVERIFY2(std::abs(glm::degrees(glm::angle(turn)) - 30.0f) < 0.01f, qPrintable(QString::number(glm::degrees(glm::angle(turn)))));
    QVERIFY(std::abs(glm::axis(turn).y) > 0.9999f);
    QCOMPARE(stack()->undoText(), QStringLiteral("Rotate Box 2"));
    press(Qt::Key_W);

    // ---- A ball joint between the copies: Shift+click adds Box 3, then Add > Joint > Ball.
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, pixelOf(*viewport(), authoredPose(box3).position));
    QCOMPARE(document()->selectedBodies(), (QList<int>{box2, box3}));
    chooseFromMenu(Qt::Key_A, {Qt::Key_J, Qt::Key_Return});
    QCOMPARE(document()->jointCount(), 1);
    const simcore::SceneJoint& joint = document()->joint(0);
    QCOMPARE(joint.joint.type, simcore::JointType::Ball);
    QCOMPARE(joint.bodyA, std::size_t(box2));
    QCOMPARE(joint.bodyB, std::optional(std::size_t(box3)));
    QCOMPARE(stack()->undoText(), QStringLiteral("Add Ball Joint"));
    const QStringList beforePlay = history(*stack());
    const float jointedDistance = glm::length(authoredPose(box3).position - authoredPose(box2).position);
    const float slop = document()->scene().settings.contact.linearSlop;

    // ---- Play (Space) until Box 1 has fallen and come to rest; pause (Space).
    interplay::SimulationController* simulation = m_window->simulation();
    viewport()->setFocus();
    press(Qt::Key_Space);
    QVERIFY(simulation->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(simulation->world()->stepCount() >= kPlayedSteps, 20000);
    press(Qt::Key_Space);
    QVERIFY(!simulation->isPlaying());
    const int frames = int(simulation->timeline().frameCount());
    QVERIFY2(frames > kPlayedSteps, qPrintable(QString::number(frames)));
    QCOMPARE(document()->jointCount(), 1);
    QCOMPARE(history(*stack()), beforePlay);  // playing edits nothing

    // ---- Scrub back to a middle frame with the timeline slider.
    QSlider* slider = m_window->timelineBar()->slider();
    const int middle = frames * 2 / 3;
    test_support::dragSliderTo(slider, middle);
    const int shown = simulation->currentFrame();
    QVERIFY2(std::abs(shown - middle) <= 3 && shown < frames - 1, qPrintable(QString::number(shown)));
    QCOMPARE(slider->value(), shown);
    const simcore::World* world = simulation->world();
    std::map<int, Pose> simulated;
    for (int body : {box1, box2, box3}) {
        const simcore::BodyId id = simulation->bodyIds()[std::size_t(body)];
        simulated[body] = {world->position(id), world->orientation(id)};
    }
    checkPlausible(simulated, sized.shape, slop, raised.position, box1, box2, box3, jointedDistance);
    if (QTest::currentTestFailed()) return;
    screenshot(3, "scrubbed");

    // ---- Apply Simulated Pose from the Edit menu (Alt+E, S): the frame shown becomes authored.
    chooseFromMenu(Qt::Key_E, {Qt::Key_S});
    QCOMPARE(stack()->undoText(), QStringLiteral("Apply Simulated Pose"));
    for (const auto& [body, pose] : simulated) {
        QCOMPARE(authoredPose(body).position, pose.position);
        QCOMPARE(authoredPose(body).orientation, pose.orientation);
    }
    const QStringList built = history(*stack());
    QCOMPARE(built, (QStringList{"Add Box 1", "Move Box 1", "Change Half extent of Box 1", "Change Half extent of Box 1",
                                 "Change Mass of Box 1", "Change Mass or density of Box 1", "Paste Box 2", "Paste Box 3", "Move Box 3", "Move Box 2",
                                 "Rotate Box 2", "Add Ball Joint", "Apply Simulated Pose"}));

    // ---- Save As (Ctrl+Shift+S) to a file of the test's own.
    m_fileAnswer = m_dir.filePath(QStringLiteral("walkthrough.json"));
    press(Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY2(m_errors.isEmpty(), qPrintable(m_errors.join('\n')));
    QCOMPARE(document()->filePath(), m_fileAnswer);
    QVERIFY(stack()->isClean());
    QCOMPARE(history(*stack()), built);  // saving keeps the history
    QFile file(m_fileAnswer);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const nlohmann::json saved = nlohmann::json::parse(file.readAll().toStdString(), nullptr, false);
    QVERIFY(!saved.is_discarded());
    const std::vector<simcore::SceneBody> savedBodies = document()->scene().bodies;
    const std::vector<simcore::SceneJoint> savedJoints = document()->scene().joints;

    // ---- Close the window (nothing to ask: it is saved) and open the file in a new one (Ctrl+O).
    QVERIFY(m_window->close());
    QCOMPARE(m_unsavedAsked, 0);
    m_window.reset();
    openWindow();
    press(Qt::Key_O, Qt::ControlModifier);
    QVERIFY2(m_errors.isEmpty(), qPrintable(m_errors.join('\n')));
    QCOMPARE(document()->filePath(), m_fileAnswer);
    QCOMPARE(stack()->count(), 0);
    QVERIFY(!document()->isModified());
    screenshot(4, "reopened");

    // The reopened document is the saved one: it serialises to the same JSON, body for body.
    const nlohmann::json reserialised = nlohmann::json::parse(simcore::serializeScene(document()->scene()));
    QVERIFY2(reserialised == saved, nlohmann::json::diff(saved, reserialised).dump().c_str());
    QCOMPARE(document()->bodyCount(), 4);
    for (std::size_t i = 0; i < savedBodies.size(); ++i)
        QVERIFY2(interplay::sameSceneBody(document()->body(int(i)), savedBodies[i]), savedBodies[i].body.name.c_str());
    QCOMPARE(document()->jointCount(), 1);
    QCOMPARE(document()->joint(0).bodyA, std::size_t(box2));
    QCOMPARE(document()->joint(0).bodyB, std::optional(std::size_t(box3)));
    QCOMPARE(document()->joint(0).joint.anchor, savedJoints[0].joint.anchor);
    // The file holds the applied poses, exactly (the format round-trips floats), under the names
    // the editor gave.
    for (const auto& [body, pose] : simulated) {
        QCOMPARE(QString::fromStdString(saved.at("bodies").at(std::size_t(body)).at("name").get<std::string>()),
                 document()->bodyName(body));
        QCOMPARE(authoredPose(body).position, pose.position);
        QCOMPARE(authoredPose(body).orientation, pose.orientation);
    }
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorWalkthrough test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_walkthrough.moc"
