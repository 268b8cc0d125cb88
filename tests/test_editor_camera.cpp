// The viewport's camera views in the whole window, with real OpenGL under Xvfb and real QTest key
// and mouse events on the viewport: Home frames every body with a margin, numpad 1 / 3 / 7 (Ctrl
// for the opposite way) look along -Z / -X / -Y, numpad 5 toggles the orthographic projection,
// under which rays are parallel and a click still selects and a drag still moves a body. Camera
// bookmarks: Ctrl+B adds the view, Ctrl+N stores it, N shows it again, the menu renames and deletes,
// each edit one undo entry, and they come back from the saved file.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/camera_bookmarks.h"
#include "app/viewport/viewport.h"

#include "simcore/shapes/shape.h"
#include "simcore/world/world.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QTemporaryDir>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTest>
#include <QUndoStack>

#include <glm/glm.hpp>

#include <memory>

using interplay::MainWindow;
using interplay::Viewport;

class TestEditorCamera : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void homeFramesEveryBody();
    void numpadKeysLookAlongTheAxes();
    void numpadFiveTogglesOrthographicAndPickingStillWorks();
    void bookmarksAreAddedShownRenamedAndDeletedWithUndo();
    void bookmarksComeBackFromTheSavedFile();
    void aBadBookmarkNameIsRefused();

private:
    Viewport* viewport() const { return m_window->viewport(); }
    simcore::Aabb sceneBounds() const;
    glm::vec3 project(const glm::vec3& world) const {
        return viewport()->camera().project(world, static_cast<float>(viewport()->width()),
                                            static_cast<float>(viewport()->height()));
    }
    bool inView(const glm::vec3& world) const {
        const glm::vec3 p = project(world);
        return p.z <= 1.0f && p.x >= 0.0f && p.y >= 0.0f && p.x <= viewport()->width() && p.y <= viewport()->height();
    }

    // The camera shows `bookmark`'s view (angles as the camera keeps them).
    void verifyShows(const simcore::CameraBookmark& bookmark) const {
        const interplay::Camera& camera = viewport()->camera();
        QCOMPARE(camera.target(), bookmark.target);
        QCOMPARE(camera.yawDegrees(), bookmark.yawDegrees);
        QCOMPARE(camera.pitchDegrees(), bookmark.pitchDegrees);
        QCOMPARE(camera.distance(), bookmark.distance);
        QCOMPARE(camera.isOrthographic(), bookmark.orthographic);
        QCOMPARE(m_window->action("orthographic")->isChecked(), bookmark.orthographic);
    }
    const std::vector<simcore::CameraBookmark>& bookmarks() const {
        return m_window->document()->scene().editor.cameraBookmarks;
    }
    // The name the next prompt answers with (nothing: cancelled).
    void answerPrompts(std::optional<QString> name) {
        m_window->cameraBookmarks()->setNamePrompt([name](const QString&, const QString&) { return name; });
    }

    std::unique_ptr<MainWindow> m_window;
};

simcore::Aabb TestEditorCamera::sceneBounds() const {
    const simcore::World* world = m_window->simulation()->world();
    simcore::Aabb box;
    for (const simcore::BodyId id : world->bodyIds()) {
        box.grow(simcore::worldBounds(world->shape(id), {world->position(id), world->orientation(id)}));
    }
    return box;
}

void TestEditorCamera::initTestCase() {
    test_support::isolateSettings("test_editor_camera");
}

void TestEditorCamera::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorCamera::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    viewport()->grabViewport();
    viewport()->setFocus();
    QVERIFY(QTest::qWaitFor([this] { return viewport()->hasFocus(); }));
    QVERIFY(m_window->simulation()->world()->bodyCount() >= 2);
}

