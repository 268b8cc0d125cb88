#include "app/panels/profiler_panel.h"

#include "app/panels/profiler_plot.h"
#include "app/simulation/simulation_controller.h"

#include "simcore/world/world.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QTabBar>
#include <QVBoxLayout>

#include <algorithm>

namespace interplay {

namespace {
const QString kPlotKey = QStringLiteral("profiler/plot");  // the tab shown: ProfilerPlot::Plot
}

ProfilerPanel::ProfilerPanel(SimulationController* simulation, QWidget* parent)
    : QWidget(parent), m_simulation(simulation), m_plotTabs(new QTabBar(this)),
      m_plot(new ProfilerPlot(simulation, this)), m_figures(new QWidget(this)) {
    // Plot and figures side by side: the dock sits under the viewport, wide and low. The tabs'
    // order is ProfilerPlot::Plot's.
    m_plotTabs->setObjectName(QStringLiteral("plotTabs"));
    m_plotTabs->setDocumentMode(true);
    m_plotTabs->setExpanding(false);
    for (const QString& name : {tr("Time per stage"), tr("Energy"), tr("Penetration"), tr("Joint error")})
        m_plotTabs->addTab(name);
    m_plot->setObjectName(QStringLiteral("profilerPlot"));
    // The plot last looked at comes back in the next session, as dock layouts do.
    m_plotTabs->setCurrentIndex(std::clamp(QSettings().value(kPlotKey).toInt(), 0, m_plotTabs->count() - 1));
    m_plot->setPlot(static_cast<ProfilerPlot::Plot>(m_plotTabs->currentIndex()));
    connect(m_plotTabs, &QTabBar::currentChanged, m_plot, [this](int index) {
        m_plot->setPlot(static_cast<ProfilerPlot::Plot>(index));
        QSettings().setValue(kPlotKey, index);
    });
    auto* plotColumn = new QVBoxLayout;
    plotColumn->setSpacing(2);
    plotColumn->addWidget(m_plotTabs);
    plotColumn->addWidget(m_plot, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addLayout(plotColumn, 1);
    auto* form = new QFormLayout(m_figures);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_figures->setMinimumWidth(300);  // room for seven-digit energies
    layout->addWidget(m_figures);

    addFigure(QStringLiteral("msPerStep"), tr("Time per step"));
    addFigure(QStringLiteral("awakeBodies"), tr("Bodies awake"));
    addFigure(QStringLiteral("contacts"), tr("Pairs / manifolds / points"));
    addFigure(QStringLiteral("islands"), tr("Islands"));
    addFigure(QStringLiteral("kineticEnergy"), tr("Kinetic energy"));
    addFigure(QStringLiteral("potentialEnergy"), tr("Potential energy"));
    addFigure(QStringLiteral("energyChange"), tr("Energy change"));
    addFigure(QStringLiteral("maxPenetration"), tr("Max penetration"));
    addFigure(QStringLiteral("skippedStages"), tr("Stages skipped"))->setWordWrap(true);

    connect(simulation, &SimulationController::stepped, this, &ProfilerPanel::refresh);
    // Edits and timeline frames change the running world between steps: its energies with them.
    connect(simulation, &SimulationController::bodiesEdited, this, &ProfilerPanel::refresh);
    connect(simulation, &SimulationController::posesEdited, this, &ProfilerPanel::refresh);
    connect(simulation, &SimulationController::timelineChanged, this, &ProfilerPanel::refresh);
    connect(simulation, &SimulationController::worldRebuilt, this, &ProfilerPanel::refresh);
    refresh();
}

QLabel* ProfilerPanel::addFigure(const QString& key, const QString& label) {
    auto* value = new QLabel(m_figures);
    value->setObjectName(key);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    static_cast<QFormLayout*>(m_figures->layout())->addRow(label, value);
    return value;
}

QString ProfilerPanel::figure(const QString& key) const {
    const auto* label = m_figures->findChild<QLabel*>(key);
    return label ? label->text() : QString();
}

void ProfilerPanel::refresh() {
    const auto set = [this](const char* key, const QString& text) {
        if (auto* label = m_figures->findChild<QLabel*>(QLatin1String(key))) label->setText(text);
    };
    const simcore::World* world = m_simulation->world();
    if (!world) return;
    const simcore::StepProfile& profile = world->lastStepProfile();
    const simcore::StepCounters& c = profile.counters;
    const double kinetic = world->kineticEnergy(), potential = world->potentialEnergy();
    // Edits before the first step build the scene the run starts from: the change counts from it.
    if (world->stepCount() == 0) m_initialEnergy = kinetic + potential;
    set("msPerStep", world->stepCount() == 0 ? tr("–") : tr("%1 ms").arg(profile.totalMs, 0, 'f', 3));
    const SimulationController::AwakeCount bodies = m_simulation->awakeCount();
    set("awakeBodies", tr("%1 of %2 dynamic").arg(bodies.awake).arg(bodies.dynamic));
    set("contacts", tr("%1 / %2 / %3").arg(c.pairs).arg(c.manifolds).arg(c.contactPoints));
    set("islands", QString::number(c.islands));
    set("kineticEnergy", tr("%1 J").arg(kinetic, 0, 'f', 3));
    set("potentialEnergy", tr("%1 J").arg(potential, 0, 'f', 3));
    set("energyChange", tr("%1 J").arg(kinetic + potential - m_initialEnergy, 0, 'f', 3));
    set("maxPenetration", tr("%1 mm").arg(profile.maxPenetration * 1000.0f, 0, 'f', 2));

    // The names in the row, each with its reason in the tooltip (a reason is a sentence).
    QStringList skipped, reasons;
    for (const simcore::StageInfo& info : simcore::kStages) {
        const simcore::StageSkip skip = profile.skipped[static_cast<std::size_t>(info.stage)];
        if (skip == simcore::StageSkip::Ran) continue;
        const std::string_view reason = simcore::stageSkipReason(skip);
        skipped << QString::fromLatin1(info.name.data(), static_cast<qsizetype>(info.name.size()));
        reasons << skipped.back() + QStringLiteral(": ") +
                       QString::fromLatin1(reason.data(), static_cast<qsizetype>(reason.size()));
    }
    set("skippedStages", world->stepCount() == 0 ? tr("–") : skipped.isEmpty() ? tr("none") : skipped.join(QStringLiteral(", ")));
    if (auto* label = m_figures->findChild<QLabel*>(QStringLiteral("skippedStages"))) label->setToolTip(reasons.join('\n'));
}

}  // namespace interplay
