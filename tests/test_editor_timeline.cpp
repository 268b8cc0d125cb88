// The timeline and the live state in the whole window, with real OpenGL under Xvfb and real QTest
// key and mouse events: steps are recorded; dragging the timeline slider or pressing , shows a
// recorded frame in the world the viewport draws and in the Live State panel; . steps on through
// the recorded frames; Play from a frame shown resumes the same run, dropping the frames after it;
// Apply Simulated Pose applies the frame shown as one undo entry; the memory limit typed into the
// bar caps the frames held; a falling body's simulated speed is g t; hovering a body names it.

#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/panels/live_state_panel.h"
#include "app/panels/timeline_bar.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/world.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QHelpEvent>
#include <QLabel>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>
#include <QUndoStack>

#include <glm/glm.hpp>

#include <memory>

using interplay::MainWindow;

namespace {

constexpr float kGravity = 9.81f;

// Body 0: the ground; body 1 "faller": a ball dropped from 100 m (it falls for 4.5 s); body 2
// "rester": a 2 kg box on the ground; then `extraBoxes` boxes in a row (for a heavier recording).
simcore::Scene timelineScene(int extraBoxes = 0) {
    simcore::Scene scene;
    scene.settings.gravity = simcore::Vec3(0.0f, -kGravity, 0.0f);
    scene.settings.sleep.enabled = false;
    simcore::SceneBody ground;
    ground.body.name = "ground";
    ground.body.motion = simcore::MotionType::Static;
    ground.body.shape = simcore::Shape::box(simcore::Vec3(30.0f, 0.5f, 30.0f));
    ground.body.position = simcore::Vec3(0.0f, -0.5f, 0.0f);
    scene.bodies.push_back(ground);
    simcore::SceneBody faller;
    faller.body.name = "faller";
    faller.body.shape = simcore::Shape::sphere(0.5f);
    faller.body.position = simcore::Vec3(0.0f, 100.0f, 0.0f);
    scene.bodies.push_back(faller);
    simcore::SceneBody rester;
    rester.body.name = "rester";
    rester.body.shape = simcore::Shape::box(simcore::Vec3(0.5f));
    rester.body.mass = 2.0f;
    rester.body.position = simcore::Vec3(3.0f, 0.5f, 0.0f);
    scene.bodies.push_back(rester);
    for (int i = 0; i < extraBoxes; ++i) {
        simcore::SceneBody box = rester;
        box.body.name = "box " + std::to_string(i);
        box.body.position = simcore::Vec3(-25.0f + 1.5f * float(i % 30), 0.5f + 1.2f * float(i / 30), 10.0f);
        scene.bodies.push_back(box);
    }
    return scene;
}

struct Pose {
    simcore::Vec3 position{0.0f};
    simcore::Quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    simcore::Vec3 velocity{0.0f};
    bool operator==(const Pose&) const = default;
};

}  // namespace

class TestEditorTimeline : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void sliderAndCommaShowTheRecordedFrame();
    void playFromAFrameShownResumesTheSameRun();
    void applySimulatedPoseAppliesTheFrameShown();
    void memoryLimitCapsTheFramesHeld();
    void liveStateShowsTheSimulatedMotion();
    void hoverShowsNameAndSpeed();

private:
    void openScene(const simcore::Scene& scene);
    interplay::SimulationController* simulation() const { return m_window->simulation(); }
    interplay::Viewport* viewport() const { return m_window->viewport(); }
    QSlider* slider() const { return m_window->timelineBar()->slider(); }
    simcore::BodyId bodyId(int index) const { return simulation()->bodyIds()[std::size_t(index)]; }
    Pose livePose(int index) const {
        const simcore::World* world = simulation()->world();
        const simcore::BodyId id = bodyId(index);
        return {world->position(id), world->orientation(id), world->linearVelocity(id)};
    }
    // Presses . `steps` times on the viewport, returning the faller's pose at each frame
    // (index 0: before the first step).
    std::vector<Pose> stepWithKeys(int steps);
    void dragSliderTo(int frame);

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

