#include "app/panels/profiler_plot.h"

#include "app/simulation/run_series.h"
#include "app/simulation/simulation_controller.h"

#include "simcore/world/world.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>

namespace interplay {
namespace {

// One colour per stage of simcore::kStages, in its order (qualitative, distinguishable when
// stacked; neighbours differ in hue).
constexpr std::array<QRgb, simcore::kStageCount> kStageColors{
    0xF58518,  // pairs
    0xE45756,  // collide
    0xB279A2,  // islands
    0x9D755D,  // prepare
    0x4C78A8,  // integrate velocities
    0xFF9DA6,  // warm start
    0x72B7B2,  // solve
    0x54A24B,  // integrate positions
    0xEECA3B,  // restitution
    0x88D27A,  // relax
    0xBAB0AC,  // store impulses
    0x2F4B7C,  // continuous
    0xD67195,  // sleep
};
constexpr int kMargin = 6;
constexpr double kTimeLabelSpacing = 90.0;  // px per time tick, room for "12.5 s"
constexpr double kValueTicks = 4.0;         // bands on the value axis

double stageSum(const RunSample& sample) {
    double sum = 0.0;
    for (double ms : sample.stageMs) sum += ms;
    return sum;
}

QFont labelFont(const QFont& base) {
    QFont small = base;
    small.setPointSizeF(small.pointSizeF() * 0.85);
    return small;
}

}  // namespace

ProfilerPlot::ProfilerPlot(SimulationController* simulation, QWidget* parent)
    : QWidget(parent), m_simulation(simulation) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setMouseTracking(true);  // hover values without a button held
    setPlot(Plot::TimePerStage);
    connect(simulation, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
    connect(simulation, &SimulationController::worldRebuilt, this, qOverload<>(&QWidget::update));
}

void ProfilerPlot::setPlot(Plot plot) {
    m_plot = plot;
    m_series.clear();
    m_stacked = plot == Plot::TimePerStage;
    switch (plot) {
    case Plot::TimePerStage:
        m_unit = tr("ms");
        for (std::size_t stage = 0; stage < simcore::kStageCount; ++stage) {
            const std::string_view name = simcore::kStages[stage].name;
            m_series.push_back({QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())),
                                QColor::fromRgb(kStageColors[stage]),
                                [stage](const RunSample& s) { return s.stageMs[stage]; }});
        }
        break;
    case Plot::Energy:
        m_unit = tr("J");
        m_series = {{tr("kinetic"), QColor::fromRgb(0xE45756), [](const RunSample& s) { return s.kineticEnergy; }},
                    {tr("potential"), QColor::fromRgb(0x4C78A8), [](const RunSample& s) { return s.potentialEnergy; }},
                    {tr("total"), QColor::fromRgb(0x54A24B), [](const RunSample& s) { return s.totalEnergy(); }}};
        break;
    case Plot::Penetration:
        m_unit = tr("mm");
        m_series = {{tr("deepest penetration"), QColor::fromRgb(0xE45756),
                     [](const RunSample& s) { return s.maxPenetration * 1000.0; }}};
        break;
    case Plot::JointError:
        m_unit = tr("mm");
        m_series = {{tr("largest joint error"), QColor::fromRgb(0xB279A2),
                     [](const RunSample& s) { return s.jointError * 1000.0; }}};
        break;
    }
    update();
}

double ProfilerPlot::niceCeiling(double value) {
    if (!(value > 0.0)) return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        if (value <= factor * power * (1.0 + 1e-9)) return factor * power;
    }
    return 10.0 * power;
}

