#include "app/panels/accuracy_plot.h"

#include "app/panels/accuracy_sweep_model.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace interplay {

namespace {

constexpr double kPickRadius = 8.0;   // px: how near the cursor a point must be to be hovered or clicked
constexpr double kFailedBand = 18.0;  // px above the plot area where failed runs sit
const QColor kGridPoint(150, 150, 150);
const QColor kFront(200, 40, 40);
const QColor kChosen(30, 100, 220);

QString decadeLabel(int exponent) {
    return QStringLiteral("1e%1").arg(exponent);
}

}  // namespace

struct AccuracyPlot::Frame {
    QRectF area;
    double xMin, xMax, yMin, yMax;  // log10 of the data range, widened to whole decades

    double x(double cost) const { return area.left() + (std::log10(cost) - xMin) / (xMax - xMin) * area.width(); }
    double y(double error) const {
        if (std::isinf(error)) return area.top() - kFailedBand / 2;
        if (error <= 0.0) return area.bottom();
        return area.bottom() - (std::log10(error) - yMin) / (yMax - yMin) * area.height();
    }
};

AccuracyPlot::AccuracyPlot(AccuracySweepModel* model, QWidget* parent) : QWidget(parent), m_model(model) {
    setObjectName(QStringLiteral("accuracyPlot"));
    connect(model, &QAbstractItemModel::modelReset, this, qOverload<>(&QWidget::update));
    connect(model, &QAbstractItemModel::dataChanged, this, qOverload<>(&QWidget::update));
}

void AccuracyPlot::setChosenRow(int row) {
    m_chosenRow = row;
    update();
}

std::optional<AccuracyPlot::Frame> AccuracyPlot::frame() const {
    double costLow = std::numeric_limits<double>::infinity(), costHigh = 0.0;
    double errorLow = std::numeric_limits<double>::infinity(), errorHigh = 0.0;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const double cost = m_model->index(row, 0).data(AccuracySweepModel::CostRole).toDouble();
        const double error = m_model->index(row, 0).data(AccuracySweepModel::ErrorRole).toDouble();
        if (!(cost > 0.0) || !std::isfinite(cost)) continue;
        costLow = std::min(costLow, cost);
        costHigh = std::max(costHigh, cost);
        if (error > 0.0 && std::isfinite(error)) {
            errorLow = std::min(errorLow, error);
            errorHigh = std::max(errorHigh, error);
        }
    }
    if (costHigh <= 0.0) return std::nullopt;
    if (errorHigh <= 0.0) errorLow = errorHigh = 1.0;  // every error zero or failed: one decade around 1
    const QFontMetrics metrics(font());
    Frame f;
    f.area = QRectF(metrics.horizontalAdvance(QStringLiteral("1e-10")) + 14.0, kFailedBand + metrics.height() + 6.0, 0, 0);
    f.area.setRight(width() - 12.0);
    f.area.setBottom(height() - 2.4 * metrics.height() - 6.0);
    f.xMin = std::floor(std::log10(costLow));
    f.xMax = std::max(std::ceil(std::log10(costHigh)), f.xMin + 1);
    f.yMin = std::floor(std::log10(errorLow));
    f.yMax = std::max(std::ceil(std::log10(errorHigh)), f.yMin + 1);
    if (f.area.width() < 20 || f.area.height() < 20) return std::nullopt;
    return f;
}

std::optional<QPointF> AccuracyPlot::pointPosition(int row) const {
    const std::optional<Frame> f = frame();
    const double cost = m_model->index(row, 0).data(AccuracySweepModel::CostRole).toDouble();
    if (!f || !(cost > 0.0) || !std::isfinite(cost)) return std::nullopt;
    return QPointF(f->x(cost), f->y(m_model->index(row, 0).data(AccuracySweepModel::ErrorRole).toDouble()));
}

int AccuracyPlot::rowAt(const QPointF& position) const {
    int nearest = -1;
    double best = kPickRadius;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const std::optional<QPointF> p = pointPosition(row);
        if (!p) continue;
        const double distance = std::hypot(p->x() - position.x(), p->y() - position.y());
        if (distance <= best) {
            best = distance;
            nearest = row;
        }
    }
    return nearest;
}

void AccuracyPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    const QFontMetrics metrics(font());
    const std::optional<Frame> f = frame();
    if (!f) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         tr("Explore accuracy sweeps the scene over a grid of settings;\nits error against cost is drawn here."));
        return;
    }
    const QColor text = palette().color(QPalette::Text);

    // Decade grid lines and their labels.
    painter.setPen(QPen(palette().color(QPalette::Mid), 0.5, Qt::DotLine));
    for (int e = int(f->xMin); e <= int(f->xMax); ++e) {
        const double x = f->area.left() + (e - f->xMin) / (f->xMax - f->xMin) * f->area.width();
        painter.drawLine(QPointF(x, f->area.top()), QPointF(x, f->area.bottom()));
    }
    for (int e = int(f->yMin); e <= int(f->yMax); ++e) {
        const double y = f->area.bottom() - (e - f->yMin) / (f->yMax - f->yMin) * f->area.height();
        painter.drawLine(QPointF(f->area.left(), y), QPointF(f->area.right(), y));
    }
    painter.setPen(text);
    for (int e = int(f->xMin); e <= int(f->xMax); ++e) {
        const double x = f->area.left() + (e - f->xMin) / (f->xMax - f->xMin) * f->area.width();
        const QString label = decadeLabel(e);
        painter.drawText(QPointF(x - metrics.horizontalAdvance(label) / 2.0, f->area.bottom() + metrics.ascent() + 3), label);
    }
    for (int e = int(f->yMin); e <= int(f->yMax); ++e) {
        const double y = f->area.bottom() - (e - f->yMin) / (f->yMax - f->yMin) * f->area.height();
        const QString label = decadeLabel(e);
        painter.drawText(QPointF(f->area.left() - metrics.horizontalAdvance(label) - 5, y + metrics.ascent() / 2.0), label);
    }
    painter.drawRect(f->area);
    const QString xLabel = tr("ms per simulated second (log)");
    painter.drawText(QPointF(f->area.center().x() - metrics.horizontalAdvance(xLabel) / 2.0, height() - 4.0), xLabel);
    painter.drawText(QPointF(4, metrics.ascent() + 2), tr("%1, log; failed runs above the box")
                                                            .arg(AccuracySweepModel::measureLabel(m_model->measure())));

    // The front, cheapest first: the rows in order of cost.
    std::vector<std::pair<double, QPointF>> front;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        if (!m_model->onFront(row, m_model->measure())) continue;
        if (const std::optional<QPointF> p = pointPosition(row))
            front.emplace_back(m_model->index(row, 0).data(AccuracySweepModel::CostRole).toDouble(), *p);
    }
    std::sort(front.begin(), front.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (front.size() > 1) {
        QPainterPath path(front.front().second);
        for (const auto& [cost, p] : front) path.lineTo(p);
        painter.setPen(QPen(kFront, 1.5));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(path);
    }

    // The chosen point last, on top of any it overlaps.
    std::vector<int> order;
    for (int row = 0; row < m_model->rowCount(); ++row)
        if (row != m_chosenRow) order.push_back(row);
    if (m_chosenRow >= 0 && m_chosenRow < m_model->rowCount()) order.push_back(m_chosenRow);
    for (int row : order) {
        const std::optional<QPointF> p = pointPosition(row);
        if (!p) continue;
        const bool onFront = m_model->onFront(row, m_model->measure());
        painter.setPen(Qt::NoPen);
        painter.setBrush(row == m_chosenRow ? kChosen : onFront ? kFront : kGridPoint);
        painter.drawEllipse(*p, row == m_chosenRow ? 5.0 : 3.5, row == m_chosenRow ? 5.0 : 3.5);
        if (const QStringList labels = m_model->labels(row); !labels.isEmpty()) {
            painter.setPen(QPen(text, 1.2));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(*p, 7.0, 7.0);
            painter.drawText(*p + QPointF(9, -4), labels.join(QStringLiteral(", ")));
        }
    }

    // Legend, top right inside the box.
    const QStringList entries{tr("grid point"), tr("Pareto front"), tr("scene / preset"), tr("chosen")};
    const double rowHeight = metrics.height();
    double legendWidth = 0;
    for (const QString& e : entries) legendWidth = std::max<double>(legendWidth, metrics.horizontalAdvance(e));
    QRectF legend(f->area.right() - legendWidth - 30, f->area.top() + 4, legendWidth + 26, rowHeight * entries.size() + 6);
    painter.setPen(QPen(palette().color(QPalette::Mid), 0.5));
    painter.setBrush(palette().base());
    painter.drawRect(legend);
    for (int i = 0; i < entries.size(); ++i) {
        const QPointF mark(legend.left() + 10, legend.top() + 3 + rowHeight * (i + 0.5));
        painter.setPen(Qt::NoPen);
        painter.setBrush(i == 0 ? kGridPoint : i == 1 ? kFront : i == 3 ? kChosen : QColor(Qt::transparent));
        painter.drawEllipse(mark, 3.5, 3.5);
        if (i == 2) {
            painter.setPen(QPen(text, 1.2));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(mark, 6.0, 6.0);
        }
        painter.setPen(text);
        painter.drawText(QPointF(mark.x() + 10, mark.y() + metrics.ascent() / 2.0 - 1), entries[i]);
    }
}

bool AccuracyPlot::event(QEvent* event) {
    // Qt's hover tooltip, due once the cursor rests: the point under it, or none (QWidget::event
    // then shows nothing).
    if (event->type() == QEvent::ToolTip) {
        const int row = rowAt(static_cast<QHelpEvent*>(event)->pos());
        setToolTip(row >= 0 ? m_model->describe(row) : QString());
    }
    return QWidget::event(event);
}

void AccuracyPlot::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
    if (const int row = rowAt(event->position()); row >= 0) emit rowClicked(row);
}

}  // namespace interplay
