// Box select, select all / none / invert, and copy, cut, paste and duplicate in the whole window,
// with real OpenGL under Xvfb and real QTest mouse and key events (issue 15): a left drag from empty
// space selects the bodies whose centres the rectangle holds, in perspective and orthographic views,
// Shift adding and Ctrl toggling; a plain click on nothing still clears and a drag on a body still
// moves it. Ctrl+C / Ctrl+V copy bodies with the joints among them through the system clipboard, as
// one undo entry, into this window or a second one; Ctrl+X cuts; Ctrl+D duplicates; the pasted
// bodies land on the ground under the cursor when it is over the view; garbage on the clipboard is
// refused with a status message and changes nothing.

#include "app/document/scene_clipboard.h"
#include "app/document/scene_document.h"
#include "app/document/scene_tree_model.h"
#include "app/panels/inspector_panel.h"
#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"
#include "simcore/shapes/shape.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QClipboard>
#include <QCursor>
#include <QGuiApplication>
#include <QItemSelectionModel>
#include <QMimeData>
#include <QScreen>
#include <QLabel>
#include <QStatusBar>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <glm/glm.hpp>

#include <cmath>
#include <memory>

using interplay::MainWindow;
using interplay::SceneDocument;
using interplay::Viewport;

namespace {

constexpr int kBodies = 5;
constexpr float kSpacing = 2.0f;  // m between the spheres' centres along x

// Five spheres in a row along x, at x = -4, -2, 0, 2, 4 and 1 m up, chained by joints: ball 0-1,
// hinge 1-2, ball 2-3, ball 3-4. No ground, so nothing but the spheres is under the cursor.
simcore::Scene fiveSpheres() {
    simcore::Scene scene;
    scene.settings.gravity = simcore::Vec3(0.0f);
    for (int i = 0; i < kBodies; ++i) {
        simcore::SceneBody body;
        body.body.name = "Sphere " + std::to_string(i + 1);
        body.body.shape = simcore::Shape::sphere(0.4f);
        body.body.position = simcore::Vec3(kSpacing * float(i - 2), 1.0f, 0.0f);
        scene.bodies.push_back(body);
    }
    for (int i = 0; i + 1 < kBodies; ++i) {
        simcore::SceneJoint joint;
        joint.joint.type = i == 1 ? simcore::JointType::Hinge : simcore::JointType::Ball;
        joint.joint.name = "link " + std::to_string(i + 1);
        joint.joint.anchor = simcore::Vec3(kSpacing * (float(i) - 1.5f), 1.0f, 0.0f);
        joint.joint.axis = simcore::Vec3(0.0f, 0.0f, 1.0f);
        joint.bodyA = std::size_t(i);
        joint.bodyB = std::size_t(i + 1);
        scene.joints.push_back(joint);
    }
    return scene;
}

QPoint pixelOf(const Viewport& viewport, const simcore::Vec3& point) {
    const glm::vec3 p = viewport.camera().project(point, float(viewport.width()), float(viewport.height()));
    return {int(std::lround(p.x)), int(std::lround(p.y))};
}

// A left drag from `from` to `to` in ten moves, as a hand makes it.
void drag(QWidget* widget, const QPoint& from, const QPoint& to, Qt::KeyboardModifiers modifiers = {}) {
    QTest::mousePress(widget, Qt::LeftButton, modifiers, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(widget, from + (to - from) * i / 10);
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers, to);
}

// The scene as its file says it, to compare documents.
std::string sceneText(const SceneDocument& document) { return simcore::serializeScene(document.scene()); }

}  // namespace

class TestEditorClipboard : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void boxDragSelectsTheBodiesInside_data();
    void boxDragSelectsTheBodiesInside();
    void clickOnNothingClearsAndDragOnABodyMoves();
    void middleDragOrbitsAndShiftMiddleDragPans();
    void selectAllNoneAndInvert();
    void copyPasteAddsBodiesWithTheirJoints();
    void pasteLandsUnderTheCursor();
    void cutThenPasteBringsThemBack();
    void duplicateCopiesBodiesWithTheirJoints();
    void pasteIntoASecondWindow();
    void garbageOnTheClipboardChangesNothing();
    void cutAndPasteWhilePlaying();