ProfilerPlot::Layout ProfilerPlot::layout() const {
    const RunSeries& run = m_simulation->series();
    Layout result;

    // Values: the range of every series (the stack's top when stacked); the measures that cannot
    // go below zero keep zero in view, energy (relative to an arbitrary height) need not.
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t i = 0; i < run.size(); ++i) {
        if (m_stacked) {
            high = std::max(high, stageSum(run[i]));
            continue;
        }
        for (const Series& series : m_series) {
            const double v = series.value(run[i]);
            low = std::min(low, v);
            high = std::max(high, v);
        }
    }
    if (run.empty()) low = high = 0.0;
    if (m_plot != Plot::Energy) low = std::min(low, 0.0);
    const double span = high - low > 0.0 ? high - low : std::max(std::abs(high), 1.0);
    Axis& values = result.values;
    values.step = niceCeiling(span / kValueTicks);
    values.low = std::floor(low / values.step + 1e-9) * values.step;
    values.high = std::max(std::ceil(high / values.step - 1e-9) * values.step, values.low + values.step);
    values.decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(values.step))), 0, 6);

    // Room for the labels: the widest value label at the left, the widest legend row at the right.
    const QFontMetricsF metrics(labelFont(font()));
    const int tickDecimals = std::max(0, values.decimals - 1);
    const double axisWidth =
        std::max({metrics.horizontalAdvance(QString::number(values.low, 'f', tickDecimals)),
                  metrics.horizontalAdvance(QString::number(values.high, 'f', tickDecimals)),
                  metrics.horizontalAdvance(m_unit)}) + 10.0;
    // Every value shown lies within the axis, so the wider of its ends fits any of them.
    const double valueWidth = std::max(metrics.horizontalAdvance(format(values.low, values.decimals)),
                                       metrics.horizontalAdvance(format(values.high, values.decimals)));
    double legendWidth = 0.0;
    for (const Series& series : m_series)
        legendWidth = std::max(legendWidth, metrics.horizontalAdvance(series.name + QStringLiteral("  ")) + valueWidth);
    legendWidth = std::min(legendWidth + 24.0, width() / 2.0);
    const double top = kMargin + metrics.height();  // the unit above the value axis
    const double bottom = kMargin + metrics.height() + 2.0;  // the time labels
    result.area = QRectF(axisWidth, top, std::max(10.0, width() - axisWidth - legendWidth - kMargin),
                         std::max(10.0, height() - top - bottom));

    // Time: the samples held, first to last, with ticks a label's width apart.
    Axis& times = result.times;
    times.low = run.empty() ? 0.0 : run.front().time;
    times.high = run.size() < 2 ? times.low + 1.0 : run.back().time;
    times.step = niceCeiling((times.high - times.low) / std::max(1.0, result.area.width() / kTimeLabelSpacing));
    times.decimals = std::clamp(-static_cast<int>(std::floor(std::log10(times.step))), 0, 6);
    return result;
}

QRectF ProfilerPlot::plotArea() const { return layout().area; }

QString ProfilerPlot::format(double value, int decimals) const {
    if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0.00"
    return QStringLiteral("%1 %2").arg(value, 0, 'f', decimals).arg(m_unit);
}

std::optional<std::size_t> ProfilerPlot::hoveredSample() const {
    const RunSeries& run = m_simulation->series();
    if (!m_hoverX || run.size() < 2) return std::nullopt;
    const Layout l = layout();
    if (*m_hoverX < l.area.left() - 1.0 || *m_hoverX > l.area.right() + 1.0) return std::nullopt;
    const double fraction = std::clamp((*m_hoverX - l.area.left()) / l.area.width(), 0.0, 1.0);
    return run.nearest(l.times.low + fraction * (l.times.high - l.times.low));
}

QStringList ProfilerPlot::readout() const {
    const std::optional<std::size_t> hovered = hoveredSample();
    if (!hovered) return {};
    const RunSample& sample = m_simulation->series()[*hovered];
    const int decimals = layout().values.decimals;
    QStringList lines{tr("%1 s").arg(sample.time, 0, 'f', 3)};
    if (m_stacked) {
        lines << tr("total %1").arg(format(stageSum(sample), decimals));
    } else {
        for (const Series& series : m_series) lines << series.name + QLatin1Char(' ') + format(series.value(sample), decimals);
    }
    return lines;
}

void ProfilerPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    painter.setFont(labelFont(font()));
    const Layout l = layout();
    drawAxes(painter, l);
    if (m_simulation->series().size() >= 2) {
        painter.save();
        painter.setClipRect(l.area.adjusted(-1, -2, 1, 2));
        m_stacked ? drawStacked(painter, l) : drawLines(painter, l);
        painter.restore();
        drawCursor(painter, l);
    } else {
        painter.setPen(palette().placeholderText().color());
        painter.drawText(l.area, Qt::AlignCenter, tr("Play or step to measure"));
    }
    drawLegend(painter, l);
}

