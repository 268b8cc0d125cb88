// The Profiler's plots in the whole window, with real OpenGL under Xvfb and real QTest events: a
// scene played with Space fills the run's series; clicking a tab shows that plot; moving the
// pointer over the plot puts a cursor at the sample nearest the pointer's time, whose values the
// readout shows as the series holds them.

#include "app/document/document_manager.h"
#include "app/main_window.h"
#include "app/panels/profiler_panel.h"
#include "app/panels/profiler_plot.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/world/world.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QTabBar>
#include <QTest>

#include <cmath>
#include <memory>

using interplay::MainWindow;
using interplay::ProfilerPlot;
using interplay::RunSample;

namespace {

// A readout line's number (the token before the unit) and half its last digit: the rounding.
struct Shown {
    double value = 0.0;
    double rounding = 0.0;
};
Shown shownValue(const QString& line) {
    const QStringList tokens = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString number = tokens.size() >= 2 ? tokens[tokens.size() - 2] : QString();
    const qsizetype point = number.indexOf(QLatin1Char('.'));
    const auto decimals = point < 0 ? 0 : number.size() - point - 1;
    bool ok = false;
    const double value = number.toDouble(&ok);
    if (!ok) qFatal("no number in the readout line \"%s\"", qPrintable(line));
    return {value, 0.5 * std::pow(10.0, -double(decimals)) * (1.0 + 1e-9)};
}

}  // namespace

class TestEditorPlots : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void tabsChooseThePlotAndHoverReadsTheSeries();
    void theChosenPlotComesBackInTheNextWindow();

private:
    interplay::SimulationController* simulation() const { return m_window->simulation(); }
    ProfilerPlot* plot() const { return m_window->profiler()->plot(); }
    void openWindow();  // ragdoll.json, the Profiler dock raised and tall
    QTabBar* tabs() const { return m_window->profiler()->plotTabs(); }
    void clickTab(ProfilerPlot::Plot which);
    void play(std::uint64_t steps);
    void checkHover(ProfilerPlot::Plot which, const QStringList& names);
    void measureCostPerStep(const QString& scene);

    std::unique_ptr<MainWindow> m_window;
};

void TestEditorPlots::initTestCase() {
    test_support::isolateSettings("test_editor_plots");
}

void TestEditorPlots::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorPlots::init() {
    test_support::clearSettings();
    openWindow();
}

