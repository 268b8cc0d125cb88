#pragma once
// The Accuracy dock: "Explore accuracy" sweeps a snapshot of the open scene over a small grid of
// settings in the background (AccuracySweepModel), with a progress bar and Cancel while the editor
// stays usable; then plots the chosen measure's error against cost (AccuracyPlot) and lists the
// points. Hovering a point shows its knobs and figures, clicking it (or its row) chooses it, and
// Apply makes the chosen point's knobs the document's settings as one undoable edit, through the
// Simulation settings model.

#include "accuracy/scene_sweep.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;

namespace interplay {

class AccuracyPlot;
class AccuracySweepModel;
class SceneDocument;
class SimulationSettingsModel;

class AccuracyPanel : public QWidget {
    Q_OBJECT

public:
    AccuracyPanel(SceneDocument* document, SimulationSettingsModel* settings, QWidget* parent = nullptr);

    AccuracySweepModel* model() const { return m_model; }
    // The grid the next sweep runs (AccuracySweepModel::defaultSpec() at first); the seconds field
    // overrides its duration.
    const accuracy::SweepSpec& spec() const { return m_spec; }
    void setSpec(const accuracy::SweepSpec& spec);
    int chosenRow() const { return m_chosenRow; }

public slots:
    // Starts a sweep of the document's scene as it is now; a refusal is shown in the status line.
    void explore();
    void cancel();
    void choose(int row);
    void applyChosen();

private:
    void sweepEnded(bool cancelled, const QString& error);
    void updateControls();

    SceneDocument* m_document;
    SimulationSettingsModel* m_settings;
    AccuracySweepModel* m_model;
    accuracy::SweepSpec m_spec;
    int m_chosenRow = -1;

    QPushButton* m_explore;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QDoubleSpinBox* m_seconds;
    QComboBox* m_measure;
    QLabel* m_status;
    AccuracyPlot* m_plot;
    QTableView* m_table;
    QLabel* m_details;
    QPushButton* m_apply;
};

}  // namespace interplay
