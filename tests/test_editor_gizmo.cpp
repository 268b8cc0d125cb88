// The viewport's transform gizmos in the whole window, with real OpenGL under Xvfb and real QTest
// mouse and key events on the viewport: dragging the move gizmo's x arrow moves the selected body
// along x only, by the distance the cursor's pixels mean on that axis, in one undo entry that Ctrl+Z
// takes back; E shows the rotate gizmo and a ring drag turns the body about the ring's axis; Ctrl
// snaps to the grid and angle steps of the settings; a multi-selection moves together; during
// play the live body follows, and several bodies turned during a run turn from their live poses;
// the Gizmo toolbar's buttons are the keys' actions, its Snap snaps without Ctrl, and the steps
// typed in Edit → Preferences apply to the next drag; Escape and a right click cancel; a jointed body carries its anchors.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/main_window.h"
#include "app/panels/preferences_dialog.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/gizmo.h"
#include "app/viewport/gizmo_tool.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QToolBar>
#include <QToolButton>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTest>
#include <QUndoStack>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <memory>

using interplay::MainWindow;
using interplay::Viewport;
using interplay::gizmo::Handle;

class TestEditorGizmo : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void xArrowDragMovesAlongXOnly();
    void ringDragTurnsAboutTheRingsAxis();
    void ctrlSnapsToTheSettingsSteps_data();
    void ctrlSnapsToTheSettingsSteps();
    void multiSelectionMovesTogether();
    void localSpaceFollowsTheBodysAxes();
    void duringPlayTheBodyFollows();
    void duringARunSeveralTurnFromTheirLivePoses();
    void escapeOrRightClickCancels_data();
    void escapeOrRightClickCancels();
    void movingAJointedBodyCarriesItsAnchors();
    void pressesAwayFromTheHandlesStillDragBodies();
    void hoveredHandleLightsUp();
    void deletingTheBodiesMidDragEndsTheDrag();
    void flyKeysStillFlyDuringARightDrag();
    void toolbarButtonsAreTheKeysActions();
    void snapButtonSnapsWithoutCtrl();
    void preferencesStepsApplyToTheNextDrag();

private:
    Viewport* viewport() const { return m_window->viewport(); }
    interplay::SceneDocument* document() const { return m_window->document(); }
    int bodyNamed(const char* name) const;
    void select(QList<int> bodies);
    // How many degrees of a turn about y one pixel of cursor is at `degrees` round the ring whose
    // point at 0 is `center + arm`: the ring is foreshortened on screen, most where it is seen edge-on.
    float ringDegreesPerPixel(const glm::vec3& center, const glm::vec3& arm, float degrees) const {
        const auto at = [&](float d) {
            const glm::vec3 point = center + glm::angleAxis(glm::radians(d), glm::vec3(0.0f, 1.0f, 0.0f)) * arm;
            const glm::vec3 p = viewport()->camera().project(point, float(viewport()->width()), float(viewport()->height()));
            return glm::vec2(p.x, p.y);
        };
        return 1.0f / glm::length(at(degrees + 0.5f) - at(degrees - 0.5f));
    }
    QPoint pixelOf(const glm::vec3& world) const {
        const glm::vec3 p =
            viewport()->camera().project(world, float(viewport()->width()), float(viewport()->height()));
        return {int(std::lround(p.x)), int(std::lround(p.y))};
    }
    interplay::gizmo::Placement placement() const {
        const auto p = viewport()->gizmoPlacement();
        if (!p) qFatal("no gizmo is shown");
        return *p;
    }
    // A point of the handle's stroke that the cursor can take: 70 % along an arrow, the middle of a
    // plane square, the point of a ring nearest the eye.
    glm::vec3 grabPoint(Handle handle) const;
    // Presses on `from`, moves in `steps` to each of `path`'s pixels... here: straight to `to` in
    // steps, and releases (unless `release` is false).
    void drag(QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}, bool release = true, int waitMs = 0);
    // Presses on the ring point `center + arm`, moves the cursor round `axis` by `degrees` in
    // `steps` equal steps along the ring, and releases.
    void turnRing(const glm::vec3& center, const glm::vec3& arm, const glm::vec3& axis, float degrees, int steps);
    // The metres one pixel spans at the gizmo: the tolerance of a drag whose end is a whole pixel.
    float metresPerPixel() const { return placement().metresPerPixel; }

    // The Gizmo toolbar's button for action `name`.
    QToolButton* gizmoButton(const char* name) const {
        auto* bar = m_window->findChild<QToolBar*>(QStringLiteral("gizmoToolBar"));
        return bar ? qobject_cast<QToolButton*>(bar->widgetForAction(m_window->action(QLatin1String(name)))) : nullptr;
    }
    // How far, in steps of `step`, a drag of the x arrow towards `metres` along x moves the
    // sphere (Ctrl held with `modifiers`).
    float xArrowDragSteps(float metres, float step, Qt::KeyboardModifiers modifiers = {});

    std::unique_ptr<MainWindow> m_window;
};