void TestEditorCamera::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorCamera::homeFramesEveryBody() {
    // Look away from the scene, close up: no body is in view.
    interplay::Camera& camera = viewport()->camera();
    camera.setTarget(glm::vec3(500.0f, 50.0f, 500.0f));
    camera.setDistance(1.0f);
    const simcore::World* world = m_window->simulation()->world();
    for (const simcore::BodyId id : world->bodyIds()) QVERIFY(!inView(world->position(id)));

    QTest::keyClick(viewport(), Qt::Key_Home);
    for (const simcore::BodyId id : world->bodyIds()) {
        QVERIFY2(inView(world->position(id)), qPrintable(QString("body %1").arg(id.index)));
    }
    // The bounding sphere is not clipped: its rim along the camera's axes stays inside the view,
    // and the margin leaves it short of the edges (it fills about 80 % of the narrower side).
    const simcore::Aabb box = sceneBounds();
    const glm::vec3 centre = 0.5f * (box.min + box.max);
    const float radius = 0.5f * glm::length(box.max - box.min);
    for (const glm::vec3& rim : {centre + radius * camera.right(), centre - radius * camera.right(),
                                 centre + radius * camera.up(), centre - radius * camera.up()}) {
        QVERIFY(inView(rim));
    }
    const float rimPixels = glm::length(glm::vec2(project(centre + radius * camera.up())) - glm::vec2(project(centre)));
    const float halfView = 0.5f * static_cast<float>(std::min(viewport()->width(), viewport()->height()));
    QVERIFY2(rimPixels < 0.9f * halfView && rimPixels > 0.6f * halfView, qPrintable(QString::number(rimPixels)));

    // F with nothing selected frames the same; with a selection it frames the selection, closer.
    const float allDistance = camera.distance();
    camera.setDistance(300.0f);
    m_window->document()->setSelectedBodies({});
    QTest::keyClick(viewport(), Qt::Key_F);
    QCOMPARE(camera.distance(), allDistance);
    m_window->document()->setSelectedBodies({1});
    QTest::keyClick(viewport(), Qt::Key_F);
    QVERIFY(camera.distance() < allDistance);
}

void TestEditorCamera::numpadKeysLookAlongTheAxes() {
    const interplay::Camera& camera = viewport()->camera();
    const struct {
        Qt::Key key;
        Qt::KeyboardModifiers modifiers;
        glm::vec3 forward;
    } views[] = {
        {Qt::Key_1, Qt::KeypadModifier, {0.0f, 0.0f, -1.0f}},
        {Qt::Key_3, Qt::KeypadModifier, {-1.0f, 0.0f, 0.0f}},
        {Qt::Key_7, Qt::KeypadModifier, {0.0f, -1.0f, 0.0f}},
        {Qt::Key_1, Qt::KeypadModifier | Qt::ControlModifier, {0.0f, 0.0f, 1.0f}},
        {Qt::Key_3, Qt::KeypadModifier | Qt::ControlModifier, {1.0f, 0.0f, 0.0f}},
        {Qt::Key_7, Qt::KeypadModifier | Qt::ControlModifier, {0.0f, 1.0f, 0.0f}},
    };
    for (const auto& view : views) {
        const glm::vec3 target = camera.target();
        const float distance = camera.distance();
        QTest::keyClick(viewport(), view.key, view.modifiers);
        QVERIFY2(glm::dot(camera.forward(), view.forward) > 0.9998f,
                 qPrintable(QString("key %1: %2 %3 %4")
                                .arg(QKeySequence(view.key | view.modifiers).toString())
                                .arg(camera.forward().x).arg(camera.forward().y).arg(camera.forward().z)));
        QCOMPARE(camera.target(), target);
        QCOMPARE(camera.distance(), distance);
    }
}

void TestEditorCamera::numpadFiveTogglesOrthographicAndPickingStillWorks() {
    QAction* ortho = m_window->action("orthographic");
    QVERIFY(!viewport()->camera().isOrthographic());
    QTest::keyClick(viewport(), Qt::Key_7, Qt::KeypadModifier);
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    QVERIFY(viewport()->camera().isOrthographic());
    QVERIFY(ortho->isChecked());
    QTest::keyClick(viewport(), Qt::Key_Home);

    // Rays are parallel now.
    const auto [originA, directionA] = viewport()->rayThrough(QPointF(10, 10));
    const auto [originB, directionB] = viewport()->rayThrough(QPointF(viewport()->width() - 10, viewport()->height() - 10));
    QVERIFY(glm::dot(directionA, directionB) > 0.99999f);
    QVERIFY(glm::length(originA - originB) > 1.0f);

    // The topmost movable body, seen from above, is clicked at its centre's pixel.
    const simcore::World* world = m_window->simulation()->world();
    const auto& ids = m_window->simulation()->bodyIds();
    int top = -1;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (world->motionType(ids[i]) == simcore::MotionType::Static) continue;
        if (top < 0 || world->position(ids[i]).y > world->position(ids[static_cast<std::size_t>(top)]).y) {
            top = static_cast<int>(i);
        }
    }
    QVERIFY(top >= 0);
    const glm::vec3 before = m_window->document()->body(top).body.position;
    const glm::vec3 projected = project(before);
    const QPoint pixel(qRound(projected.x), qRound(projected.y));
    QVERIFY(viewport()->rect().contains(pixel));
    m_window->document()->setSelectedBodies({});
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, pixel);
    QCOMPARE(m_window->document()->selectedBodies(), QList<int>{top});

    // A drag 60 px to the right moves it along +X by 60 px' worth of metres.
    const int entries = m_window->document()->undoStack()->count();
    QTest::mousePress(viewport(), Qt::LeftButton, {}, pixel);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(viewport(), pixel + QPoint(6 * i, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, pixel + QPoint(60, 0));
    const glm::vec3 after = m_window->document()->body(top).body.position;
    const glm::vec3 expectedPixel = projected + glm::vec3(60.0f, 0.0f, 0.0f);
    QVERIFY2(std::abs(project(after).x - expectedPixel.x) < 2.0f && std::abs(project(after).y - expectedPixel.y) < 2.0f,
             qPrintable(QString("%1 %2").arg(project(after).x).arg(project(after).y)));
    QVERIFY(after.x > before.x);
    QCOMPARE(m_window->document()->undoStack()->count(), entries + 1);

    // And back to perspective.
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    QVERIFY(!viewport()->camera().isOrthographic());
    QVERIFY(!ortho->isChecked());

}

