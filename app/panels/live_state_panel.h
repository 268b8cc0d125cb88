#pragma once
// The Live State dock: what the simulation has made of the selected bodies, set apart from the
// Inspector's authored values by its heading and tint. One body: its simulated pose, linear and
// angular velocity, kinetic energy, its touching contacts and the normal force they carry; several:
// their totals. It follows playback at most kRefreshHz times a second, and a scrubbed frame.
// It also answers tooltips over the viewport with the body under the cursor, its name and speed.

#include "simcore/world/world.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <optional>

class QLabel;

namespace interplay {

class SceneDocument;
class SimulationController;
class Viewport;

// The figures the panel shows, for the selection as the running world has it now.
struct LiveState {
    int bodies = 0;  // selected bodies that are in the running world
    // One body (bodies == 1):
    QString name;
    simcore::Vec3 position{0.0f};  // m
    simcore::Quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    simcore::Vec3 linearVelocity{0.0f};   // m/s
    simcore::Vec3 angularVelocity{0.0f};  // rad/s
    bool awake = false;
    // Summed over the bodies:
    double kineticEnergy = 0.0;        // J
    simcore::Vec3 linearMomentum{0.0f};  // kg m/s
    int contacts = 0;                  // touching manifolds (a pair of selected bodies counts twice)
    float contactForce = 0.0f;         // N, their normal force
    double time = 0.0;                 // s of simulated time
};

class LiveStatePanel : public QWidget {
    Q_OBJECT

public:
    static constexpr int kRefreshHz = 10;

    LiveStatePanel(SceneDocument* document, SimulationController* simulation, QWidget* parent = nullptr);

    // Shows a tooltip with the name and speed of the body under the cursor in `viewport`.
    void watchHover(Viewport* viewport);
    // The figures on show (refreshed at most kRefreshHz times a second), for tests.
    const LiveState& shown() const { return m_shown; }
    // The text of a row by key ("position", "speed", "kineticEnergy", "contacts", ...), for tests.
    QString figure(const QString& key) const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    LiveState measure() const;
    void refresh();
    void scheduleRefresh();
    QLabel* addRow(const QString& key, const QString& label);

    SceneDocument* m_document;
    SimulationController* m_simulation;
    Viewport* m_viewport = nullptr;
    QTimer m_refreshTimer;
    QElapsedTimer m_lastRefresh;
    QLabel* m_heading;
    QLabel* m_empty;
    QWidget* m_rows;
    LiveState m_shown;
};

}  // namespace interplay