int TestEditorGizmo::bodyNamed(const char* name) const {
    for (int i = 0; i < document()->bodyCount(); ++i) {
        if (document()->body(i).body.name == name) return i;
    }
    return -1;
}

void TestEditorGizmo::select(QList<int> bodies) {
    document()->setSelectedBodies(std::move(bodies));
    viewport()->grabViewport();
}

glm::vec3 TestEditorGizmo::grabPoint(Handle handle) const {
    const interplay::gizmo::Placement p = placement();
    const std::vector<glm::vec3> stroke = interplay::gizmo::handleStroke(handle, p);
    if (handle == Handle::AxisX || handle == Handle::AxisY || handle == Handle::AxisZ)
        return glm::mix(stroke[0], stroke[1], 0.7f);
    if (handle == Handle::PlaneYZ || handle == Handle::PlaneXZ || handle == Handle::PlaneXY)
        return 0.5f * (stroke[0] + stroke[2]);
    const glm::vec3 eye = viewport()->camera().eye();
    glm::vec3 nearest = stroke.front();
    for (const glm::vec3& point : stroke) {
        if (glm::length(point - eye) < glm::length(nearest - eye)) nearest = point;
    }
    return nearest;
}

void TestEditorGizmo::turnRing(const glm::vec3& center, const glm::vec3& arm, const glm::vec3& axis, float degrees,
                               int steps) {
    viewport()->setFocus();
    const QPoint from = pixelOf(center + arm);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
    QPoint to = from;
    for (int step = 1; step <= steps; ++step) {
        to = pixelOf(center + glm::angleAxis(glm::radians(degrees * float(step) / float(steps)), axis) * arm);
        QTest::mouseMove(viewport(), to);
    }
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
}

void TestEditorGizmo::drag(QPoint from, QPoint to, Qt::KeyboardModifiers modifiers, bool release, int waitMs) {
    viewport()->setFocus();
    QTest::mousePress(viewport(), Qt::LeftButton, modifiers, from);
    constexpr int kSteps = 10;
    for (int i = 1; i <= kSteps; ++i) {
        const QPoint at = from + (to - from) * i / kSteps;
        // QTest::mouseMove sends no modifiers; the gizmo reads Ctrl from the move events.
        QMouseEvent move(QEvent::MouseMove, at, viewport()->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, modifiers);
        QApplication::sendEvent(viewport(), &move);
        if (waitMs > 0) QTest::qWait(waitMs);
    }
    if (release) QTest::mouseRelease(viewport(), Qt::LeftButton, modifiers, to);
}

void TestEditorGizmo::initTestCase() { test_support::isolateSettings("test_editor_gizmo"); }

void TestEditorGizmo::cleanupTestCase() { test_support::removeSettings(); }

void TestEditorGizmo::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    auto& prompts = m_window->documentManager()->prompts();
    prompts.unsavedChanges = [](const QString&) { return interplay::DocumentManager::UnsavedChoice::Discard; };
    prompts.error = [](const QString& title, const QString& text, const QString& details) {
        QFAIL(qPrintable(title + ": " + text + '\n' + details));
    };
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    viewport()->grabViewport();                                                      // the first frame frames the scene
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Move));  // shown from the start
}

void TestEditorGizmo::cleanup() {
    if (m_window) m_window->simulation()->pause();
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorGizmo::xArrowDragMovesAlongXOnly() {
    const int sphere = bodyNamed("sphere");
    select({sphere});
    const simcore::BodyCreationSettings start = document()->body(sphere).body;
    QCOMPARE(placement().center, start.position);
    // The cursor goes from the arrow to where that point of it would be 1.5 m further along x.
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    constexpr float kMetres = 1.5f;
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(kMetres, 0.0f, 0.0f)));

    const simcore::BodyCreationSettings& moved = document()->body(sphere).body;
    QVERIFY2(
        std::abs(moved.position.x - start.position.x - kMetres) < 2.0f * metresPerPixel(),
        qPrintable(
            QStringLiteral("moved %1 m, %2 m a pixel").arg(moved.position.x - start.position.x).arg(metresPerPixel())));
    QCOMPARE(moved.position.y, start.position.y);
    QCOMPARE(moved.position.z, start.position.z);
    QCOMPARE(moved.orientation, start.orientation);
    // The live body went with it, and the gizmo with the body.
    const simcore::World* world = m_window->simulation()->world();
    const simcore::BodyId id = m_window->simulation()->bodyIds()[std::size_t(sphere)];
    QCOMPARE(world->position(id), moved.position);
    QCOMPARE(placement().center, moved.position);

    QUndoStack* stack = document()->undoStack();
    QCOMPARE(stack->count(), 1);
    QCOMPARE(stack->text(0), QStringLiteral("Move sphere"));
    QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document()->body(sphere).body.position, start.position);
}

