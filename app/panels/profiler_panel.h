#pragma once
// The Profiler dock: per-stage time per step over time (ProfilerPlot), and the latest step's
// counters and error measures: bodies awake, pairs, contacts, islands, kinetic and potential
// energy, the energy's change since the world was built, the deepest penetration, and which
// stages the step skipped (why, in the tooltip).

#include <QWidget>

class QLabel;

namespace interplay {

class SimulationController;

class ProfilerPanel : public QWidget {
    Q_OBJECT

public:
    explicit ProfilerPanel(SimulationController* simulation, QWidget* parent = nullptr);

    // The text of a figure by key ("msPerStep", "awakeBodies", "kineticEnergy", "skippedStages",
    // ...), for tests.
    QString figure(const QString& key) const;

private:
    void refresh();
    QLabel* addFigure(const QString& key, const QString& label);

    SimulationController* m_simulation;
    QWidget* m_figures;
    double m_initialEnergy = 0.0;  // total energy (J) of the world as built
};

}  // namespace interplay