void ProfilerPlot::drawAxes(QPainter& painter, const Layout& l) const {
    const QRectF& area = l.area;
    const double fontHeight = painter.fontMetrics().height();
    const int tickDecimals = std::max(0, l.values.decimals - 1);
    for (double v = l.values.low; v <= l.values.high + 0.5 * l.values.step; v += l.values.step) {
        const double y = l.yAt(v);
        const bool zero = std::abs(v) < 0.5 * l.values.step;
        painter.setPen(QPen(palette().mid().color(), 0.0, zero || v == l.values.low ? Qt::SolidLine : Qt::DotLine));
        painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
        painter.setPen(palette().text().color());
        painter.drawText(QRectF(0, y - fontHeight / 2, area.left() - 5, fontHeight), Qt::AlignRight | Qt::AlignVCenter,
                         QString::number(zero ? 0.0 : v, 'f', tickDecimals));
    }
    painter.drawText(QRectF(0, kMargin / 2.0, area.left() - 5, fontHeight), Qt::AlignRight | Qt::AlignVCenter, m_unit);

    // Time ticks at the multiples of the step within the samples' span.
    for (double t = std::ceil(l.times.low / l.times.step - 1e-9) * l.times.step; t <= l.times.high + 1e-9; t += l.times.step) {
        const double x = l.xAt(t);
        painter.setPen(QPen(palette().mid().color(), 0.0, Qt::DotLine));
        painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
        painter.setPen(palette().text().color());
        const QString label = tr("%1 s").arg(t, 0, 'f', l.times.decimals);
        const double labelWidth = painter.fontMetrics().horizontalAdvance(label);
        // Centred under its tick, but kept inside the widget at either end.
        const double left = std::max(0.0, std::min(x - labelWidth / 2, width() - labelWidth));
        painter.drawText(QRectF(left, area.bottom() + 2, labelWidth, fontHeight), Qt::AlignCenter, label);
    }
}

void ProfilerPlot::drawLines(QPainter& painter, const Layout& l) const {
    const RunSeries& run = m_simulation->series();
    for (const Series& series : m_series) {
        // Per pixel column, the lowest and the highest sample in the order they came: spikes stay.
        QPolygonF points;
        int column = INT_MIN;
        std::size_t lowest = 0, highest = 0;
        double lowValue = 0.0, highValue = 0.0;
        const auto flush = [&] {
            if (column == INT_MIN) return;
            const bool lowFirst = lowest <= highest;
            for (const auto& [i, v] : {lowFirst ? std::pair(lowest, lowValue) : std::pair(highest, highValue),
                                       lowFirst ? std::pair(highest, highValue) : std::pair(lowest, lowValue)}) {
                const QPointF p(l.xAt(run[i].time), l.yAt(v));
                if (points.isEmpty() || points.back() != p) points << p;
            }
        };
        for (std::size_t i = 0; i < run.size(); ++i) {
            const int c = static_cast<int>(std::floor(l.xAt(run[i].time)));
            const double v = series.value(run[i]);
            if (c != column) {
                flush();
                column = c;
                lowest = highest = i;
                lowValue = highValue = v;
            } else if (v < lowValue) {
                lowest = i;
                lowValue = v;
            } else if (v > highValue) {
                highest = i;
                highValue = v;
            }
        }
        flush();
        painter.setPen(QPen(series.color, 1.5));
        painter.drawPolyline(points);
    }
}

void ProfilerPlot::drawStacked(QPainter& painter, const Layout& l) const {
    const RunSeries& run = m_simulation->series();
    // Per pixel column, the step that took longest: a slow step stays visible in a long run.
    std::vector<std::size_t> shown;
    int column = INT_MIN;
    double longest = 0.0;  // ms, of shown.back()
    for (std::size_t i = 0; i < run.size(); ++i) {
        const int c = static_cast<int>(std::floor(l.xAt(run[i].time)));
        const double ms = stageSum(run[i]);
        if (c != column) {
            shown.push_back(i);
            column = c;
            longest = ms;
        } else if (ms > longest) {
            shown.back() = i;
            longest = ms;
        }
    }
    // Bottom stage first: each band lies between the running sums below and above it.
    std::vector<double> below(shown.size(), 0.0), above(shown.size());
    for (std::size_t stage = 0; stage < m_series.size(); ++stage) {
        QPainterPath band;
        for (std::size_t k = 0; k < shown.size(); ++k) {
            above[k] = below[k] + run[shown[k]].stageMs[stage];
            const QPointF p(l.xAt(run[shown[k]].time), l.yAt(above[k]));
            k == 0 ? band.moveTo(p) : band.lineTo(p);
        }
        for (std::size_t k = shown.size(); k-- > 0;) band.lineTo(l.xAt(run[shown[k]].time), l.yAt(below[k]));
        band.closeSubpath();
        painter.setPen(Qt::NoPen);
        painter.setBrush(m_series[stage].color);
        painter.drawPath(band);
        std::swap(below, above);
    }
}