void TestEditorGizmo::ringDragTurnsAboutTheRingsAxis() {
    const int box = bodyNamed("box");  // turned 0.35 rad about y to begin with
    select({box});
    QTest::keyClick(viewport(), Qt::Key_E);
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Rotate));
    QVERIFY(m_window->action(QStringLiteral("gizmoRotate"))->isChecked());
    QVERIFY(!m_window->action(QStringLiteral("gizmoMove"))->isChecked());
    viewport()->grabViewport();
    const simcore::BodyCreationSettings start = document()->body(box).body;
    const interplay::gizmo::Placement p = placement();
    // Drag the x ring's near point round by 40° about x, in steps along the ring.
    const glm::vec3 arm = grabPoint(Handle::RingX) - p.center;
    turnRing(p.center, arm, glm::vec3(1.0f, 0.0f, 0.0f), 40.0f, 8);

    const simcore::BodyCreationSettings& turned = document()->body(box).body;
    QCOMPARE(turned.position, start.position);  // one body turns about its own centre
    const glm::quat turn = turned.orientation * glm::inverse(start.orientation);
    const float degrees = glm::degrees(glm::angle(turn));
    // The pixel grid moves the cursor by up to half a pixel on an 85 px ring: 0.4° or so.
    QVERIFY2(std::abs(degrees - 40.0f) < 1.0f, qPrintable(QString::number(degrees)));
    const glm::vec3 axis = glm::axis(turn);
    QVERIFY2(axis.x > 0.9999f, qPrintable(QStringLiteral("axis %1 %2 %3").arg(axis.x).arg(axis.y).arg(axis.z)));
    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->text(0), QStringLiteral("Rotate box"));
    document()->undoStack()->undo();
    QCOMPARE(document()->body(box).body.orientation, start.orientation);
}

void TestEditorGizmo::ctrlSnapsToTheSettingsSteps_data() {
    QTest::addColumn<double>("gridStep");
    QTest::addColumn<double>("angleStep");
    QTest::newRow("defaults 0.1 m, 15°") << 0.0 << 0.0;
    QTest::newRow("0.25 m, 10°") << 0.25 << 10.0;
}

void TestEditorGizmo::ctrlSnapsToTheSettingsSteps() {
    QFETCH(double, gridStep);
    QFETCH(double, angleStep);
    if (gridStep > 0.0) {
        QSettings().setValue(QLatin1String(interplay::kGizmoGridStepKey), gridStep);
        QSettings().setValue(QLatin1String(interplay::kGizmoAngleStepKey), angleStep);
    }
    const float grid = gridStep > 0.0 ? float(gridStep) : float(interplay::kDefaultGizmoGridStep);
    const float angle = angleStep > 0.0 ? float(angleStep) : float(interplay::kDefaultGizmoAngleStep);
    const int sphere = bodyNamed("sphere");  // at x = -2, a whole number of either step
    select({sphere});
    const simcore::BodyCreationSettings start = document()->body(sphere).body;
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(0.93f, 0.0f, 0.0f)), Qt::ControlModifier);
    const float moved = document()->body(sphere).body.position.x - start.position.x;
    const float steps = moved / grid;
    QVERIFY2(std::abs(steps - std::round(steps)) < 1e-3f && std::round(steps) >= 3.0f,
             qPrintable(QStringLiteral("moved %1 m").arg(moved)));
    QVERIFY2(std::abs(moved - 0.93f) <= 0.5f * grid + 2.0f * metresPerPixel(), qPrintable(QString::number(moved)));

    // Turning, 33° swept: a whole number of angle steps, the nearest one. 33° lies 2° or more from
    // every rounding boundary of either step (22.5, 37.5; 25, 35), more than a pixel's worth of
    // angle on the ring (85 px: 0.7°).
    QTest::keyClick(viewport(), Qt::Key_E);
    viewport()->grabViewport();
    const glm::quat startOrientation = document()->body(sphere).body.orientation;
    const interplay::gizmo::Placement p = placement();
    const glm::vec3 arm = grabPoint(Handle::RingY) - p.center;
    viewport()->setFocus();
    const QPoint from = pixelOf(p.center + arm);
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::ControlModifier, from);
    QPoint to = from;
    for (int step = 1; step <= 8; ++step) {
        to = pixelOf(p.center + glm::angleAxis(glm::radians(33.0f * step / 8.0f), glm::vec3(0.0f, 1.0f, 0.0f)) * arm);
        QMouseEvent move(QEvent::MouseMove, to, viewport()->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                         Qt::ControlModifier);
        QApplication::sendEvent(viewport(), &move);
    }
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ControlModifier, to);
    const glm::quat turn = document()->body(sphere).body.orientation * glm::inverse(startOrientation);
    const float degrees = glm::degrees(glm::angle(turn));
    QVERIFY2(std::abs(degrees - angle * std::round(33.0f / angle)) < 0.01f, qPrintable(QString::number(degrees)));
    QCOMPARE(document()->undoStack()->count(), 2);  // one entry per gesture
}

