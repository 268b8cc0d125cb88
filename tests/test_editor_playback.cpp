// Playback off the GUI thread (issue 14, item 4), in the whole window with real OpenGL under Xvfb
// and real QTest mouse events: while the 1000 cubes of pile1k.json play, a click on a body in the
// viewport shows it in the Inspector within 50 ms, and an edit reaches the running world as fast;
// while a slow scene plays, the event loop keeps running its timers and the world still advances;
// the status bar gives the real-time factor, and says so when the run cannot keep up. That a run
// played on the worker is the runner's, bit for bit, is test_editor_determinism's.
// INTERPLAY_PLAYBACK_SCREENSHOT and INTERPLAY_SLOW_PLAYBACK_SCREENSHOT (FILE.png) save the window
// while pile1k plays and while the slow scene does.

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/main_window.h"
#include "app/panels/inspector_panel.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using interplay::MainWindow;

namespace {

constexpr qint64 kResponseLimitMs = 50;

QString scenePath(const char* name) {
    return QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/") + QLatin1String(name);
}

QPoint pixelOf(const interplay::Viewport& viewport, const simcore::Vec3& point) {
    const glm::vec3 p = viewport.camera().project(point, float(viewport.width()), float(viewport.height()));
    return {int(std::lround(p.x)), int(std::lround(p.y))};
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

}  // namespace

class TestEditorPlayback : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void clickShowsTheBodyInTheInspectorWhilePlaying();
    void editReachesTheRunningWorldWhilePlaying();
    void eventLoopRunsWhileASlowSceneSteps();
    void statusBarShowsTheRealTimeFactor();

private:
    void open(const char* scene);
    interplay::SimulationController* simulation() const { return m_window->simulation(); }
    interplay::SceneDocument* document() const { return m_window->document(); }
    interplay::Viewport* viewport() const { return m_window->viewport(); }
    // Steps announced so far, read without waiting for a step in flight.
    std::uint64_t stepsShown() const { return simulation()->snapshot().stepCount; }
    // The slow scene: the pyramid of 385 cubes kept awake, at 64 substeps of 50 solver passes each,
    // about 350 ms a step on this machine: far slower than drawing it (Mesa's software renderer
    // takes tens of ms a frame here).
    void openSlowScene();

    std::unique_ptr<MainWindow> m_window;
};

void TestEditorPlayback::initTestCase() {
    test_support::isolateSettings("test_editor_playback");
}

void TestEditorPlayback::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorPlayback::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    QVERIFY(test_support::showActive(*m_window));
}

void TestEditorPlayback::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorPlayback::open(const char* scene) {
    QVERIFY(m_window->documentManager()->open(scenePath(scene)));
    QTest::qWait(100);  // framed and drawn once
}

void TestEditorPlayback::openSlowScene() {
    open("pyramid10.json");
    simcore::WorldSettings settings = document()->scene().settings;
    settings.sleep.enabled = false;
    settings.substeps = 64;
    settings.solver.velocityIterations = 50;
    QString error;
    QVERIFY2(simulation()->applySettings(settings, &error), qPrintable(error));
}

void TestEditorPlayback::clickShowsTheBodyInTheInspectorWhilePlaying() {
    open("pile1k.json");
    QCOMPARE(document()->bodyCount(), 1001);
    auto* name = m_window->inspector()->findChild<QLineEdit*>(QStringLiteral("name"));
    QVERIFY(name);
    simulation()->play();
    QTRY_VERIFY_WITH_TIMEOUT(stepsShown() >= 30, 10000);  // the pile is falling

    std::vector<double> times;
    for (int click = 0; click < 8; ++click) {
        document()->setSelectedBodies({});
        QTest::qWait(40);  // steps run on; one may be in flight as the click comes
        QVERIFY(simulation()->isPlaying());
        // The highest cube as drawn: nothing stands over it in a view from above. Read from the
        // snapshot, which leaves the step in flight running: the click's pick waits for it.
        const interplay::WorldSnapshot& drawn = simulation()->snapshot();
        const auto& ids = simulation()->bodyIds();
        const auto centre = [&](int index) { return drawn.find(ids[std::size_t(index)])->transform.position; };
        int top = 1;
        for (int i = 1; i < document()->bodyCount(); ++i) {
            if (centre(i).y > centre(top).y) top = i;
        }
        const QPoint pixel = pixelOf(*viewport(), centre(top));

        QElapsedTimer clock;
        clock.start();
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, pixel);
        const auto shown = [&] {
            const QList<int> selected = document()->selectedBodies();
            return selected.size() == 1 && name->isVisible() &&
                   name->text() == QString::fromStdString(document()->body(selected[0]).body.name);
        };
        while (!shown() && clock.elapsed() < 2000) QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        const double ms = double(clock.nsecsElapsed()) * 1e-6;
        QVERIFY2(shown(), "the click selected no body the Inspector shows");
        times.push_back(ms);
    }
    QVERIFY(stepsShown() > 30);
    test_support::saveScreenshotIfAsked(*m_window, "INTERPLAY_PLAYBACK_SCREENSHOT");
    const double slowest = *std::max_element(times.begin(), times.end());
    qInfo("click to Inspector while playing pile1k: median %.2f ms, slowest %.2f ms", median(times), slowest);
    QVERIFY2(slowest < kResponseLimitMs, qPrintable(QString::number(slowest)));
}

