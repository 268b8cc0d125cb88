#pragma once
// The Profiler dock: the run's series over time (ProfilerPlot), one plot at a time chosen by tabs
// (time per stage, energy, penetration, joint error), and the latest step's counters and error
// measures: bodies awake, pairs, contacts, islands, kinetic and potential
// energy, the energy's change since the world was built, the deepest penetration, and which
// stages the step skipped (why, in the tooltip).

#include <QWidget>

class QLabel;
class QTabBar;

namespace interplay {

class ProfilerPlot;
class SimulationController;

class ProfilerPanel : public QWidget {
    Q_OBJECT

public:
    explicit ProfilerPanel(SimulationController* simulation, QWidget* parent = nullptr);

    // The text of a figure by key ("msPerStep", "awakeBodies", "kineticEnergy", "skippedStages",
    // ...), for tests.
    QString figure(const QString& key) const;
    ProfilerPlot* plot() const { return m_plot; }
    QTabBar* plotTabs() const { return m_plotTabs; }

private:
    void refresh();
    QLabel* addFigure(const QString& key, const QString& label);

    SimulationController* m_simulation;
    QTabBar* m_plotTabs;
    ProfilerPlot* m_plot;
    QWidget* m_figures;
    double m_initialEnergy = 0.0;  // total energy (J) of the world before its first step
};

}  // namespace interplay