void TestEditorGizmo::multiSelectionMovesTogether() {
    const int sphere = bodyNamed("sphere"), cylinder = bodyNamed("cylinder");
    select({sphere, cylinder});
    const glm::vec3 sphereStart = document()->body(sphere).body.position;
    const glm::vec3 cylinderStart = document()->body(cylinder).body.position;
    QVERIFY(glm::length(placement().center - 0.5f * (sphereStart + cylinderStart)) < 1e-5f);
    // The xz plane handle, carried 1 m along z and 0.5 m along x.
    const glm::vec3 grabbed = grabPoint(Handle::PlaneXZ);
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(0.5f, 0.0f, 1.0f)));
    const glm::vec3 sphereOffset = document()->body(sphere).body.position - sphereStart;
    const glm::vec3 cylinderOffset = document()->body(cylinder).body.position - cylinderStart;
    QVERIFY(glm::length(sphereOffset - cylinderOffset) < 1e-5f);
    QCOMPARE(sphereOffset.y, 0.0f);  // in the plane
    QVERIFY2(glm::length(sphereOffset - glm::vec3(0.5f, 0.0f, 1.0f)) < 3.0f * metresPerPixel(),
             qPrintable(QStringLiteral("%1 %2 %3").arg(sphereOffset.x).arg(sphereOffset.y).arg(sphereOffset.z)));
    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->text(0), QStringLiteral("Move 2 Bodies"));

    // Turned together a quarter of the way round y: about their centre, each keeping its place
    // relative to the other.
    QTest::keyClick(viewport(), Qt::Key_E);
    viewport()->grabViewport();
    const glm::vec3 a = document()->body(sphere).body.position, b = document()->body(cylinder).body.position;
    const interplay::gizmo::Placement p = placement();
    const glm::vec3 arm = grabPoint(Handle::RingY) - p.center;
    turnRing(p.center, arm, glm::vec3(0.0f, 1.0f, 0.0f), 90.0f, 9);
    const glm::vec3 a2 = document()->body(sphere).body.position, b2 = document()->body(cylinder).body.position;
    QVERIFY(glm::length(0.5f * (a2 + b2) - 0.5f * (a + b)) < 1e-4f);  // the centre stays
    QVERIFY(std::abs(glm::length(a2 - b2) - glm::length(a - b)) < 1e-4f);
    const float turned = glm::degrees(std::acos(glm::dot(glm::normalize(a2 - b2), glm::normalize(a - b))));
    // The press and the release are whole pixels, each up to half a pixel off in x and y.
    const float tolerance = 0.75f * (ringDegreesPerPixel(p.center, arm, 0.0f) + ringDegreesPerPixel(p.center, arm, 90.0f));
    QVERIFY2(std::abs(turned - 90.0f) < tolerance,
             qPrintable(QStringLiteral("turned %1°, allowed ±%2°").arg(turned).arg(tolerance)));
    QCOMPARE(document()->undoStack()->count(), 2);
}

void TestEditorGizmo::localSpaceFollowsTheBodysAxes() {
    const int box = bodyNamed("box");  // turned 0.35 rad about y
    select({box});
    QTest::keyClick(viewport(), Qt::Key_L);
    QCOMPARE(viewport()->gizmoSpace(), interplay::gizmo::Space::Local);
    viewport()->grabViewport();
    const simcore::BodyCreationSettings start = document()->body(box).body;
    const glm::vec3 localX = start.orientation * glm::vec3(1.0f, 0.0f, 0.0f);
    QVERIFY(glm::length(placement().axes[0] - localX) < 1e-5f);
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    drag(pixelOf(grabbed), pixelOf(grabbed + localX));
    const glm::vec3 offset = document()->body(box).body.position - start.position;
    // Along the body's own x: nothing across it.
    QVERIFY2(glm::length(offset - glm::dot(offset, localX) * localX) < 1e-5f,
             qPrintable(QString::number(glm::length(offset))));
    QVERIFY(std::abs(glm::dot(offset, localX) - 1.0f) < 2.0f * metresPerPixel());
}