private:
    Viewport* viewport() const { return m_window->viewport(); }
    SceneDocument* document() const { return m_window->document(); }
    // Keys go to the window's shortcuts: the viewport has the focus, as after a click in it.
    void press(int key, Qt::KeyboardModifiers modifiers) { QTest::keyClick(viewport(), Qt::Key(key), modifiers); }
    // Moves the pointer off the view (onto the menu bar), so Paste places beside the originals.
    void cursorAway() {
        const QPoint menuBar = m_window->mapToGlobal(QPoint(4, 4));
        QCursor::setPos(menuBar);
        QTRY_COMPARE(QCursor::pos(), menuBar);
    }
    // The rectangle just around the centres of spheres `first` to `last`, 40 px of margin.
    QRect boxAround(int first, int last) const;

    std::unique_ptr<MainWindow> m_window;
};

void TestEditorClipboard::initTestCase() { test_support::isolateSettings("test_editor_clipboard"); }

void TestEditorClipboard::cleanupTestCase() { test_support::removeSettings(); }

void TestEditorClipboard::init() {
    test_support::clearSettings();
    QGuiApplication::clipboard()->clear();
    m_window = std::make_unique<MainWindow>();
    m_window->document()->restoreRecovered(fiveSpheres(), {});
    QVERIFY(test_support::showActive(*m_window));
    viewport()->grabViewport();  // the first frame frames the scene; then the test aims the camera
    // Straight on from the front, so the row lies across the view.
    interplay::Camera& camera = viewport()->camera();
    camera.setTarget({0.0f, 1.0f, 0.0f});
    camera.setYawDegrees(0.0f);
    camera.setPitchDegrees(10.0f);
    camera.setDistance(16.0f);
    viewport()->grabViewport();
    viewport()->setFocus();
    document()->undoStack()->clear();
}

void TestEditorClipboard::cleanup() {
    if (m_window) m_window->simulation()->pause();
    test_support::closeWithoutPrompt(m_window);
}

QRect TestEditorClipboard::boxAround(int first, int last) const {
    QRect box(pixelOf(*viewport(), document()->body(first).body.position),
              pixelOf(*viewport(), document()->body(last).body.position));
    return box.normalized().adjusted(-40, -40, 40, 40);
}

void TestEditorClipboard::boxDragSelectsTheBodiesInside_data() {
    QTest::addColumn<bool>("orthographic");
    QTest::newRow("perspective") << false;
    QTest::newRow("orthographic") << true;
}

void TestEditorClipboard::boxDragSelectsTheBodiesInside() {
    QFETCH(bool, orthographic);
    if (orthographic) QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    QCOMPARE(viewport()->camera().isOrthographic(), orthographic);
    // The move gizmo (on by default) takes presses on its handles before box select does
    // (test_editor_gizmo), and the selection's gizmo sits where some of these boxes start: off.
    m_window->action("gizmoMove")->trigger();
    QVERIFY(!viewport()->gizmoMode());
    viewport()->grabViewport();

    // From empty space above and left of sphere 2 to below and right of sphere 4.
    const QRect box = boxAround(1, 3);
    QCOMPARE(viewport()->sceneBodyAt(box.topLeft()), -1);
    QVERIFY(!viewport()->pickJoint(box.topLeft()));
    const QImage without = viewport()->grabViewport();
    QTest::mousePress(viewport(), Qt::LeftButton, {}, box.topLeft());
    for (int i = 1; i <= 10; ++i)
        QTest::mouseMove(viewport(), box.topLeft() + (box.bottomRight() - box.topLeft()) * i / 10);
    // While dragging, the rectangle is drawn: its edge changes the pixels it crosses.
    const QImage with = viewport()->grabViewport();
    int changed = 0;
    const qreal ratio = with.devicePixelRatio();
    for (int x = box.left() + 5; x < box.right() - 5; x += 7) {
        const QPoint p(int(x * ratio), int(box.top() * ratio));
        if (with.pixel(p) != without.pixel(p)) ++changed;
    }
    QVERIFY2(changed > 0, "the rubber band is drawn along the box's top edge");
    if (!orthographic) test_support::saveScreenshotIfAsked(*m_window, "INTERPLAY_BOX_SELECT_SCREENSHOT");
    QVERIFY(document()->selectedBodies().isEmpty());  // selected on release, not before
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, box.bottomRight());
    QCOMPARE(document()->selectedBodies(), (QList<int>{1, 2, 3}));
    QCOMPARE(document()->undoStack()->count(), 0);  // selecting is no edit
    QVERIFY(!viewport()->grabViewport().isNull());

    // The Scene tree shows the same three rows selected.
    const QModelIndexList rows = m_window->sceneTree()->selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 3);

    // Shift adds sphere 5; Ctrl toggles spheres 4 and 5 off again; Ctrl over 1 toggles it on.
    drag(viewport(), boxAround(4, 4).topLeft(), boxAround(4, 4).bottomRight(), Qt::ShiftModifier);
    QCOMPARE(document()->selectedBodies(), (QList<int>{1, 2, 3, 4}));
    drag(viewport(), boxAround(3, 4).topLeft(), boxAround(3, 4).bottomRight(), Qt::ControlModifier);
    QCOMPARE(document()->selectedBodies(), (QList<int>{1, 2}));
    drag(viewport(), boxAround(0, 0).topLeft(), boxAround(0, 0).bottomRight(), Qt::ControlModifier);
    QCOMPARE(document()->selectedBodies(), (QList<int>{0, 1, 2}));
    // A plain box replaces the selection; one holding no centre leaves nothing selected.
    drag(viewport(), boxAround(4, 4).topLeft(), boxAround(4, 4).bottomRight());
    QCOMPARE(document()->selectedBodies(), QList<int>{4});
    drag(viewport(), QPoint(10, 10), QPoint(60, 40));
    QVERIFY(document()->selectedBodies().isEmpty());
}