void TestEditorPlayback::editReachesTheRunningWorldWhilePlaying() {
    open("pile1k.json");
    simulation()->play();
    QTRY_VERIFY_WITH_TIMEOUT(stepsShown() >= 30, 10000);
    std::vector<double> times;
    for (int edit = 0; edit < 8; ++edit) {
        QTest::qWait(40);
        const int index = 1 + edit;
        simcore::SceneBody moved = document()->body(index);
        moved.body.position.y += 20.0f;
        QElapsedTimer clock;
        clock.start();
        document()->undoStack()->push(new interplay::ChangeBodies(document(), QStringLiteral("Lift"),
                                                                  interplay::BodyField::Position, {index}, {moved}));
        const double ms = double(clock.nsecsElapsed()) * 1e-6;
        times.push_back(ms);
        // Lifted in place: the live body is 20 m above where the run had it, not at its authored pose.
        const simcore::World* world = simulation()->world();
        QVERIFY(world->position(simulation()->bodyIds()[std::size_t(index)]).y > 15.0f);
    }
    QVERIFY(simulation()->isPlaying());
    const double slowest = *std::max_element(times.begin(), times.end());
    qInfo("edit while playing pile1k: median %.2f ms, slowest %.2f ms", median(times), slowest);
    QVERIFY2(slowest < kResponseLimitMs, qPrintable(QString::number(slowest)));
}

void TestEditorPlayback::eventLoopRunsWhileASlowSceneSteps() {
    openSlowScene();
    simulation()->play();
    QTRY_VERIFY_WITH_TIMEOUT(stepsShown() >= 2, 20000);

    // A 2 ms timer, as a widget's animation would have: each gap between its timeouts is how long
    // the GUI thread was kept from its event loop, and the timeouts between two announcements of
    // steps are how often it ran while the worker stepped.
    QTimer probe;
    probe.setInterval(2);
    QElapsedTimer clock;
    double longestGap = 0.0;
    int timeouts = 0;
    connect(&probe, &QTimer::timeout, this, [&] {
        if (timeouts++ > 0) longestGap = std::max(longestGap, double(clock.nsecsElapsed()) * 1e-6);
        clock.restart();
    });
    std::vector<double> timeoutsBetweenSteps;
    int timeoutsAtLastStep = 0;
    connect(simulation(), &interplay::SimulationController::stepped, this, [&] {
        if (timeouts > 0) timeoutsBetweenSteps.push_back(timeouts - timeoutsAtLastStep);
        timeoutsAtLastStep = timeouts;
    });
    const std::uint64_t stepsBefore = stepsShown();
    clock.start();
    probe.start();
    QTest::qWait(2500);
    probe.stop();
    const std::uint64_t stepsRun = stepsShown() - stepsBefore;
    simulation()->pause();

    const interplay::RunSeries& series = simulation()->series();
    std::vector<double> stepMs;
    for (std::size_t i = 0; i < series.size(); ++i) stepMs.push_back(series[i].totalMs);
    const double typicalStep = median(stepMs);
    const double typicalTimeouts = median(timeoutsBetweenSteps);
    qInfo("slow scene: %llu steps of %.1f ms in 2.5 s; the GUI thread's longest gap %.1f ms, %d timeouts, %.0f "
          "between two steps",
          static_cast<unsigned long long>(stepsRun), typicalStep, longestGap, timeouts, typicalTimeouts);
    QVERIFY2(stepsRun >= 3, qPrintable(QString::number(stepsRun)));
    QVERIFY2(typicalStep > 100.0, "the scene steps too fast to show anything");
    // Stepped on the GUI thread, no gap could be shorter than a step, and the timer would come
    // about once between two steps. (The margins leave room for drawing on a busy machine.)
    QVERIFY2(longestGap < typicalStep, qPrintable(QString::number(longestGap)));
    QVERIFY2(typicalTimeouts >= 3, qPrintable(QString::number(typicalTimeouts)));
}

void TestEditorPlayback::statusBarShowsTheRealTimeFactor() {
    auto* rate = m_window->findChild<QLabel*>(QStringLiteral("realTimeLabel"));
    QVERIFY(rate);
    const auto factorShown = [rate] {
        const QString text = rate->text();
        const qsizetype at = text.indexOf(QChar(0x00D7));  // ×
        return at < 0 ? -1.0 : text.mid(at + 1, 4).toDouble();
    };

    // A light scene keeps up.
    open("dominoes.json");
    QVERIFY(!rate->isVisible());
    simulation()->play();
    QTRY_VERIFY(rate->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(simulation()->playbackRate().has_value(), 5000);
    QTest::qWait(1200);  // a whole window of measures
    qInfo("dominoes: \"%s\"", qPrintable(rate->text()));
    QVERIFY2(!rate->text().contains(QStringLiteral("cannot keep up")), qPrintable(rate->text()));
    QVERIFY2(std::abs(factorShown() - 1.0) < 0.1, qPrintable(rate->text()));
    simulation()->pause();
    QVERIFY(!rate->isVisible());

    // The slow scene does not, and the bar says so.
    openSlowScene();
    simulation()->play();
    QTRY_VERIFY_WITH_TIMEOUT(rate->text().contains(QStringLiteral("cannot keep up")), 10000);
    qInfo("slow scene: \"%s\"", qPrintable(rate->text()));
    QVERIFY2(factorShown() > 0.0 && factorShown() < interplay::SimulationController::kKeepingUpFraction,
             qPrintable(rate->text()));
    test_support::saveScreenshotIfAsked(*m_window, "INTERPLAY_SLOW_PLAYBACK_SCREENSHOT");
    simulation()->pause();
}

QTEST_MAIN(TestEditorPlayback)
#include "test_editor_playback.moc"