void TestEditorGizmo::duringPlayTheBodyFollows() {
    const int cylinder = bodyNamed("cylinder");
    select({cylinder});
    interplay::SimulationController* simulation = m_window->simulation();
    // Looked up each time: the world is rebuilt from the scene before its first step.
    const auto livePosition = [&] {
        return simulation->world()->position(simulation->bodyIds()[std::size_t(cylinder)]);
    };
    const glm::vec3 authoredStart = document()->body(cylinder).body.position;
    simulation->play();
    QTRY_VERIFY_WITH_TIMEOUT(glm::length(livePosition() - authoredStart) > 0.05f, 10000);  // it falls
    viewport()->grabViewport();
    const glm::vec3 liveStart = livePosition();
    QCOMPARE(placement().center, liveStart);  // the gizmo sits on the live body
    const glm::vec3 grabbed = grabPoint(Handle::AxisZ);
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(0.0f, 0.0f, 2.0f)), {}, true, 30);
    QVERIFY(simulation->isPlaying());
    const glm::vec3 live = livePosition();
    const float authoredMoved = document()->body(cylinder).body.position.z - authoredStart.z;
    // The live body moved by what the drag moved the authored one (the run adds a little of its own).
    QVERIFY2(std::abs(authoredMoved - 2.0f) < 3.0f * metresPerPixel(), qPrintable(QString::number(authoredMoved)));
    QVERIFY2(std::abs(live.z - liveStart.z - authoredMoved) < 0.05f,
             qPrintable(QStringLiteral("live %1, authored %2").arg(live.z - liveStart.z).arg(authoredMoved)));
    QCOMPARE(document()->undoStack()->count(), 1);
}

void TestEditorGizmo::duringARunSeveralTurnFromTheirLivePoses() {
    // Several bodies turned during a run turn from where the run has them, as one body does; they
    // used to jump to their authored poses. Paused after the fall, so that only the turn moves them.
    const int sphere = bodyNamed("sphere"), cylinder = bodyNamed("cylinder");
    select({sphere, cylinder});
    interplay::SimulationController* simulation = m_window->simulation();
    const auto live = [&](int body) { return simulation->bodyIds()[std::size_t(body)]; };
    const glm::vec3 authoredStart = document()->body(cylinder).body.position;
    simulation->play();
    QTRY_VERIFY_WITH_TIMEOUT(glm::length(simulation->world()->position(live(cylinder)) - authoredStart) > 0.3f, 10000);
    simulation->pause();
    const simcore::World* world = simulation->world();
    const glm::vec3 liveStart[] = {world->position(live(sphere)), world->position(live(cylinder))};
    const glm::quat liveTurnStart[] = {world->orientation(live(sphere)), world->orientation(live(cylinder))};
    const simcore::BodyCreationSettings authored[] = {document()->body(sphere).body, document()->body(cylinder).body};

    QTest::keyClick(viewport(), Qt::Key_E);
    viewport()->grabViewport();
    const interplay::gizmo::Placement p = placement();
    const glm::vec3 arm = grabPoint(Handle::RingY) - p.center;
    turnRing(p.center, arm, glm::vec3(0.0f, 1.0f, 0.0f), 60.0f, 6);

    QCOMPARE(document()->undoStack()->count(), 1);
    QCOMPARE(document()->undoStack()->text(0), QStringLiteral("Rotate 2 Bodies"));
    const int bodies[] = {sphere, cylinder};
    for (int i = 0; i < 2; ++i) {
        const simcore::BodyCreationSettings& turned = document()->body(bodies[i]).body;
        const glm::quat turn = turned.orientation * glm::inverse(authored[i].orientation);
        QVERIFY2(glm::degrees(glm::angle(turn)) > 40.0f, qPrintable(QString::number(glm::degrees(glm::angle(turn)))));
        // The live body moved and turned by what the authored one did, from its live pose: the
        // whole run's fall stays (0.3 m or more), where a jump would have undone it.
        const glm::vec3 liveMoved = world->position(live(bodies[i])) - liveStart[i];
        const glm::vec3 authoredMoved = turned.position - authored[i].position;
        QVERIFY2(glm::length(liveMoved - authoredMoved) < 1e-4f,
                 qPrintable(QStringLiteral("body %1: live moved %2 m, authored %3 m")
                                .arg(i)
                                .arg(glm::length(liveMoved))
                                .arg(glm::length(authoredMoved))));
        const glm::quat liveTurn = world->orientation(live(bodies[i])) * glm::inverse(liveTurnStart[i]);
        QVERIFY2(std::abs(glm::dot(liveTurn, turn)) > 1.0f - 1e-5f, qPrintable(QStringLiteral("body %1").arg(i)));
    }
    // Undo turns the live bodies back to where the run had them.
    document()->undoStack()->undo();
    for (int i = 0; i < 2; ++i) QVERIFY(glm::length(world->position(live(bodies[i])) - liveStart[i]) < 1e-4f);
}