void TestEditorCamera::bookmarksAreAddedShownRenamedAndDeletedWithUndo() {
    QUndoStack* stack = m_window->document()->undoStack();
    QVERIFY(bookmarks().empty());
    // A top view, orthographic, kept as "Plan" with Ctrl+B.
    QTest::keyClick(viewport(), Qt::Key_7, Qt::KeypadModifier);
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    answerPrompts(QStringLiteral("Plan"));
    QTest::keyClick(viewport(), Qt::Key_B, Qt::ControlModifier);
    QCOMPARE(bookmarks().size(), std::size_t(1));
    const simcore::CameraBookmark plan = bookmarks()[0];
    QCOMPARE(plan.name, std::string("Plan"));
    QVERIFY(plan.orthographic);
    QCOMPARE(plan.pitchDegrees, viewport()->camera().pitchDegrees());
    QVERIFY(plan.pitchDegrees > 88.0f);  // from above
    QCOMPARE(stack->count(), 1);
    QCOMPARE(stack->text(0), QStringLiteral("Add Bookmark \u201cPlan\u201d"));
    QVERIFY(m_window->document()->isModified());
    QVERIFY(m_window->isWindowModified());

    // An orbited, zoomed perspective view stored in bookmark 2 with Ctrl+2: a new one.
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    const QPoint centre = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::MiddleButton, {}, centre);
    for (int i = 1; i <= 8; ++i) QTest::mouseMove(viewport(), centre + QPoint(10 * i, -6 * i));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, {}, centre + QPoint(80, -48));
    QTest::keyClick(viewport(), Qt::Key_2, Qt::ControlModifier);
    QCOMPARE(bookmarks().size(), std::size_t(2));
    const simcore::CameraBookmark orbited = bookmarks()[1];
    QCOMPARE(orbited.name, std::string("Bookmark 2"));
    QVERIFY(!orbited.orthographic);
    QVERIFY(std::abs(orbited.pitchDegrees - plan.pitchDegrees) > 1.0f);
    QCOMPARE(stack->count(), 2);

    // 1 and 2 show them; the menu lists them with their keys.
    QTest::keyClick(viewport(), Qt::Key_1);
    verifyShows(plan);
    QTest::keyClick(viewport(), Qt::Key_2);
    verifyShows(orbited);
    QCOMPARE(m_window->action("showBookmark1")->text(), QStringLiteral("&1 Plan"));
    QCOMPARE(m_window->action("showBookmark2")->shortcut(), QKeySequence(Qt::Key_2));
    QCOMPARE(stack->count(), 2);  // showing is no edit

    // Ctrl+1 stores the view shown in "Plan", keeping its name.
    QTest::keyClick(viewport(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(bookmarks()[0].name, std::string("Plan"));
    QCOMPARE(bookmarks()[0], interplay::bookmarkOf(viewport()->camera(), QStringLiteral("Plan")));
    QCOMPARE(stack->text(2), QStringLiteral("Store View in Bookmark \u201cPlan\u201d"));
    stack->undo();
    QCOMPARE(bookmarks()[0], plan);

    // Rename and delete, from the View menu's Bookmarks submenu.
    auto* renameMenu = m_window->findChild<QMenu*>(QStringLiteral("renameBookmarkMenu"));
    auto* deleteMenu = m_window->findChild<QMenu*>(QStringLiteral("deleteBookmarkMenu"));
    QVERIFY(renameMenu && deleteMenu);
    QCOMPARE(renameMenu->actions().size(), 2);
    answerPrompts(QStringLiteral("  Floor plan "));
    renameMenu->actions()[0]->trigger();
    QCOMPARE(bookmarks()[0].name, std::string("Floor plan"));  // trimmed
    QCOMPARE(m_window->action("showBookmark1")->text(), QStringLiteral("&1 Floor plan"));
    deleteMenu->actions()[0]->trigger();
    QCOMPARE(bookmarks().size(), std::size_t(1));
    QCOMPARE(bookmarks()[0], orbited);
    QTest::keyClick(viewport(), Qt::Key_1);  // now the orbited view
    verifyShows(orbited);
    QCOMPARE(stack->text(stack->count() - 1), QStringLiteral("Delete Bookmark \u201cFloor plan\u201d"));

    // Undo takes each back, to a clean document.
    stack->undo();
    QCOMPARE(bookmarks().size(), std::size_t(2));
    QCOMPARE(bookmarks()[0].name, std::string("Floor plan"));
    stack->undo();
    QCOMPARE(bookmarks()[0], plan);
    while (stack->canUndo()) stack->undo();
    QVERIFY(bookmarks().empty());
    QVERIFY(!m_window->document()->isModified());
    QVERIFY(!m_window->action("showBookmark1"));
}

void TestEditorCamera::bookmarksComeBackFromTheSavedFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bookmarked.json"));
    auto& prompts = m_window->documentManager()->prompts();
    prompts.chooseFile = [path](interplay::DocumentManager::FileChoice, const QString&, const QString&) { return path; };
    prompts.error = [](const QString& title, const QString& text, const QString& details) {
        QFAIL(qPrintable(title + ": " + text + '\n' + details));
    };
    QTest::keyClick(viewport(), Qt::Key_3, Qt::KeypadModifier);
    answerPrompts(QStringLiteral("Side"));
    QTest::keyClick(viewport(), Qt::Key_B, Qt::ControlModifier);
    const simcore::CameraBookmark side = bookmarks().at(0);
    QVERIFY(m_window->documentManager()->saveAs());
    QVERIFY(!m_window->document()->isModified());

    // Opened again (after looking elsewhere), the bookmark is there and shows the same view.
    QVERIFY(m_window->documentManager()->newScene());
    QVERIFY(bookmarks().empty());
    QString error;
    QVERIFY2(m_window->documentManager()->openFile(path, &error), qPrintable(error));
    QCOMPARE(bookmarks().size(), std::size_t(1));
    QCOMPARE(bookmarks()[0], side);
    viewport()->grabViewport();  // the opened scene's framing happens on its first frame
    QTest::keyClick(viewport(), Qt::Key_1);
    verifyShows(side);
    viewport()->grabViewport();  // and a frame drawn after does not reframe it
    verifyShows(side);
    QVERIFY(!m_window->document()->isModified());
}