void TestEditorClipboard::clickOnNothingClearsAndDragOnABodyMoves() {
    document()->setSelectedBodies({0, 1});
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, QPoint(viewport()->width() / 2, 5));
    QVERIFY(document()->selectedBodies().isEmpty());

    const simcore::Vec3 before = document()->body(2).body.position;
    const QPoint at = pixelOf(*viewport(), before);
    QCOMPARE(viewport()->sceneBodyAt(at), 2);
    drag(viewport(), at, at + QPoint(60, 0));
    QCOMPARE(document()->selectedBodies(), QList<int>{2});
    QVERIFY(document()->body(2).body.position.x > before.x + 0.5f);  // moved right, not box-selected
    QCOMPARE(document()->undoStack()->count(), 1);
}

void TestEditorClipboard::middleDragOrbitsAndShiftMiddleDragPans() {
    interplay::Camera& camera = viewport()->camera();
    const QPoint from(viewport()->width() / 2, 20);  // the sky: the left button would box-select here
    const float yaw = camera.yawDegrees();
    const glm::vec3 target = camera.target();
    QTest::mousePress(viewport(), Qt::MiddleButton, {}, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport(), from + QPoint(6 * i, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, {}, from + QPoint(60, 0));
    // 60 px at 0.3 degrees per pixel: the view turns 18 degrees about its target.
    QVERIFY2(std::abs(camera.yawDegrees() - (yaw - 18.0f)) < 1e-3f, qPrintable(QString::number(camera.yawDegrees())));
    QCOMPARE(camera.target(), target);

    const float turned = camera.yawDegrees();
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::ShiftModifier, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport(), from + QPoint(6 * i, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::ShiftModifier, from + QPoint(60, 0));
    QCOMPARE(camera.yawDegrees(), turned);
    QVERIFY(glm::length(camera.target() - target) > 0.1f);
    QVERIFY(document()->selectedBodies().isEmpty());
    QCOMPARE(document()->undoStack()->count(), 0);
}

void TestEditorClipboard::selectAllNoneAndInvert() {
    press(Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(document()->selectedBodies(), (QList<int>{0, 1, 2, 3, 4}));
    QCOMPARE(m_window->sceneTree()->selectionModel()->selectedRows().size(), kBodies);
    press(Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(document()->selectedBodies().isEmpty());
    QVERIFY(m_window->sceneTree()->selectionModel()->selectedRows().isEmpty());
    // The Inspector says so in full: its wrapped header is as tall as its lines need.
    auto* header = m_window->inspector()->findChild<QLabel*>(QStringLiteral("inspectorHeader"));
    QVERIFY(header);
    QTRY_VERIFY(header->text().startsWith(QStringLiteral("Nothing selected")));
    QTRY_VERIFY2(header->height() >= header->heightForWidth(header->width()),
                 qPrintable(QString("%1 px tall, %2 needed").arg(header->height()).arg(header->heightForWidth(header->width()))));
    document()->setSelectedBodies({1, 3});
    press(Qt::Key_I, Qt::ControlModifier);
    QCOMPARE(document()->selectedBodies(), (QList<int>{0, 2, 4}));
    const QModelIndexList rows = m_window->sceneTree()->selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 3);
    QCOMPARE(m_window->sceneTreeModel()->bodyIndexOf(rows.first()) % 2, 0);
    // The menu lists them with the keys a user reads there.
    QCOMPARE(m_window->action("selectNone")->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    QCOMPARE(m_window->action("invertSelection")->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_I));
    QCOMPARE(document()->undoStack()->count(), 0);
}

void TestEditorClipboard::copyPasteAddsBodiesWithTheirJoints() {
    cursorAway();
    document()->setSelectedBodies({0, 1, 2});
    const std::string before = sceneText(*document());
    press(Qt::Key_C, Qt::ControlModifier);
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    QVERIFY(data && data->hasFormat(interplay::kSceneFragmentMimeType) && data->hasText());
    // The clipboard holds a scene file: the three spheres and the two joints among them.
    const interplay::ParsedFragment copied = interplay::parseFragment(data->text().toUtf8());
    QVERIFY2(copied.fragment, qPrintable(copied.error));
    QCOMPARE(copied.fragment->bodies.size(), std::size_t(3));
    QCOMPARE(copied.fragment->joints.size(), std::size_t(2));
    QCOMPARE(sceneText(*document()), before);  // copying changes nothing

    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), kBodies + 3);
    QCOMPARE(document()->jointCount(), 4 + 2);
    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->undoText(), QString("Paste 3 Bodies"));
    QCOMPARE(document()->selectedBodies(), (QList<int>{5, 6, 7}));
    QCOMPARE(document()->bodyName(5), QString("Sphere 6"));
    // The copies are joined to each other as the originals were, and sit beside them (the three
    // spheres span 4.8 m, so 4.9 m along +x), not in them.
    QCOMPARE(document()->joint(4).bodyA, std::size_t(5));
    QCOMPARE(document()->joint(4).bodyB, std::optional<std::size_t>(6));
    QCOMPARE(document()->joint(4).joint.name, std::string("link 5"));  // "link 1" copied
    QCOMPARE(document()->joint(5).joint.type, simcore::JointType::Hinge);
    QCOMPARE(document()->joint(5).joint.name, std::string("link 6"));
    for (int i = 0; i < 3; ++i) {
        const simcore::Vec3 offset = document()->body(5 + i).body.position - document()->body(i).body.position;
        QVERIFY(glm::length(offset - simcore::Vec3(4.9f, 0.0f, 0.0f)) < 1e-5f);
    }
    QVERIFY(glm::length(document()->joint(4).joint.anchor - document()->joint(0).joint.anchor -
                        simcore::Vec3(4.9f, 0.0f, 0.0f)) < 1e-5f);
    // The running world holds them too.
    QCOMPARE(m_window->simulation()->bodyIds().size(), std::size_t(kBodies + 3));
    QCOMPARE(m_window->simulation()->jointIds().size(), std::size_t(6));
    test_support::saveScreenshotIfAsked(*m_window, "INTERPLAY_PASTE_SCREENSHOT");

    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(sceneText(*document()), before);
    QCOMPARE(m_window->simulation()->bodyIds().size(), std::size_t(kBodies));
}