void TestEditorGizmo::escapeOrRightClickCancels_data() {
    QTest::addColumn<bool>("rightClick");
    QTest::newRow("Escape") << false;
    QTest::newRow("right click") << true;
}

void TestEditorGizmo::escapeOrRightClickCancels() {
    QFETCH(bool, rightClick);
    const int sphere = bodyNamed("sphere");
    select({sphere});
    const simcore::SceneBody start = document()->body(sphere);
    const glm::vec3 grabbed = grabPoint(Handle::AxisY);
    const QPoint to = pixelOf(grabbed + glm::vec3(0.0f, 1.0f, 0.0f));
    drag(pixelOf(grabbed), to, {}, false);
    QVERIFY(document()->body(sphere).body.position.y > start.body.position.y + 0.5f);  // it moved
    if (rightClick) {
        QTest::mousePress(viewport(), Qt::RightButton, {}, to);
        QTest::mouseRelease(viewport(), Qt::RightButton, {}, to);
    } else {
        QTest::keyClick(viewport(), Qt::Key_Escape);
    }
    QVERIFY(interplay::sameSceneBody(document()->body(sphere), start));
    QCOMPARE(document()->undoStack()->count(), 0);
    QVERIFY(document()->undoStack()->isClean());
    // The left button's release after the cancel moves nothing.
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to + QPoint(30, 0));
    QVERIFY(interplay::sameSceneBody(document()->body(sphere), start));
    QCOMPARE(document()->undoStack()->count(), 0);
}

void TestEditorGizmo::movingAJointedBodyCarriesItsAnchors() {
    QString error;
    QVERIFY2(m_window->documentManager()->openFile(QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/ragdoll.json"), &error),
             qPrintable(error));
    viewport()->grabViewport();
    const int forearm = bodyNamed("left forearm");
    int elbow = -1;
    for (int j = 0; j < document()->jointCount(); ++j) {
        if (document()->joint(j).joint.name == "left elbow") elbow = j;
    }
    QVERIFY(forearm >= 0 && elbow >= 0);
    select({forearm});
    const glm::vec3 start = document()->body(forearm).body.position;
    const glm::vec3 anchorStart = document()->joint(elbow).joint.anchor;
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(0.6f, 0.0f, 0.0f)));
    const glm::vec3 offset = document()->body(forearm).body.position - start;
    QVERIFY(offset.x > 0.4f);
    QVERIFY(glm::length(document()->joint(elbow).joint.anchor - (anchorStart + offset)) < 1e-5f);
    QCOMPARE(document()->undoStack()->count(), 1);  // body and anchor in one entry
    document()->undoStack()->undo();
    QCOMPARE(document()->joint(elbow).joint.anchor, anchorStart);
}

void TestEditorGizmo::pressesAwayFromTheHandlesStillDragBodies() {
    // The gizmo leaves its centre free: a drag from a selected body's centre moves it on the
    // horizontal plane as before, and a press on another body selects that one.
    const int sphere = bodyNamed("sphere"), cylinder = bodyNamed("cylinder");
    select({sphere});
    const glm::vec3 start = document()->body(sphere).body.position;
    drag(pixelOf(start), pixelOf(start) + QPoint(0, 40));
    const glm::vec3 moved = document()->body(sphere).body.position;
    QCOMPARE(moved.y, start.y);
    QVERIFY(glm::length(moved - start) > 0.1f);
    const QPoint onCylinder = pixelOf(document()->body(cylinder).body.position);
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, onCylinder);
    QCOMPARE(document()->selectedBodies(), QList<int>{cylinder});
    // With no gizmo (W pressed again) the arrows' pixels are the scene's.
    QTest::keyClick(viewport(), Qt::Key_W);
    QCOMPARE(viewport()->gizmoMode(), std::nullopt);
    QVERIFY(!viewport()->gizmoPlacement());
}

void TestEditorGizmo::hoveredHandleLightsUp() {
    select({bodyNamed("sphere")});
    // The middle of the x arrow's shaft, in the framebuffer's pixels.
    const glm::vec3 onShaft = grabPoint(Handle::AxisX);
    const QPoint pixel = pixelOf(onShaft);
    const auto colorAt = [&] {
        const QImage image = viewport()->grabViewport();
        return image.pixelColor(QPoint(pixel * image.devicePixelRatio()));
    };
    QTest::mouseMove(viewport(), pixel + QPoint(0, 150));  // away from every handle
    const QColor idle = colorAt();
    // The x arrow is red: much more red than green.
    QVERIFY2(idle.red() > 180 && idle.green() < 140, qPrintable(idle.name()));
    QTest::mouseMove(viewport(), pixel);
    const QColor hovered = colorAt();
    // Lit: pale yellow, as bright in green as in red.
    QVERIFY2(hovered.red() > 200 && hovered.green() > 200, qPrintable(hovered.name()));
    QTest::mouseMove(viewport(), pixel + QPoint(0, 150));
    QCOMPARE(colorAt(), idle);
    // Nor does it stay lit when the cursor leaves the view from over it.
    QTest::mouseMove(viewport(), pixel);
    QCOMPARE(colorAt(), hovered);
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(viewport(), &leave);
    QCOMPARE(colorAt(), idle);
}

