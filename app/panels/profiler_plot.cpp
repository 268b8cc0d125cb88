#include "app/panels/profiler_plot.h"

#include "app/simulation/simulation_controller.h"

#include "simcore/world/profiler.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>

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
constexpr int kLegendWidth = 170;  // room for "integrate velocities  0.000"
constexpr int kAxisWidth = 48;
constexpr int kMargin = 6;

}  // namespace

ProfilerPlot::ProfilerPlot(SimulationController* simulation, QWidget* parent)
    : QWidget(parent), m_simulation(simulation) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    connect(simulation, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
    connect(simulation, &SimulationController::worldRebuilt, this, qOverload<>(&QWidget::update));
}

double ProfilerPlot::niceCeiling(double value) {
    if (!(value > 0.0)) return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        if (value <= factor * power * (1.0 + 1e-9)) return factor * power;
    }
    return 10.0 * power;
}

void ProfilerPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());

    const QRectF plot(kAxisWidth, kMargin, std::max(10, width() - kAxisWidth - kLegendWidth - kMargin),
                      std::max(10, height() - 2 * kMargin - 14));
    const auto& history = m_simulation->history();
    double largest = 0.0;
    for (const StepSample& sample : history) {
        double sum = 0.0;
        for (double ms : sample.profile.stageMs) sum += ms;
        largest = std::max(largest, sum);
    }
    const double top = niceCeiling(largest);
    const auto capacity = static_cast<double>(SimulationController::kHistoryLength);
    const auto xAt = [&](std::size_t i) {
        // The newest sample at the right edge; older ones scroll left.
        const double age = static_cast<double>(history.size() - 1 - i);
        return plot.right() - age / (capacity - 1.0) * plot.width();
    };
    const auto yAt = [&](double ms) { return plot.bottom() - ms / top * plot.height(); };

    // Grid: four bands, labelled in ms.
    painter.setPen(QPen(palette().mid().color(), 0.0, Qt::DotLine));
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    painter.setFont(small);
    for (int line = 0; line <= 4; ++line) {
        const double ms = top * line / 4.0;
        const double y = yAt(ms);
        painter.setPen(QPen(palette().mid().color(), 0.0, line == 0 ? Qt::SolidLine : Qt::DotLine));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(palette().text().color());
        painter.drawText(QRectF(0, y - 8, kAxisWidth - 4, 16), Qt::AlignRight | Qt::AlignVCenter,
                         QStringLiteral("%1").arg(ms, 0, 'g', 3));
    }
    painter.drawText(QRectF(0, plot.bottom() + 2, kAxisWidth - 4, 14), Qt::AlignRight, tr("ms"));
    painter.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), 14), Qt::AlignRight,
                     tr("last %1 steps").arg(SimulationController::kHistoryLength));

    // Stacked areas, bottom stage first: each band lies between the running sums below and above it.
    if (history.size() >= 2) {
        std::vector<double> below(history.size(), 0.0);
        for (int stage = 0; stage < simcore::kStageCount; ++stage) {
            QPainterPath band;
            std::vector<double> above(history.size());
            for (std::size_t i = 0; i < history.size(); ++i) {
                above[i] = below[i] + history[i].profile.stageMs[static_cast<std::size_t>(stage)];
                const QPointF p(xAt(i), yAt(above[i]));
                i == 0 ? band.moveTo(p) : band.lineTo(p);
            }
            for (std::size_t i = history.size(); i-- > 0;) band.lineTo(xAt(i), yAt(below[i]));
            band.closeSubpath();
            QColor color = QColor::fromRgb(kStageColors[static_cast<std::size_t>(stage)]);
            painter.setPen(Qt::NoPen);
            painter.setBrush(color);
            painter.drawPath(band);
            below = std::move(above);
        }
    } else {
        painter.setPen(palette().placeholderText().color());
        painter.drawText(plot, Qt::AlignCenter, tr("Play or step to measure"));
    }

    // Legend: stage colour, name and the latest step's time; rows shrink to fit a low dock.
    const double legendX = plot.right() + 10;
    const double rowHeight = std::clamp((height() - 2.0 * kMargin) / simcore::kStageCount, 10.0, 16.0);
    for (int stage = 0; stage < simcore::kStageCount; ++stage) {
        const double y = kMargin + stage * rowHeight;
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor::fromRgb(kStageColors[static_cast<std::size_t>(stage)]));
        painter.drawRect(QRectF(legendX, y + (rowHeight - 8.0) / 2.0, 8, 8));
        painter.setPen(palette().text().color());
        const double latest = history.empty() ? 0.0 : history.back().profile.stageMs[static_cast<std::size_t>(stage)];
        const std::string_view name = simcore::kStages[static_cast<std::size_t>(stage)].name;
        painter.drawText(QRectF(legendX + 14, y, kLegendWidth - 16, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         QStringLiteral("%1  %2")
                             .arg(QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())))
                             .arg(latest, 0, 'f', 3));
    }
}

}  // namespace interplay