void TestEditorTimeline::initTestCase() {
    test_support::isolateSettings("test_editor_timeline");
    QVERIFY(m_dir.isValid());
}

void TestEditorTimeline::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorTimeline::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    openScene(timelineScene());
    QVERIFY(test_support::showActive(*m_window));
    viewport()->setFocus();
    QVERIFY(QTest::qWaitFor([this] { return viewport()->hasFocus(); }));
}

void TestEditorTimeline::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorTimeline::openScene(const simcore::Scene& scene) {
    const QString path = m_dir.filePath(QStringLiteral("timeline.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QByteArray::fromStdString(simcore::serializeScene(scene)));
    file.close();
    QString error;
    QVERIFY2(m_window->document()->load(path, &error), qPrintable(error));
    QCOMPARE(simulation()->world()->bodyCount(), scene.bodies.size());
}

std::vector<Pose> TestEditorTimeline::stepWithKeys(int steps) {
    std::vector<Pose> poses{livePose(1)};
    for (int i = 0; i < steps; ++i) {
        QTest::keyClick(viewport(), Qt::Key_Period);
        poses.push_back(livePose(1));
    }
    return poses;
}

// Presses the slider's handle and drags it to where `frame` sits on the groove.
void TestEditorTimeline::dragSliderTo(int frame) {
    QStyleOptionSlider option;
    option.initFrom(slider());
    option.orientation = Qt::Horizontal;
    option.minimum = slider()->minimum();
    option.maximum = slider()->maximum();
    option.sliderPosition = slider()->sliderPosition();
    option.sliderValue = slider()->value();
    const QRect handle = slider()->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider());
    const QRect groove = slider()->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, slider());
    const int span = groove.width() - handle.width();
    const int x = groove.x() + handle.width() / 2 +
                  QStyle::sliderPositionFromValue(slider()->minimum(), slider()->maximum(), frame, span);
    const QPoint from = handle.center();
    const QPoint to(x, from.y());
    QTest::mousePress(slider(), Qt::LeftButton, {}, from);
    for (int i = 1; i <= 8; ++i) QTest::mouseMove(slider(), from + (to - from) * i / 8);
    QTest::mouseRelease(slider(), Qt::LeftButton, {}, to);
}

void TestEditorTimeline::sliderAndCommaShowTheRecordedFrame() {
    const std::vector<Pose> recorded = stepWithKeys(40);
    const interplay::Timeline& timeline = simulation()->timeline();
    QCOMPARE(timeline.frameCount(), std::size_t{41});
    QCOMPARE(simulation()->currentFrame(), 40);
    QCOMPARE(slider()->maximum(), 40);
    QCOMPARE(slider()->value(), 40);
    m_window->document()->setSelectedBodies({1});

    dragSliderTo(15);
    const int shown = slider()->value();
    QVERIFY2(shown >= 13 && shown <= 17, qPrintable(QString::number(shown)));  // a pixel is about one frame
    QCOMPARE(simulation()->currentFrame(), shown);
    QVERIFY(!simulation()->isPlaying());
    QVERIFY(livePose(1) == recorded[std::size_t(shown)]);  // the world the viewport draws
    QCOMPARE(timeline.frameCount(), std::size_t{41});     // scrubbing records nothing
    QTRY_COMPARE(m_window->liveState()->shown().position, recorded[std::size_t(shown)].position);
    QCOMPARE(m_window->liveState()->shown().linearVelocity, recorded[std::size_t(shown)].velocity);

    QTest::keyClick(viewport(), Qt::Key_Comma);
    QCOMPARE(simulation()->currentFrame(), shown - 1);
    QCOMPARE(slider()->value(), shown - 1);
    QVERIFY(livePose(1) == recorded[std::size_t(shown - 1)]);
    QTRY_COMPARE(m_window->liveState()->shown().position, recorded[std::size_t(shown - 1)].position);

    // . goes on through the recording, stepping nothing new.
    QTest::keyClick(viewport(), Qt::Key_Period);
    QTest::keyClick(viewport(), Qt::Key_Period);
    QCOMPARE(simulation()->currentFrame(), shown + 1);
    QVERIFY(livePose(1) == recorded[std::size_t(shown + 1)]);
    QCOMPARE(timeline.frameCount(), std::size_t{41});

    // , stops at the first frame: the authored start.
    for (int i = 0; i < 60; ++i) QTest::keyClick(viewport(), Qt::Key_Comma);
    QCOMPARE(simulation()->currentFrame(), 0);
    QVERIFY(livePose(1) == recorded[0]);
    QCOMPARE(livePose(1).position, m_window->document()->body(1).body.position);
}