void TestEditorGizmo::deletingTheBodiesMidDragEndsTheDrag() {
    const int sphere = bodyNamed("sphere");
    select({sphere});
    const int bodies = document()->bodyCount();
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    const QPoint to = pixelOf(grabbed + glm::vec3(1.0f, 0.0f, 0.0f));
    drag(pixelOf(grabbed), to, {}, false);
    const glm::vec3 moved = document()->body(sphere).body.position;
    QTest::keyClick(viewport(), Qt::Key_Delete);
    QCOMPARE(document()->bodyCount(), bodies - 1);
    // The rest of the gesture moves nothing (body `sphere` is now the next one), and a cancel
    // leaves the history as it is: the move, then the delete.
    const glm::vec3 next = document()->body(sphere).body.position;
    QTest::mouseMove(viewport(), to + QPoint(40, 0));
    QTest::keyClick(viewport(), Qt::Key_Escape);
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to + QPoint(40, 0));
    QCOMPARE(document()->body(sphere).body.position, next);
    QUndoStack* stack = document()->undoStack();
    QCOMPARE(stack->count(), 2);
    stack->undo();
    QCOMPARE(document()->body(sphere).body.position, moved);
}

void TestEditorGizmo::flyKeysStillFlyDuringARightDrag() {
    // W and E are the gizmo's keys, and also fly forward and up while the right button is held.
    const glm::vec3 eye = viewport()->camera().eye();
    const glm::vec3 forward = viewport()->camera().forward();
    const QPoint centre(viewport()->width() / 2, viewport()->height() / 2);
    viewport()->setFocus();
    QTest::mousePress(viewport(), Qt::RightButton, {}, centre);
    QTest::keyPress(viewport(), Qt::Key_W);
    QTest::keyPress(viewport(), Qt::Key_E);
    // Forward (which looks down a little) and up together: along both.
    QTRY_VERIFY(glm::dot(viewport()->camera().eye() - eye, forward) > 0.5f &&
                glm::dot(viewport()->camera().eye() - eye, viewport()->camera().up()) > 0.5f);
    QTest::keyRelease(viewport(), Qt::Key_E);
    QTest::keyRelease(viewport(), Qt::Key_W);
    QTest::mouseRelease(viewport(), Qt::RightButton, {}, centre);
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Move));
    // Without the right button, E is the rotate gizmo's key again.
    QTest::keyClick(viewport(), Qt::Key_E);
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Rotate));
}

float TestEditorGizmo::xArrowDragSteps(float metres, float step, Qt::KeyboardModifiers modifiers) {
    const int sphere = bodyNamed("sphere");  // at x = -2, a whole number of any step used here
    select({sphere});
    const float start = document()->body(sphere).body.position.x;
    const glm::vec3 grabbed = grabPoint(Handle::AxisX);
    drag(pixelOf(grabbed), pixelOf(grabbed + glm::vec3(metres, 0.0f, 0.0f)), modifiers);
    return (document()->body(sphere).body.position.x - start) / step;
}

void TestEditorGizmo::toolbarButtonsAreTheKeysActions() {
    QToolButton* move = gizmoButton("gizmoMove");
    QToolButton* rotate = gizmoButton("gizmoRotate");
    QToolButton* local = gizmoButton("gizmoLocal");
    QToolButton* snap = gizmoButton("gizmoSnap");
    QVERIFY(move && rotate && local && snap);
    QCOMPARE(move->text(), QStringLiteral("Move"));
    QVERIFY(move->isChecked() && !rotate->isChecked());
    // A click on Rotate is E: one group, so Move goes off.
    QTest::mouseClick(rotate, Qt::LeftButton);
    QCOMPARE(viewport()->gizmoMode(), std::optional(interplay::gizmo::Mode::Rotate));
    QVERIFY(rotate->isChecked() && !move->isChecked());
    // W is a click on Move; pressed again, no gizmo and neither button down.
    QTest::keyClick(viewport(), Qt::Key_W);
    QVERIFY(move->isChecked() && !rotate->isChecked());
    QTest::mouseClick(move, Qt::LeftButton);
    QCOMPARE(viewport()->gizmoMode(), std::nullopt);
    QVERIFY(!move->isChecked() && !rotate->isChecked());
    // Local and Snap are toggles of their own, the buttons and L and Y alike.
    QTest::mouseClick(local, Qt::LeftButton);
    QCOMPARE(viewport()->gizmoSpace(), interplay::gizmo::Space::Local);
    QTest::keyClick(viewport(), Qt::Key_L);
    QCOMPARE(viewport()->gizmoSpace(), interplay::gizmo::Space::World);
    QVERIFY(!local->isChecked());
    QTest::keyClick(viewport(), Qt::Key_Y);
    QVERIFY(viewport()->gizmoSnapping() && snap->isChecked());
    QTest::mouseClick(snap, Qt::LeftButton);
    QVERIFY(!viewport()->gizmoSnapping() && !snap->isChecked());
    QCOMPARE(document()->undoStack()->count(), 0);  // tools, not edits
}