void TestEditorPlots::openWindow() {
    m_window = std::make_unique<MainWindow>();
    QVERIFY(m_window->documentManager()->openFile(QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/ragdoll.json")));
    QVERIFY(test_support::showActive(*m_window));
    // A taller dock than the default layout's, so that the plots read.
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("profilerDock"));
    QVERIFY(dock);
    dock->raise();
    m_window->resizeDocks({dock}, {300}, Qt::Vertical);
    QTRY_VERIFY(plot()->isVisible() && plot()->height() > 150);
}

void TestEditorPlots::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorPlots::clickTab(ProfilerPlot::Plot which) {
    const int index = int(which);
    QTest::mouseClick(tabs(), Qt::LeftButton, {}, tabs()->tabRect(index).center());
    QCOMPARE(tabs()->currentIndex(), index);
    QCOMPARE(plot()->plot(), which);
}

// Space on the viewport plays; Space again pauses once `steps` steps have run.
void TestEditorPlots::play(std::uint64_t steps) {
    m_window->viewport()->setFocus();
    QVERIFY(QTest::qWaitFor([this] { return m_window->viewport()->hasFocus(); }));
    QTest::keyClick(m_window->viewport(), Qt::Key_Space);
    QVERIFY(simulation()->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(simulation()->world()->stepCount() >= steps, 20000);
    QTest::keyClick(m_window->viewport(), Qt::Key_Space);
    QVERIFY(!simulation()->isPlaying());
    QCOMPARE(simulation()->series().size(), std::size_t(simulation()->world()->stepCount()));
}

void TestEditorPlots::tabsChooseThePlotAndHoverReadsTheSeries() {
    QCOMPARE(plot()->plot(), ProfilerPlot::Plot::TimePerStage);  // the Profiler's view before plots
    QCOMPARE(tabs()->count(), 4);
    play(30);
    simulation()->stepFrames(90);  // the ragdoll lands: contacts and joint error in the series

    // The series each plot's readout lists after the time, in order.
    checkHover(ProfilerPlot::Plot::Energy, {"kinetic", "potential", "total"});
    checkHover(ProfilerPlot::Plot::Penetration, {"deepest penetration"});
    checkHover(ProfilerPlot::Plot::JointError, {"largest joint error"});
    checkHover(ProfilerPlot::Plot::TimePerStage, {"total"});

    // Leaving the plot hides the readout.
    QTest::mouseMove(tabs(), tabs()->tabRect(0).center());
    QTRY_VERIFY(plot()->readout().isEmpty());
    QVERIFY(!plot()->hoveredSample());

    if (const QString scene = qEnvironmentVariable("INTERPLAY_PLOTS_COST"); !scene.isEmpty()) measureCostPerStep(scene);
}

void TestEditorPlots::theChosenPlotComesBackInTheNextWindow() {
    clickTab(ProfilerPlot::Plot::Penetration);
    test_support::closeWithoutPrompt(m_window);
    openWindow();  // the settings kept
    QCOMPARE(tabs()->currentIndex(), int(ProfilerPlot::Plot::Penetration));
    QCOMPARE(plot()->plot(), ProfilerPlot::Plot::Penetration);
}

void TestEditorPlots::checkHover(ProfilerPlot::Plot which, const QStringList& names) {
    clickTab(which);
    const interplay::RunSeries& series = simulation()->series();

    // The time axis spans the samples held: left edge, a third of the way, the right edge.
    const QRectF area = plot()->plotArea();
    for (double fraction : {0.0, 1.0 / 3.0, 1.0}) {
        const QPoint at(int(std::lround(area.left() + fraction * area.width())), int(area.center().y()));
        const double timeAt = series.front().time + (at.x() - area.left()) / area.width() * (series.back().time - series.front().time);
        const std::size_t expected = *series.nearest(timeAt);
        QTest::mouseMove(plot(), at);
        QTRY_VERIFY2(plot()->hoveredSample() == expected, qPrintable(QString("hovering x = %1").arg(at.x())));

        const RunSample& sample = series[expected];
        const std::vector<double> values = [&]() -> std::vector<double> {
            switch (which) {
            case ProfilerPlot::Plot::Energy: return {sample.kineticEnergy, sample.potentialEnergy, sample.totalEnergy()};
            case ProfilerPlot::Plot::Penetration: return {sample.maxPenetration * 1000.0};  // mm
            case ProfilerPlot::Plot::JointError: return {sample.jointError * 1000.0};       // mm
            case ProfilerPlot::Plot::TimePerStage: break;
            }
            double sum = 0.0;
            for (double ms : sample.stageMs) sum += ms;
            return {sum};
        }();
        const QStringList lines = plot()->readout();
        QCOMPARE(lines.size(), names.size() + 1);
        const Shown time = shownValue(lines[0]);
        QVERIFY2(lines[0].endsWith(" s") && std::abs(time.value - sample.time) <= time.rounding, qPrintable(lines[0]));
        for (qsizetype k = 0; k < names.size(); ++k) {
            const QString& line = lines[k + 1];
            QVERIFY2(line.startsWith(names[k] + ' '), qPrintable(line));
            const Shown shown = shownValue(line);
            QVERIFY2(std::abs(shown.value - values[std::size_t(k)]) <= shown.rounding,
                     qPrintable(QString("%1: the series holds %2").arg(line).arg(values[std::size_t(k)], 0, 'g', 9)));
        }
    }
    // At the right edge, the newest step.
    QCOMPARE(*plot()->hoveredSample(), series.size() - 1);

    // With INTERPLAY_PLOTS_SCREENSHOT=FILE.png the energy plot, hovered, is saved: the README's.
    const QString screenshot = qEnvironmentVariable("INTERPLAY_PLOTS_SCREENSHOT");
    if (!screenshot.isEmpty() && which == ProfilerPlot::Plot::Energy) {
        QTest::mouseMove(plot(), QPoint(int(area.left() + 0.3 * area.width()), int(area.center().y())));
        QTest::qWait(300);
        QVERIFY(m_window->grab().save(screenshot));
    }
}

// With INTERPLAY_PLOTS_COST=SCENE.json: the editor's wall time per step (step, record, sample,
// repaint) on that scene with the Profiler's energy plot shown and with its dock closed, and what
// sampling one step costs. A measurement for the commit and docs/editor.md, not a check.
void TestEditorPlots::measureCostPerStep(const QString& scene) {
    QVERIFY(m_window->documentManager()->openFile(scene));
    clickTab(ProfilerPlot::Plot::Energy);
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("profilerDock"));
    const auto msPerStep = [this](int steps) {
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < steps; ++i) {
            simulation()->stepFrames(1);
            QCoreApplication::processEvents();  // the repaints a frame of playback makes
        }
        return double(clock.nsecsElapsed()) * 1e-6 / steps;
    };
    msPerStep(20);  // past the first contacts
    for (int round = 0; round < 2; ++round) {
        dock->show();
        dock->raise();
        QTRY_VERIFY(plot()->isVisible());
        const double open = msPerStep(40);
        dock->close();
        QTRY_VERIFY(!plot()->isVisible());
        const double closed = msPerStep(40);
        qInfo("round %d: %.2f ms per step with the energy plot shown, %.2f ms with the dock closed", round, open, closed);
    }
    dock->show();
    dock->raise();
    QTRY_VERIFY(plot()->isVisible());
    const auto drawMs = [this] {
        // Into an image: the plot's own painting, without the window's (OpenGL) composition.
        QImage image(plot()->size(), QImage::Format_ARGB32_Premultiplied);
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < 20; ++i) plot()->render(&image);
        return double(clock.nsecsElapsed()) * 1e-6 / 20;
    };
    qInfo("drawing the plot of %zu samples: %.3f ms", simulation()->series().size(), drawMs());
    interplay::RunSeries series;
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < 1000; ++i) series.record(*simulation()->world());
    qInfo("sampling a step: %.4f ms", double(clock.nsecsElapsed()) * 1e-6 / 1000);

    // A full ring (the ragdoll, cheap to step): what drawing costs at the most samples held.
    QVERIFY(m_window->documentManager()->openFile(QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/ragdoll.json")));
    simulation()->setRecording(false);
    simulation()->stepFrames(int(simulation()->series().capacity()) + 100);
    QCOMPARE(simulation()->series().size(), simulation()->series().capacity());
    for (ProfilerPlot::Plot which : {ProfilerPlot::Plot::Energy, ProfilerPlot::Plot::TimePerStage}) {
        clickTab(which);
        qInfo("drawing plot %d of %zu samples: %.3f ms", int(which), simulation()->series().size(), drawMs());
    }
}

QTEST_MAIN(TestEditorPlots)
#include "test_editor_plots.moc"
