#pragma once
// The run's series over simulated time (SimulationController::series()), drawn with QPainter: one
// plot at a time, chosen by the Profiler's tabs. Energy (kinetic, potential, total, J), the deepest
// penetration (mm) and the largest joint error (mm) as lines; the time per step, stage by stage
// (ms), as a stacked area. Both axes step by 1, 2 or 5 times a power of ten so their labels stay
// readable; the legend names each series with its latest value. Hovering shows a cursor line with
// the values of the sample nearest the pointer's time, at the cursor and in the legend. More
// samples than pixels are drawn as each column's extremes, so a long run costs what a short one does.

#include <QStringList>
#include <QWidget>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace interplay {

class SimulationController;
struct RunSample;

class ProfilerPlot : public QWidget {
    Q_OBJECT

public:
    enum class Plot { TimePerStage, Energy, Penetration, JointError };

    explicit ProfilerPlot(SimulationController* simulation, QWidget* parent = nullptr);

    QSize sizeHint() const override { return {420, 200}; }
    QSize minimumSizeHint() const override { return {260, 130}; }

    Plot plot() const { return m_plot; }
    void setPlot(Plot plot);

    // The area the series are drawn in (widget coordinates), and the sample the pointer is over.
    QRectF plotArea() const;
    std::optional<std::size_t> hoveredSample() const;
    // What the cursor's readout shows: the hovered sample's time and values, a line each
    // ("0.500 s", "kinetic 12.3 J", ...); empty when nothing is hovered.
    QStringList readout() const;

    // The top of a vertical axis for a largest value: 1, 2 or 5 times a power of ten.
    static double niceCeiling(double value);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    struct Series {
        QString name;
        QColor color;
        std::function<double(const RunSample&)> value;  // in the plot's unit
    };
    struct Axis {
        double low = 0.0, high = 1.0, step = 1.0;  // ticks at low, low + step, ..., high
        int decimals = 0;                          // enough to tell one tick from the next
    };
    struct Layout {
        QRectF area;
        Axis values, times;
        double xAt(double time) const { return area.left() + (time - times.low) / (times.high - times.low) * area.width(); }
        double yAt(double value) const {
            return area.bottom() - (value - values.low) / (values.high - values.low) * area.height();
        }
    };

    Layout layout() const;
    QString format(double value, int decimals) const;  // with the unit
    void drawAxes(QPainter& painter, const Layout& layout) const;
    void drawLines(QPainter& painter, const Layout& layout) const;
    void drawStacked(QPainter& painter, const Layout& layout) const;
    void drawLegend(QPainter& painter, const Layout& layout) const;
    void drawCursor(QPainter& painter, const Layout& layout) const;

    SimulationController* m_simulation;
    Plot m_plot = Plot::TimePerStage;
    std::vector<Series> m_series;  // of m_plot
    QString m_unit;                // of m_plot's values
    bool m_stacked = false;
    std::optional<double> m_hoverX;  // the pointer's x while it is over the widget
};

}  // namespace interplay