void TestEditorCamera::aBadBookmarkNameIsRefused() {
    QUndoStack* stack = m_window->document()->undoStack();
    answerPrompts(QStringLiteral("   "));
    QTest::keyClick(viewport(), Qt::Key_B, Qt::ControlModifier);
    QVERIFY(bookmarks().empty());
    QCOMPARE(stack->count(), 0);
    QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("needs a name")),
             qPrintable(m_window->statusBar()->currentMessage()));
    answerPrompts(std::nullopt);  // cancelled: nothing, said or done
    QTest::keyClick(viewport(), Qt::Key_B, Qt::ControlModifier);
    QCOMPARE(stack->count(), 0);
    answerPrompts(QStringLiteral("ok"));
    QTest::keyClick(viewport(), Qt::Key_B, Qt::ControlModifier);
    answerPrompts(QString(201, QLatin1Char('x')));
    m_window->findChild<QMenu*>(QStringLiteral("renameBookmarkMenu"))->actions()[0]->trigger();
    QCOMPARE(bookmarks()[0].name, std::string("ok"));
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("at most 200 bytes")));
    QCOMPARE(stack->count(), 1);
    // Ctrl+5 with one bookmark would store in bookmark 2: it is off until there are four.
    QVERIFY(!m_window->action("storeBookmark5")->isEnabled());
    QVERIFY(m_window->action("storeBookmark2")->isEnabled());
}

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorCamera test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_camera.moc"
