#pragma once
// The bar under the viewport that scrubs the recorded run (SimulationController's timeline): a
// slider over the frames held (dragging it pauses and shows that frame), the frame shown and its
// time, what the recording holds (frames, seconds, MiB of the limit) and costs (ms per step), a
// Record toggle and the memory limit, a preference kept in QSettings.

#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace interplay {

class SimulationController;

class TimelineBar : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMinLimitMiB = 1;
    static constexpr int kMaxLimitMiB = 64 * 1024;
    static const char* const kMemoryLimitKey;  // QSettings key, in MiB

    explicit TimelineBar(SimulationController* simulation, QWidget* parent = nullptr);

    QSlider* slider() const { return m_slider; }
    QSpinBox* memoryLimit() const { return m_limit; }
    QCheckBox* recordToggle() const { return m_record; }

private:
    void refresh();
    void setLimitMiB(int mib);

    SimulationController* m_simulation;
    QSlider* m_slider;
    QLabel* m_frame;
    QLabel* m_held;
    QCheckBox* m_record;
    QSpinBox* m_limit;
    bool m_refreshing = false;  // the slider moved by refresh(), not by the user
};

}  // namespace interplay