void TestEditorClipboard::pasteLandsUnderTheCursor() {
    document()->setSelectedBodies({2});
    press(Qt::Key_C, Qt::ControlModifier);
    // The ground plane under a pixel below the row: y = 0 there.
    const QPoint pixel(viewport()->width() / 3, viewport()->height() * 3 / 4);
    const std::optional<glm::vec3> ground = viewport()->surfacePointAt(pixel);
    QVERIFY(ground);
    QVERIFY(std::abs(ground->y) < 1e-4f);
    QCursor::setPos(viewport()->mapToGlobal(pixel));
    QTRY_COMPARE(viewport()->mapFromGlobal(QCursor::pos()), pixel);
    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), kBodies + 1);
    // The copy rests on the ground where the cursor points: its centre a radius above that point.
    const simcore::Vec3 placed = document()->body(kBodies).body.position;
    QVERIFY2(glm::length(placed - (*ground + glm::vec3(0.0f, 0.4f, 0.0f))) < 1e-4f,
             qPrintable(QString("%1 %2 %3").arg(placed.x).arg(placed.y).arg(placed.z)));
    QCOMPARE(document()->undoStack()->undoText(), QString("Paste Sphere 6"));
}

void TestEditorClipboard::cutThenPasteBringsThemBack() {
    cursorAway();
    document()->setSelectedBodies({3, 4});
    press(Qt::Key_X, Qt::ControlModifier);
    // Cut removes the bodies with every joint they had, the one to sphere 3 included: one entry.
    QCOMPARE(document()->bodyCount(), 3);
    QCOMPARE(document()->jointCount(), 2);
    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->undoText(), QString("Cut 2 Bodies"));

    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), 5);
    QCOMPARE(document()->jointCount(), 3);  // the joint between them, not the one to sphere 3
    QCOMPARE(document()->undoStack()->count(), 2);
    // Their names are free again, so they come back under them.
    QCOMPARE(document()->bodyName(3), QString("Sphere 4"));
    QCOMPARE(document()->bodyName(4), QString("Sphere 5"));
    QCOMPARE(document()->joint(2).bodyA, std::size_t(3));

    press(Qt::Key_Z, Qt::ControlModifier);
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(sceneText(*document()), simcore::serializeScene(fiveSpheres()));
}