void TestEditorGizmo::snapButtonSnapsWithoutCtrl() {
    // A step of many pixels at this distance (the default view: about 0.03 m a pixel).
    constexpr float grid = 0.5f;
    QSettings().setValue(QLatin1String(interplay::kGizmoGridStepKey), grid);
    QTest::mouseClick(gizmoButton("gizmoSnap"), Qt::LeftButton);
    select({bodyNamed("sphere")});
    // 2.5 m asked: 5 steps, 0.25 m (more than two pixels) from either rounding boundary.
    QVERIFY2(2.0f * metresPerPixel() < 0.25f, qPrintable(QString::number(metresPerPixel())));
    const float snapped = xArrowDragSteps(2.5f, grid);
    QVERIFY2(std::abs(snapped - 5.0f) < 1e-3f, qPrintable(QString::number(snapped)));
    // Ctrl held drags freely now: 2.25 m to within two pixels, which holds no whole step (2 and
    // 2.5 m are 0.25 m away).
    document()->undoStack()->undo();
    viewport()->grabViewport();
    const float free = xArrowDragSteps(2.25f, grid, Qt::ControlModifier);
    QVERIFY2(std::abs(free * grid - 2.25f) < 2.0f * metresPerPixel(), qPrintable(QString::number(free * grid)));
    QVERIFY2(std::abs(free - std::round(free)) > 1e-3f, qPrintable(QString::number(free)));
}

void TestEditorGizmo::preferencesStepsApplyToTheNextDrag() {
    QAction* preferences = m_window->action(QStringLiteral("preferences"));
    QVERIFY(!preferences->shortcut().isEmpty());
    QTest::keySequence(m_window.get(), preferences->shortcut());
    auto* dialog = m_window->findChild<interplay::PreferencesDialog*>();
    QVERIFY(dialog);
    QVERIFY(QTest::qWaitForWindowExposed(dialog));
    QCOMPARE(dialog->gridStepField()->value(), interplay::kDefaultGizmoGridStep);
    QCOMPARE(dialog->angleStepField()->value(), interplay::kDefaultGizmoAngleStep);
    // Typed and committed with Enter: stored at once.
    QLineEdit* gridText = dialog->gridStepField()->findChild<QLineEdit*>();
    dialog->gridStepField()->setFocus();
    gridText->selectAll();
    QTest::keyClicks(gridText, QStringLiteral("0.25"));
    QTest::keyClick(gridText, Qt::Key_Return);
    QCOMPARE(QSettings().value(QLatin1String(interplay::kGizmoGridStepKey)).toDouble(), 0.25);
    QLineEdit* angleText = dialog->angleStepField()->findChild<QLineEdit*>();
    dialog->angleStepField()->setFocus();
    angleText->selectAll();
    QTest::keyClicks(angleText, QStringLiteral("10"));
    QTest::keyClick(angleText, Qt::Key_Enter);  // the keypad's
    QCOMPARE(QSettings().value(QLatin1String(interplay::kGizmoAngleStepKey)).toDouble(), 10.0);
    // Out of range is held at the field's bounds, never stored as zero.
    gridText->selectAll();
    dialog->gridStepField()->setFocus();
    QTest::keyClicks(gridText, QStringLiteral("0"));
    QTest::keyClick(gridText, Qt::Key_Return);
    QVERIFY(QSettings().value(QLatin1String(interplay::kGizmoGridStepKey)).toDouble() > 0.0);
    dialog->gridStepField()->setValue(0.25);
    dialog->close();

    // The next Ctrl-drag snaps to 0.25 m: 0.95 m becomes 1 m.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    viewport()->grabViewport();
    const float steps = xArrowDragSteps(0.95f, 0.25f, Qt::ControlModifier);
    QVERIFY2(std::abs(steps - 4.0f) < 1e-3f, qPrintable(QString::number(steps)));
    QCOMPARE(document()->undoStack()->count(), 1);  // preferences are no edit of the scene
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorGizmo test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_gizmo.moc"
