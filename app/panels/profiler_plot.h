#pragma once
// Time per step, stage by stage, over the last steps: a stacked area plot drawn with QPainter.
// The newest step is at the right edge; the vertical scale follows the largest total in view,
// rounded to a 1-2-5 step so the grid labels stay readable.

#include <QWidget>

namespace interplay {

class SimulationController;

class ProfilerPlot : public QWidget {
    Q_OBJECT

public:
    explicit ProfilerPlot(SimulationController* simulation, QWidget* parent = nullptr);

    QSize sizeHint() const override { return {360, 180}; }
    QSize minimumSizeHint() const override { return {200, 120}; }

    // The top of the vertical axis for a largest value (ms): 1, 2 or 5 times a power of ten.
    static double niceCeiling(double value);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    SimulationController* m_simulation;
};

}  // namespace interplay