void TestEditorClipboard::duplicateCopiesBodiesWithTheirJoints() {
    document()->setSelectedBodies({1, 2});
    press(Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), kBodies + 2);
    QCOMPARE(document()->jointCount(), 4 + 1);  // the hinge between them, not the balls to 1 and 4
    QCOMPARE(document()->joint(4).joint.type, simcore::JointType::Hinge);
    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->undoText(), QString("Duplicate 2 Bodies"));
    QCOMPARE(document()->selectedBodies(), (QList<int>{5, 6}));
    QVERIFY(QGuiApplication::clipboard()->text().isEmpty());  // Duplicate leaves the clipboard alone
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), kBodies);
    QCOMPARE(document()->jointCount(), 4);
}

void TestEditorClipboard::pasteIntoASecondWindow() {
    cursorAway();
    auto second = std::make_unique<MainWindow>();
    second->document()->newEmpty();
    const int groundOnly = second->document()->bodyCount();
    QVERIFY(test_support::showActive(*second));

    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    document()->setSelectedBodies({0, 1, 2, 3, 4});
    press(Qt::Key_C, Qt::ControlModifier);

    second->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(second.get()));
    QCursor::setPos(second->mapToGlobal(QPoint(4, 4)));  // off its view: beside where they were
    second->viewport()->setFocus();
    QTest::keyClick(second->viewport(), Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(second->document()->bodyCount(), groundOnly + kBodies);
    QCOMPARE(second->document()->jointCount(), 4);
    QCOMPARE(second->document()->undoStack()->count(), 1);
    // Its names were free there: they keep them.
    QCOMPARE(second->document()->bodyName(groundOnly), QString("Sphere 1"));
    QCOMPARE(document()->undoStack()->count(), 0);  // the first window is untouched
    test_support::closeWithoutPrompt(second);
}

void TestEditorClipboard::garbageOnTheClipboardChangesNothing() {
    const std::string before = sceneText(*document());
    QGuiApplication::clipboard()->setText(QStringLiteral("{\"format\": \"interplay.scene\", \"bodies\": [ oops"));
    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(sceneText(*document()), before);
    QCOMPARE(document()->undoStack()->count(), 0);
    const QString message = m_window->statusBar()->currentMessage();
    QVERIFY2(message.startsWith("Nothing pasted: ") && message.contains("clipboard:1:"), qPrintable(message));

    // A scene with a value the loader refuses names where it is.
    QGuiApplication::clipboard()->setText(QStringLiteral(
        R"({"format": "interplay.scene", "version": 1, "bodies": [{"name": "b", "shape": {"type": "sphere", "radius": -1}, "position": [0, 1, 0]}]})"));
    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(sceneText(*document()), before);
    QVERIFY2(m_window->statusBar()->currentMessage().contains("/bodies/0/shape/radius"),
             qPrintable(m_window->statusBar()->currentMessage()));
}

void TestEditorClipboard::cutAndPasteWhilePlaying() {
    cursorAway();
    interplay::SimulationController* simulation = m_window->simulation();
    m_window->action("play")->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(simulation->world()->stepCount() > 10, 10000);
    // As Delete and Add during a run: the world loses and gains the bodies and keeps running.
    document()->setSelectedBodies({3, 4});
    press(Qt::Key_X, Qt::ControlModifier);
    QCOMPARE(simulation->bodyIds().size(), std::size_t(3));
    QCOMPARE(simulation->jointIds().size(), std::size_t(2));
    QVERIFY(simulation->isPlaying());
    press(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(document()->bodyCount(), kBodies);
    QCOMPARE(simulation->bodyIds().size(), std::size_t(kBodies));
    QCOMPARE(simulation->jointIds().size(), std::size_t(3));
    QVERIFY(simulation->isPlaying());
    const simcore::World* world = simulation->world();
    QVERIFY(world->contains(simulation->bodyIds()[4]));
    // The pasted body starts where the paste put it (beside where it was copied from).
    const std::uint64_t steps = world->stepCount();
    QTRY_VERIFY_WITH_TIMEOUT(simulation->world()->stepCount() > steps + 10, 10000);
    QVERIFY(std::isfinite(simulation->world()->kineticEnergy()));
    simulation->pause();
    QCOMPARE(document()->undoStack()->count(), 2);
}

QTEST_MAIN(TestEditorClipboard)
#include "test_editor_clipboard.moc"
