#pragma once
// The accuracy panel's plot: the chosen measure's error against ms per simulated second, log-log,
// drawn with QPainter from the sweep model (no chart library): grid points grey, the Pareto front
// as a red line, the scene's own settings and the presets ringed and named, the chosen point
// filled blue, failed runs in a band above the plot and zero errors on its bottom edge. Cost is
// per simulated second rather than per step so that points with different time steps compare
// (the front is taken on it); the table and the tooltip give ms/step too. Hovering a point shows
// its knobs and figures; clicking one chooses it.

#include <QWidget>

#include <optional>

namespace interplay {

class AccuracySweepModel;

class AccuracyPlot : public QWidget {
    Q_OBJECT

public:
    explicit AccuracyPlot(AccuracySweepModel* model, QWidget* parent = nullptr);

    void setChosenRow(int row);  // -1: none
    // Where row `row` is drawn, in widget coordinates (nothing when it is not drawn).
    std::optional<QPointF> pointPosition(int row) const;
    // The row drawn nearest `position`, within a few pixels, or -1.
    int rowAt(const QPointF& position) const;

    QSize sizeHint() const override { return {520, 300}; }
    QSize minimumSizeHint() const override { return {260, 160}; }

signals:
    void rowClicked(int row);

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    struct Frame;  // the plot area and its log ranges
    std::optional<Frame> frame() const;

    AccuracySweepModel* m_model;
    int m_chosenRow = -1;
};

}  // namespace interplay
