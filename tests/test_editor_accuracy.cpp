// The Accuracy dock in the whole window under Xvfb, driven by real QTest events: Explore accuracy
// sweeps the open scene in the background and the table ends with the grid's points; Cancel stops
// a sweep mid-way and keeps the points done; a point clicked in the plot and applied changes the
// settings as one undo entry that Ctrl+Z takes back; editing the scene while a sweep runs works and
// leaves the running sweep's results exactly those of the scene as it was.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/main_window.h"
#include "app/panels/accuracy_panel.h"
#include "app/panels/accuracy_plot.h"
#include "app/panels/accuracy_sweep_model.h"

#include "simcore/io/scene_io.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHelpEvent>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <memory>
#include <optional>

using interplay::AccuracyPanel;
using interplay::AccuracySweepModel;
using interplay::MainWindow;

namespace {

constexpr int kSweepTimeoutMs = 120000;  // a tiny grid takes a second or two; a slow shared CI runner, far more

// Two points, a quarter second each: the smallest sweep with a front and a choice.
accuracy::SweepSpec tinySpec() {
    accuracy::SweepSpec spec;
    spec.knobs = {{"substeps", {"1", "2"}}, {"solver.velocityIterations", {"2"}}};
    spec.seconds = 0.25;
    return spec;
}

}  // namespace

class TestEditorAccuracy : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void exploreFillsTheTableWithTheGrid();
    void cancelStopsMidWayAndKeepsThePointsDone();
    void applyingAPointIsOneUndoEntry();
    void editingWhileASweepRunsLeavesItsResults();
    void plotMarksTheFrontAndTheChosenPoint();

private:
    AccuracyPanel* panel() const { return m_window->accuracyPanel(); }
    AccuracySweepModel* model() const { return panel()->model(); }
    QPushButton* button(const char* name) const { return panel()->findChild<QPushButton*>(QString::fromLatin1(name)); }
    bool waitForSweep() const {
        return QTest::qWaitFor([this] { return !model()->isRunning(); }, kSweepTimeoutMs);
    }
    // The table fits its columns to the results, which moves the splitter and so the plot's
    // points: let that layout happen before reading where a point is drawn.
    static void settleLayout() {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
        QTest::qWait(50);
    }
    void showPanel() const {
        auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
        dock->show();
        dock->raise();
    }

    std::unique_ptr<MainWindow> m_window;
};

void TestEditorAccuracy::initTestCase() {
    test_support::isolateSettings("test_editor_accuracy");
}

void TestEditorAccuracy::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorAccuracy::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    QVERIFY(m_window->document()->scene().bodies.size() >= 2);
}