void ProfilerPlot::drawLegend(QPainter& painter, const Layout& l) const {
    // The hovered sample's values, else the latest; rows shrink to fit a low dock.
    const RunSeries& run = m_simulation->series();
    const std::optional<std::size_t> hovered = hoveredSample();
    const RunSample* sample = hovered ? &run[*hovered] : run.empty() ? nullptr : &run.back();
    const double legendX = l.area.right() + 12;
    const double rowHeight = std::clamp((height() - 2.0 * kMargin) / static_cast<double>(m_series.size()), 10.0, 18.0);
    for (std::size_t row = 0; row < m_series.size(); ++row) {
        const Series& series = m_series[row];
        const double y = kMargin + static_cast<double>(row) * rowHeight;
        painter.setPen(Qt::NoPen);
        painter.setBrush(series.color);
        painter.drawRect(QRectF(legendX, y + (rowHeight - 8.0) / 2.0, 8, 8));
        painter.setPen(palette().text().color());
        painter.drawText(QRectF(legendX + 14, y, width() - legendX - 14, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         series.name + QStringLiteral("  ") + (sample ? format(series.value(*sample), l.values.decimals) : QStringLiteral("–")));
    }
}

void ProfilerPlot::drawCursor(QPainter& painter, const Layout& l) const {
    const RunSeries& run = m_simulation->series();
    const QRectF& area = l.area;

    // The frame shown, when the timeline is scrubbed back: the samples after it go if Play resumes.
    // The snapshot's time: painting never waits for a step in flight.
    if (const double shown = m_simulation->snapshot().simulatedTime; shown < run.back().time) {
        painter.setPen(QPen(palette().highlight().color(), 1.0, Qt::DashLine));
        const double x = l.xAt(shown);
        painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    }

    const std::optional<std::size_t> hovered = hoveredSample();
    if (!hovered) return;
    const RunSample& sample = run[*hovered];
    const double x = l.xAt(sample.time);
    painter.setPen(QPen(palette().text().color(), 1.0));
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    if (m_stacked) {
        painter.setBrush(palette().text());  // the stack's top: the step's time
        painter.drawEllipse(QPointF(x, l.yAt(stageSum(sample))), 3.0, 3.0);
    } else {
        for (const Series& series : m_series) {
            painter.setBrush(series.color);
            painter.drawEllipse(QPointF(x, l.yAt(series.value(sample))), 3.0, 3.0);
        }
    }

    // The readout beside the cursor line, on whichever side has room.
    const QStringList lines = readout();
    const QFontMetricsF metrics(painter.font());
    double boxWidth = 0.0;
    for (const QString& line : lines) boxWidth = std::max(boxWidth, metrics.horizontalAdvance(line));
    boxWidth += 10.0;
    const double boxHeight = lines.size() * metrics.height() + 6.0;
    const double left = x + 8.0 + boxWidth <= area.right() ? x + 8.0 : std::max(area.left(), x - 8.0 - boxWidth);
    const QRectF box(left, area.top() + 2.0, boxWidth, boxHeight);
    painter.setPen(palette().mid().color());
    painter.setBrush(palette().toolTipBase());
    painter.drawRect(box);
    painter.setPen(palette().toolTipText().color());
    painter.drawText(box.adjusted(5, 3, -5, -3), Qt::AlignLeft | Qt::AlignTop, lines.join(QLatin1Char('\n')));
}

void ProfilerPlot::mouseMoveEvent(QMouseEvent* event) {
    m_hoverX = event->position().x();
    update();
}

void ProfilerPlot::leaveEvent(QEvent*) {
    m_hoverX.reset();
    update();
}

}  // namespace interplay
