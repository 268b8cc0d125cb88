#include "app/panels/timeline_bar.h"

#include "app/simulation/simulation_controller.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>

#include <algorithm>

namespace interplay {

const char* const TimelineBar::kMemoryLimitKey = "timeline/memoryLimitMiB";

TimelineBar::TimelineBar(SimulationController* simulation, QWidget* parent)
    : QWidget(parent),
      m_simulation(simulation),
      m_slider(new QSlider(Qt::Horizontal)),
      m_frame(new QLabel),
      m_held(new QLabel),
      m_record(new QCheckBox(tr("Record"))),
      m_limit(new QSpinBox) {
    m_slider->setObjectName(QStringLiteral("timelineSlider"));
    m_slider->setToolTip(tr("The recorded frames: drag to show one (pauses); , and . step through them"));
    m_slider->setFocusPolicy(Qt::NoFocus);  // arrow keys stay with the viewport's camera
    m_frame->setObjectName(QStringLiteral("timelineFrame"));
    m_held->setObjectName(QStringLiteral("timelineHeld"));
    m_held->setToolTip(tr("What the recording holds and what recording a step costs"));
    m_record->setObjectName(QStringLiteral("timelineRecord"));
    m_record->setToolTip(tr("Record every step while playing, to scrub back (off discards the recording)"));
    m_record->setChecked(simulation->isRecording());
    m_limit->setObjectName(QStringLiteral("timelineMemoryLimit"));
    m_limit->setRange(kMinLimitMiB, kMaxLimitMiB);
    m_limit->setSuffix(tr(" MiB"));
    m_limit->setToolTip(tr("The most memory the recording may take; the oldest frames go first"));

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_frame);
    layout->addWidget(m_held);
    layout->addWidget(m_record);
    layout->addWidget(new QLabel(tr("Limit")));
    layout->addWidget(m_limit);

    const int saved = QSettings().value(QLatin1String(kMemoryLimitKey), int(Timeline::kDefaultMemoryLimit / Timeline::kMiB)).toInt();
    m_limit->setValue(saved);
    setLimitMiB(m_limit->value());  // the range clamps a bad stored value
    connect(m_limit, &QSpinBox::valueChanged, this, [this](int mib) {
        setLimitMiB(mib);
        QSettings().setValue(QLatin1String(kMemoryLimitKey), mib);
    });
    connect(m_record, &QCheckBox::toggled, m_simulation, &SimulationController::setRecording);
    connect(m_slider, &QSlider::valueChanged, this, [this](int frame) {
        if (!m_refreshing) m_simulation->showFrame(frame);
    });
    connect(m_simulation, &SimulationController::timelineChanged, this, &TimelineBar::refresh);
    refresh();
}

void TimelineBar::setLimitMiB(int mib) {
    m_simulation->setRecordingMemoryLimit(static_cast<std::size_t>(mib) * Timeline::kMiB);
}

void TimelineBar::refresh() {
    const Timeline& timeline = m_simulation->timeline();
    const int frames = static_cast<int>(timeline.frameCount());
    const int current = m_simulation->currentFrame();
    m_refreshing = true;
    m_slider->setEnabled(frames > 1);
    m_slider->setRange(0, std::max(0, frames - 1));
    m_slider->setValue(std::max(0, current));
    m_refreshing = false;
    if (current >= 0)
        m_frame->setText(tr("frame %1 of %2, t = %3 s").arg(current + 1).arg(frames).arg(timeline.timeOf(std::size_t(current)), 0, 'f', 3));
    else
        m_frame->setText(tr("nothing recorded"));
    m_held->setText(tr("%1 frames, %2 s, %3 MiB; %4 ms/step")
                        .arg(frames)
                        .arg(timeline.secondsCovered(), 0, 'f', 2)
                        .arg(double(timeline.bytesUsed()) / double(Timeline::kMiB), 0, 'f', 1)
                        .arg(m_simulation->recordingMs(), 0, 'f', 3));
}

}  // namespace interplay