void TestEditorAccuracy::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorAccuracy::exploreFillsTheTableWithTheGrid() {
    const accuracy::SweepSpec spec = tinySpec();
    panel()->setSpec(spec);
    QSignalSpy ended(model(), &AccuracySweepModel::sweepEnded);
    QSignalSpy progress(model(), &AccuracySweepModel::progressChanged);
    QAbstractItemModelTester tester(model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    // The menu action shows the dock and starts.
    m_window->action(QStringLiteral("exploreAccuracy"))->trigger();
    QVERIFY(m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"))->isVisible());
    QVERIFY(model()->isRunning());
    QVERIFY(!button("exploreButton")->isEnabled());
    QVERIFY(button("cancelButton")->isEnabled());
    QVERIFY(panel()->findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->isVisible());
    QVERIFY(waitForSweep());
    QCOMPARE(ended.count(), 1);
    QCOMPARE(ended.at(0).at(0).toBool(), false);           // not cancelled
    QCOMPARE(ended.at(0).at(1).toString(), QString());     // no error
    QCOMPARE(progress.last().at(0).toInt(), 2);            // 2 of 2
    QCOMPARE(progress.last().at(1).toInt(), 2);

    // One row per grid point, in grid order, each a real run: finite errors and a positive cost.
    const std::vector<accuracy::GridPoint> grid = accuracy::gridPoints(spec);
    QCOMPARE(model()->rowCount(), int(grid.size()));
    for (int row = 0; row < model()->rowCount(); ++row) {
        QCOMPARE(model()->point(row).point.id, grid[std::size_t(row)].id);
        QVERIFY(!model()->point(row).failed);
        QVERIFY(model()->point(row).msPerStep > 0.0);
        QVERIFY(std::isfinite(model()->index(row, 0).data(AccuracySweepModel::ErrorRole).toDouble()));
    }
    // Two substeps resolve the reference's trajectory at least as well as one.
    QVERIFY(model()->point(1).measures[0] <= model()->point(0).measures[0]);
    QVERIFY(button("exploreButton")->isEnabled());
    QVERIFY(!button("cancelButton")->isEnabled());
}

void TestEditorAccuracy::cancelStopsMidWayAndKeepsThePointsDone() {
    // A 386-body pyramid, 24 points of a second: the costliest point takes about 16 times the
    // cheapest, far more than passes between the first point's report and Cancel. A cheaper
    // reference (4 substeps) keeps the wait for that first report short.
    QVERIFY(m_window->documentManager()->openFile(QStringLiteral(INTERPLAY_SOURCE_DIR "/scenes/pyramid10.json")));
    accuracy::SweepSpec spec;
    spec.reference = {"substeps=4"};
    spec.knobs = {accuracy::defaultKnobs().front(), {"substeps", {"1", "2", "4", "8"}},
                  {"solver.velocityIterations", {"2", "4"}}};
    spec.seconds = 1.0;
    panel()->setSpec(spec);
    showPanel();
    QSignalSpy ended(model(), &AccuracySweepModel::sweepEnded);
    QTest::mouseClick(button("exploreButton"), Qt::LeftButton);
    QVERIFY2(model()->isRunning(), qPrintable(panel()->findChild<QLabel*>(QStringLiteral("sweepStatus"))->text()));
    QSignalSpy progress(model(), &AccuracySweepModel::progressChanged);
    QVERIFY(QTest::qWaitFor([&] { return !progress.isEmpty() && progress.last().at(0).toInt() >= 1; }, kSweepTimeoutMs));
    QTest::mouseClick(button("cancelButton"), Qt::LeftButton);
    QVERIFY(waitForSweep());
    QCOMPARE(ended.count(), 1);
    QCOMPARE(ended.at(0).at(0).toBool(), true);
    QVERIFY(model()->wasCancelled());
    // The points finished before Cancel are kept, and only they: fewer than the grid.
    QVERIFY(model()->rowCount() >= 1);
    QVERIFY(model()->rowCount() < int(model()->gridSize()));
    for (int row = 0; row < model()->rowCount(); ++row) QVERIFY(!model()->point(row).failed);
    // A new sweep can start after it.
    QVERIFY(button("exploreButton")->isEnabled());
}

void TestEditorAccuracy::applyingAPointIsOneUndoEntry() {
    panel()->setSpec(tinySpec());
    showPanel();
    QTest::mouseClick(button("exploreButton"), Qt::LeftButton);
    QVERIFY(waitForSweep());
    QCOMPARE(model()->rowCount(), 2);

    // Click the 2-substep point in the plot.
    auto* plot = panel()->findChild<interplay::AccuracyPlot*>();
    QVERIFY(plot);
    settleLayout();
    const int row = 1;
    const std::optional<QPointF> at = plot->pointPosition(row);
    QVERIFY(at);
    QCOMPARE(plot->rowAt(*at), row);
    // Hovering it shows its knobs and figures; clicking it chooses it and shows them beside.
    // (The tooltip event is sent as Qt sends it once the cursor rests: Xvfb's pointer does not
    // follow QTest's synthetic moves, so Qt's own hover timer does not reliably fire.)
    QTest::mouseMove(plot, at->toPoint());
    QHelpEvent hover(QEvent::ToolTip, at->toPoint(), plot->mapToGlobal(at->toPoint()));
    QApplication::sendEvent(plot, &hover);
    QVERIFY2(plot->toolTip().contains(QStringLiteral("substeps=2")), qPrintable(plot->toolTip()));
    QVERIFY(plot->toolTip().contains(QStringLiteral("largest position error")));
    QTest::mouseClick(plot, Qt::LeftButton, {}, at->toPoint());
    QCOMPARE(panel()->chosenRow(), row);
    QVERIFY(panel()->findChild<QLabel*>(QStringLiteral("pointDetails"))->text().contains(QStringLiteral("substeps=2")));

    QUndoStack* undo = m_window->document()->undoStack();
    const simcore::WorldSettings before = m_window->document()->scene().settings;
    const int entries = undo->count();
    QTest::mouseClick(button("applyButton"), Qt::LeftButton);
    QCOMPARE(undo->count(), entries + 1);
    QCOMPARE(undo->undoText(), QStringLiteral("Change settings to an accuracy point"));
    const simcore::WorldSettings& after = m_window->document()->scene().settings;
    QCOMPARE(after.substeps, 2);
    QCOMPARE(after.solver.velocityIterations, 2);
    QVERIFY(after != before);
    QVERIFY(m_window->document()->isModified());

    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(undo->count(), entries + 1);  // still there to redo
    QCOMPARE(undo->index(), entries);
    QVERIFY(m_window->document()->scene().settings == before);
}

void TestEditorAccuracy::editingWhileASweepRunsLeavesItsResults() {
    // Two seconds a run, so that the edits below land while the worker is still stepping.
    accuracy::SweepSpec spec = tinySpec();
    spec.seconds = 2.0;
    panel()->setSpec(spec);
    showPanel();
    const simcore::Scene original = m_window->document()->scene();
    QTest::mouseClick(button("exploreButton"), Qt::LeftButton);
    QVERIFY(model()->isRunning());

    // Edit the scene while the sweep runs: a body added, gravity changed.
    m_window->action(QStringLiteral("addBox"))->trigger();
    QCOMPARE(m_window->document()->scene().bodies.size(), original.bodies.size() + 1);
    QVERIFY(m_window->document()->undoStack()->count() >= 1);
    simcore::Scene edited = m_window->document()->scene();
    QVERIFY(!simcore::applySettingOverride(edited, "gravity=[0,-1.62,0]"));
    m_window->document()->undoStack()->push(
        new interplay::ChangeSettings(m_window->document(), QStringLiteral("Change gravity"), QStringLiteral("gravity"),
                                      edited.settings));
    QVERIFY(waitForSweep());
    QCOMPARE(model()->sweptScene().bodies.size(), original.bodies.size());
    QVERIFY(model()->sweptScene().settings == original.settings);
    QCOMPARE(model()->rowCount(), 2);

    // Its errors are those of the scene as it was: the same sweep run on an unedited copy (errors
    // are deterministic; only timings differ).
    std::vector<accuracy::PointResult> during(model()->rowCount());
    for (int row = 0; row < model()->rowCount(); ++row) during[std::size_t(row)] = model()->point(row);
    QString error;
    QVERIFY(model()->start(original, panel()->spec(), error));
    QVERIFY(waitForSweep());
    QCOMPARE(model()->rowCount(), int(during.size()));
    for (int row = 0; row < model()->rowCount(); ++row) {
        for (std::size_t m = 0; m < accuracy::kMeasureCount; ++m)
            QCOMPARE(model()->point(row).measures[m], during[std::size_t(row)].measures[m]);
    }
}

// With INTERPLAY_ACCURACY_SCREENSHOT=FILE.png (and INTERPLAY_ACCURACY_SCENE=SCENE.json) it sweeps
// that scene at the panel's default grid and saves the window: the README's screenshot.
void TestEditorAccuracy::plotMarksTheFrontAndTheChosenPoint() {
    const QString screenshot = qEnvironmentVariable("INTERPLAY_ACCURACY_SCREENSHOT");
    if (screenshot.isEmpty()) {
        accuracy::SweepSpec spec = tinySpec();
        spec.knobs[0].values = {"1", "2", "4"};
        panel()->setSpec(spec);
    } else {
        QVERIFY(m_window->documentManager()->openFile(qEnvironmentVariable("INTERPLAY_ACCURACY_SCENE")));
    }
    showPanel();
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(button("exploreButton"), Qt::LeftButton);
    QVERIFY(waitForSweep());
    qInfo("%d points in %.1f s", model()->rowCount(), clock.elapsed() / 1000.0);
    QVERIFY(model()->rowCount() >= 3);

    // The cheapest point is always on the front (nothing is cheaper): drawn red; once chosen, blue.
    int cheapest = 0;
    for (int row = 1; row < model()->rowCount(); ++row)
        if (model()->point(row).msPerSimulatedSecond < model()->point(cheapest).msPerSimulatedSecond) cheapest = row;
    QVERIFY(model()->onFront(cheapest, model()->measure()));
    auto* plot = panel()->findChild<interplay::AccuracyPlot*>();
    settleLayout();
    const std::optional<QPointF> at = plot->pointPosition(cheapest);
    QVERIFY(at);
    const auto colourAt = [plot](QPointF p) { return plot->grab().toImage().pixelColor(p.toPoint() * plot->devicePixelRatio()); };
    QColor drawn = colourAt(*at);
    QVERIFY2(drawn.red() > 150 && drawn.green() < 100 && drawn.blue() < 100, qPrintable(drawn.name()));
    QTest::mouseClick(plot, Qt::LeftButton, {}, at->toPoint());
    QCOMPARE(panel()->chosenRow(), cheapest);
    drawn = colourAt(*at);
    QVERIFY2(drawn.blue() > 150 && drawn.red() < 100, qPrintable(drawn.name()));

    if (!screenshot.isEmpty()) {
        // A taller dock than the default layout's, so that the plot reads.
        auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
        m_window->resizeDocks({dock}, {430}, Qt::Vertical);
        QTest::qWait(300);
        QVERIFY(m_window->grab().save(screenshot));
    }
}

QTEST_MAIN(TestEditorAccuracy)
#include "test_editor_accuracy.moc"