void TestEditorTimeline::playFromAFrameShownResumesTheSameRun() {
    const std::vector<Pose> recorded = stepWithKeys(30);
    for (int i = 0; i < 18; ++i) QTest::keyClick(viewport(), Qt::Key_Comma);
    QCOMPARE(simulation()->currentFrame(), 12);
    QTest::keyClick(viewport(), Qt::Key_Space);
    QVERIFY(simulation()->isPlaying());
    const interplay::Timeline& timeline = simulation()->timeline();
    // The frames after 12 were dropped at once, and the run records on from 12.
    QVERIFY(QTest::qWaitFor([&] { return timeline.frameCount() >= 40; }, 10000));
    QTest::keyClick(viewport(), Qt::Key_Space);
    QVERIFY(!simulation()->isPlaying());
    QCOMPARE(timeline.stepOf(12), std::uint64_t{12});
    // Nothing pulled or threw: the resumed run is the recorded one, bit for bit.
    for (int frame : {13, 20, 30}) {
        QVERIFY(simulation()->showFrame(frame));
        QVERIFY2(livePose(1) == recorded[std::size_t(frame)], qPrintable(QString("frame %1").arg(frame)));
    }
}

void TestEditorTimeline::applySimulatedPoseAppliesTheFrameShown() {
    const std::vector<Pose> recorded = stepWithKeys(25);
    for (int i = 0; i < 10; ++i) QTest::keyClick(viewport(), Qt::Key_Comma);
    QCOMPARE(simulation()->currentFrame(), 15);
    QUndoStack* undo = m_window->document()->undoStack();
    const int entries = undo->count();
    const simcore::Vec3 authored = m_window->document()->body(1).body.position;

    m_window->action(QStringLiteral("applyPose"))->trigger();
    QCOMPARE(undo->count(), entries + 1);
    QCOMPARE(undo->text(undo->count() - 1), QStringLiteral("Apply Simulated Pose"));
    QVERIFY(m_window->document()->isModified());
    QCOMPARE(m_window->document()->body(1).body.position, recorded[15].position);
    QCOMPARE(m_window->document()->body(1).body.linearVelocity, recorded[15].velocity);
    // The edit made the recording stale: it is discarded, the world stays at the applied frame.
    QVERIFY(simulation()->timeline().empty());
    QCOMPARE(livePose(1).position, recorded[15].position);

    QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(undo->index(), entries);
    QCOMPARE(m_window->document()->body(1).body.position, authored);
    QVERIFY(!m_window->document()->isModified());
}

