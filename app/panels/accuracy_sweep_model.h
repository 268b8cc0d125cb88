#pragma once
// The accuracy panel's sweep and its results, Qt-Widgets-free (interplay_model): a sweep of a
// snapshot of the scene over a grid of settings (interplay_accuracy's engine, the one under
// interplay-sweep) on a worker thread, and its points as a table, one row per point. The scene is
// copied when the sweep starts, so the document can be edited while it runs; the results are for
// the scene as it was then (sweptScene()). Cancelling stops the running points at their next step
// and keeps the points already finished: the table then holds a part of the grid, and
// wasCancelled() says so.

#include "accuracy/scene_sweep.h"

#include "simcore/io/scene.h"

#include <QAbstractTableModel>
#include <QDateTime>

#include <array>
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

namespace interplay {

class AccuracySweepModel : public QAbstractTableModel {
    Q_OBJECT

public:
    // Settings (the point's assignments), labels ("scene", preset names), ms/step, ms per
    // simulated second, then one column per measure in accuracy::Measure order.
    enum Column { SettingsColumn, LabelsColumn, MsPerStepColumn, MsPerSecondColumn, FirstMeasureColumn };
    enum Role {
        OnFrontRole = Qt::UserRole + 1,  // on the front of the chosen measure (measure())
        ErrorRole,                       // the chosen measure's error, a double (+inf: failed)
        CostRole,                        // ms per simulated second, a double
    };

    explicit AccuracySweepModel(QObject* parent = nullptr);
    ~AccuracySweepModel() override;  // cancels a running sweep and waits for its thread

    // The editor's grid, small so that a pile-sized scene finishes in tens of seconds: time step
    // 1/30, 1/60, 1/120 s x 1, 2, 4 substeps x 1, 4 velocity iterations (18 points) over 1 s, plus
    // the scene's own settings and the three quality presets, so that the plot can mark them.
    static accuracy::SweepSpec defaultSpec();

    // Starts sweeping a copy of `scene` over the spec's grid, where points that give the scene the
    // same settings (a preset equal to the scene's own, say) run once, as the first of them; refuses (returns false, with `error`) while a sweep runs
    // or when the spec does not fit the scene (accuracy::checkSpec's sentence).
    bool start(const simcore::Scene& scene, const accuracy::SweepSpec& spec, QString& error);
    void cancel();
    bool isRunning() const { return m_running; }
    bool wasCancelled() const { return m_cancelled; }
    const simcore::Scene& sweptScene() const { return m_scene; }
    QDateTime startedAt() const { return m_startedAt; }
    std::size_t gridSize() const { return m_gridSize; }

    // "largest position error (m)": the measure as the drop-down and the plot name it.
    static QString measureLabel(accuracy::Measure measure);
    // "timeStep=1/60" for timeStep=0.016666668: an assignment as the table and tooltips show it.
    static QString displayAssignment(const std::string& assignment);

    accuracy::Measure measure() const { return m_measure; }
    void setMeasure(accuracy::Measure measure);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    const accuracy::PointResult& point(int row) const { return m_points[static_cast<std::size_t>(row)]; }
    bool onFront(int row, accuracy::Measure measure) const;
    QStringList labels(int row) const;
    // A point's knobs and figures over several lines, for a tooltip or the details line.
    QString describe(int row) const;
    // `settings` with the point's assignments applied: what Apply makes the document's settings.
    simcore::WorldSettings appliedTo(int row, const simcore::Scene& scene) const;

signals:
    // `done` of `total` grid points; done = 0 while the reference runs.
    void progressChanged(int done, int total);
    void runningChanged(bool running);
    // The sweep ended: finished, cancelled (the points done so far are kept) or failed (`error`,
    // the reference did not converge to finite values; no points).
    void sweepEnded(bool cancelled, const QString& error);

private:
    struct Outcome;
    void finish(std::shared_ptr<Outcome> outcome);
    void join();

    simcore::Scene m_scene;
    QDateTime m_startedAt;
    std::size_t m_gridSize = 0;
    std::vector<accuracy::PointResult> m_points;
    std::vector<std::vector<std::string>> m_labels;
    std::array<std::vector<std::size_t>, accuracy::kMeasureCount> m_fronts;
    accuracy::Measure m_measure = accuracy::Measure::PositionMax;
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
    bool m_running = false;
    bool m_cancelled = false;
};

}  // namespace interplay
