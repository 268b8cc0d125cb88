#include "app/panels/live_state_panel.h"

#include "app/document/scene_document.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include <QEvent>
#include <QFormLayout>
#include <QHelpEvent>
#include <QLabel>
#include <QScrollArea>
#include <QToolTip>
#include <QVBoxLayout>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace interplay {
namespace {

QString vectorText(const simcore::Vec3& v, int decimals = 3) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x, 0, 'f', decimals).arg(v.y, 0, 'f', decimals).arg(v.z, 0, 'f', decimals);
}

// Axis and angle read more easily than a quaternion's components.
QString orientationText(const simcore::Quat& q) {
    const float angle = glm::angle(q);
    if (angle < 1e-6f) return LiveStatePanel::tr("none (identity)");
    return LiveStatePanel::tr("%1° about %2").arg(glm::degrees(angle), 0, 'f', 2).arg(vectorText(glm::axis(q), 3));
}

}  // namespace

LiveStatePanel::LiveStatePanel(SceneDocument* document, SimulationController* simulation, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_simulation(simulation),
      m_heading(new QLabel),
      m_empty(new QLabel(tr("Select bodies to see their simulated state."))),
      m_rows(new QWidget) {
    setObjectName(QStringLiteral("liveStatePanel"));
    // A tint of its own, so simulated figures are never mistaken for the Inspector's authored ones.
    setAutoFillBackground(true);
    QPalette tinted = palette();
    tinted.setColor(QPalette::Window, tinted.color(QPalette::Window).darker(108));
    tinted.setColor(QPalette::WindowText, QColor(20, 70, 130));
    setPalette(tinted);

    m_heading->setObjectName(QStringLiteral("liveStateHeading"));
    m_heading->setTextFormat(Qt::RichText);
    m_heading->setText(tr("<b>Simulated</b> <i>(live state, not the authored values)</i>"));
    m_heading->setWordWrap(true);
    m_empty->setWordWrap(true);

    auto* rows = new QFormLayout(m_rows);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    addRow(QStringLiteral("time"), tr("Time (s)"));
    addRow(QStringLiteral("name"), tr("Body"));
    addRow(QStringLiteral("position"), tr("Position (m)"));
    addRow(QStringLiteral("orientation"), tr("Orientation"));
    addRow(QStringLiteral("linearVelocity"), tr("Velocity (m/s)"));
    addRow(QStringLiteral("speed"), tr("Speed (m/s)"));
    addRow(QStringLiteral("angularVelocity"), tr("Angular velocity (rad/s)"));
    addRow(QStringLiteral("kineticEnergy"), tr("Kinetic energy (J)"));
    addRow(QStringLiteral("momentum"), tr("Momentum (kg m/s)"));
    addRow(QStringLiteral("contacts"), tr("Contacts"));
    addRow(QStringLiteral("contactForce"), tr("Contact force (N)"));
    addRow(QStringLiteral("state"), tr("State"));

    // In a scroll area, so rows appearing with a selection never resize the dock (and with it
    // the viewport under the cursor).
    auto* content = new QWidget;
    auto* contentLayout = new QVBoxLayout(content);
    contentLayout->addWidget(m_heading);
    contentLayout->addWidget(m_empty);
    contentLayout->addWidget(m_rows);
    contentLayout->addStretch(1);
    auto* scroll = new QScrollArea;
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setWidget(content);
    scroll->viewport()->setAutoFillBackground(false);
    content->setAutoFillBackground(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    // Playback runs at the display's rate; the figures need not (and the text would only flicker).
    m_refreshTimer.setSingleShot(true);
    connect(&m_refreshTimer, &QTimer::timeout, this, &LiveStatePanel::refresh);
    connect(m_simulation, &SimulationController::stepped, this, &LiveStatePanel::scheduleRefresh);
    connect(m_simulation, &SimulationController::posesEdited, this, &LiveStatePanel::scheduleRefresh);
    connect(m_simulation, &SimulationController::bodiesEdited, this, &LiveStatePanel::scheduleRefresh);
    connect(m_simulation, &SimulationController::worldRebuilt, this, &LiveStatePanel::refresh);
    connect(m_document, &SceneDocument::selectionChanged, this, &LiveStatePanel::refresh);
    refresh();
}

QLabel* LiveStatePanel::addRow(const QString& key, const QString& label) {
    auto* value = new QLabel;
    value->setObjectName(key);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    static_cast<QFormLayout*>(m_rows->layout())->addRow(label, value);
    return value;
}

QString LiveStatePanel::figure(const QString& key) const {
    const auto* label = m_rows->findChild<QLabel*>(key);
    return label ? label->text() : QString();
}

void LiveStatePanel::scheduleRefresh() {
    // At once when the last refresh is old enough (a step or a scrub after a pause shows at once),
    // else once the interval is up: never more than kRefreshHz a second.
    constexpr qint64 interval = 1000 / kRefreshHz;  // ms
    if (!m_lastRefresh.isValid() || m_lastRefresh.elapsed() >= interval) {
        refresh();
        return;
    }
    // Playing, a later batch of steps refreshes it: as stepped() comes the world is free, while a
    // timer could fire with a step in flight and wait for it.
    if (m_simulation->isPlaying()) return;
    if (!m_refreshTimer.isActive()) m_refreshTimer.start(int(interval - m_lastRefresh.elapsed()));
}

LiveState LiveStatePanel::measure() const {
    LiveState state;
    const simcore::World* world = m_simulation->world();
    if (!world) return state;
    state.time = world->simulatedTime();
    const auto& ids = m_simulation->bodyIds();
    for (const int index : m_document->selectedBodies()) {
        if (index < 0 || index >= static_cast<int>(ids.size())) continue;
        const simcore::BodyId id = ids[static_cast<std::size_t>(index)];
        if (!world->contains(id)) continue;
        ++state.bodies;
        state.name = QString::fromStdString(world->name(id));
        state.position = world->position(id);
        state.orientation = world->orientation(id);
        state.linearVelocity = world->linearVelocity(id);
        state.angularVelocity = world->angularVelocity(id);
        state.awake = world->isAwake(id);
        state.kineticEnergy += world->kineticEnergy(id);
        if (world->motionType(id) == simcore::MotionType::Dynamic) state.linearMomentum += world->mass(id) * state.linearVelocity;
        const simcore::ContactLoad load = world->contactLoad(id);
        state.contacts += load.contacts;
        state.contactForce += load.normalForce;
    }
    return state;
}

void LiveStatePanel::refresh() {
    m_refreshTimer.stop();
    m_lastRefresh.start();
    m_shown = measure();
    const LiveState& s = m_shown;
    const bool one = s.bodies == 1;
    m_empty->setVisible(s.bodies == 0);
    m_rows->setVisible(s.bodies > 0);
    if (s.bodies == 0) return;
    auto* form = static_cast<QFormLayout*>(m_rows->layout());
    const auto set = [this, form](const QString& key, const QString& text, bool visible = true) {
        auto* label = m_rows->findChild<QLabel*>(key);
        label->setText(text);
        form->setRowVisible(label, visible);
    };
    set(QStringLiteral("time"), QString::number(s.time, 'f', 4));
    set(QStringLiteral("name"), one ? s.name : tr("%1 bodies (totals)").arg(s.bodies));
    set(QStringLiteral("position"), vectorText(s.position), one);
    set(QStringLiteral("orientation"), orientationText(s.orientation), one);
    set(QStringLiteral("linearVelocity"), vectorText(s.linearVelocity), one);
    set(QStringLiteral("speed"), QString::number(glm::length(s.linearVelocity), 'f', 4), one);
    set(QStringLiteral("angularVelocity"), vectorText(s.angularVelocity), one);
    set(QStringLiteral("kineticEnergy"), QString::number(s.kineticEnergy, 'g', 6));
    set(QStringLiteral("momentum"), vectorText(s.linearMomentum));
    set(QStringLiteral("contacts"), QString::number(s.contacts));
    set(QStringLiteral("contactForce"), QString::number(s.contactForce, 'f', 3));
    set(QStringLiteral("state"), s.awake ? tr("awake") : tr("asleep"), one);
}

void LiveStatePanel::watchHover(Viewport* viewport) {
    m_viewport = viewport;
    viewport->installEventFilter(this);
}

bool LiveStatePanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_viewport || event->type() != QEvent::ToolTip) return QWidget::eventFilter(watched, event);
    auto* help = static_cast<QHelpEvent*>(event);
    const simcore::World* world = m_simulation->world();
    const auto hit = world ? m_viewport->pick(help->pos()) : std::nullopt;
    if (!hit) {
        QToolTip::hideText();
        event->ignore();
        return true;
    }
    const float speed = glm::length(world->linearVelocity(hit->body));
    QToolTip::showText(help->globalPos(),
                       tr("%1\n%2 m/s (simulated)").arg(QString::fromStdString(world->name(hit->body))).arg(speed, 0, 'f', 3),
                       m_viewport);
    return true;
}

}  // namespace interplay