void TestEditorTimeline::memoryLimitCapsTheFramesHeld() {
    openScene(timelineScene(300));  // about 100 kB a keyframe
    QSpinBox* limit = m_window->timelineBar()->memoryLimit();
    QCOMPARE(limit->value(), 256);  // the default
    limit->setFocus();
    QTest::keyClick(limit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(limit, QStringLiteral("1"));
    QTest::keyClick(limit, Qt::Key_Return);
    QCOMPARE(limit->value(), 1);
    QCOMPARE(QSettings().value(QLatin1String(interplay::TimelineBar::kMemoryLimitKey)).toInt(), 1);
    QCOMPARE(simulation()->timeline().memoryLimit(), std::size_t{1} << 20);

    simulation()->stepFrames(200);
    const interplay::Timeline& timeline = simulation()->timeline();
    QVERIFY(timeline.bytesUsed() <= std::size_t{1} << 20);
    QVERIFY2(timeline.frameCount() > 10 && timeline.frameCount() < 200, qPrintable(QString::number(timeline.frameCount())));
    QCOMPARE(timeline.stepOf(timeline.frameCount() - 1), std::uint64_t{200});  // the newest are kept
    const QString held = m_window->timelineBar()->findChild<QLabel*>(QStringLiteral("timelineHeld"))->text();
    QVERIFY2(held.startsWith(QString::number(timeline.frameCount()) + QStringLiteral(" frames")), qPrintable(held));

    // A new window takes the stored limit.
    test_support::closeWithoutPrompt(m_window);
    m_window = std::make_unique<MainWindow>();
    QCOMPARE(m_window->timelineBar()->memoryLimit()->value(), 1);
    QCOMPARE(m_window->simulation()->timeline().memoryLimit(), std::size_t{1} << 20);
}

void TestEditorTimeline::liveStateShowsTheSimulatedMotion() {
    m_window->document()->setSelectedBodies({1});
    const int steps = 60;
    stepWithKeys(steps);
    const interplay::LiveStatePanel* live = m_window->liveState();
    const double t = steps * double(simulation()->world()->settings().timeStep);
    // Free fall from rest, no damping: v = g t; 1e-4 allows float sums of 60 velocity steps.
    QTRY_VERIFY(std::abs(live->shown().time - t) < 1e-9);
    const double speed = glm::length(live->shown().linearVelocity);
    QVERIFY2(std::abs(speed - kGravity * t) < 1e-4 * kGravity * t, qPrintable(QString::number(speed)));
    QVERIFY(std::abs(live->figure(QStringLiteral("speed")).toDouble() - kGravity * t) < 1e-3);
    QCOMPARE(live->shown().contacts, 0);
    // Kinetic energy 1/2 m v^2 for a ball of density 1000.
    const float mass = simulation()->world()->mass(bodyId(1));
    QVERIFY(std::abs(live->shown().kineticEnergy - 0.5 * mass * speed * speed) < 1e-4 * live->shown().kineticEnergy);
    QVERIFY(live->findChild<QLabel*>(QStringLiteral("liveStateHeading"))->text().contains(QStringLiteral("not the authored")));

    // The resting box: one contact carrying its weight, 2 kg x g.
    m_window->document()->setSelectedBodies({2});
    QCOMPARE(live->shown().contacts, 1);
    QVERIFY2(std::abs(live->shown().contactForce - 2.0f * kGravity) < 0.02f * 2.0f * kGravity,
             qPrintable(QString::number(live->shown().contactForce)));
    QCOMPARE(live->figure(QStringLiteral("contacts")), QStringLiteral("1"));

    // Both: totals.
    m_window->document()->setSelectedBodies({1, 2});
    QCOMPARE(live->shown().bodies, 2);
    const simcore::World* world = simulation()->world();
    QCOMPARE(live->shown().kineticEnergy, world->kineticEnergy(bodyId(1)) + world->kineticEnergy(bodyId(2)));
    QCOMPARE(live->shown().contacts, 1);
    QCOMPARE(live->figure(QStringLiteral("name")), QStringLiteral("2 bodies (totals)"));
}

void TestEditorTimeline::hoverShowsNameAndSpeed() {
    stepWithKeys(30);
    const simcore::Vec3 centre = simulation()->world()->position(bodyId(2));
    const glm::vec3 pixel = viewport()->camera().project(centre, float(viewport()->width()), float(viewport()->height()));
    const QPoint at(int(pixel.x), int(pixel.y));
    const auto hit = viewport()->pick(at);
    QVERIFY(hit && hit->body == bodyId(2));
    QHelpEvent help(QEvent::ToolTip, at, viewport()->mapToGlobal(at));
    QApplication::sendEvent(viewport(), &help);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY2(QToolTip::text().contains(QStringLiteral("rester")), qPrintable(QToolTip::text()));
    const float speed = glm::length(simulation()->world()->linearVelocity(bodyId(2)));
    QVERIFY2(QToolTip::text().contains(QString::number(speed, 'f', 3) + QStringLiteral(" m/s")), qPrintable(QToolTip::text()));
    QToolTip::hideText();
}

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorTimeline test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_timeline.moc"
