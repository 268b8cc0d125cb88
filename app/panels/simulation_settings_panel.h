#pragma once
// The Simulation settings dock's contents: qml/SimulationSettings.qml in a QQuickWidget, with the
// settings model, the simulation controller and the debug-draw options as context properties
// (set before the QML loads, so no binding ever sees them missing).

#include <QList>
#include <QQmlError>
#include <QWidget>

class QQuickWidget;

namespace interplay {

class DebugDrawOptions;
class SimulationController;
class SimulationSettingsModel;

class SimulationSettingsPanel : public QWidget {
    Q_OBJECT

public:
    SimulationSettingsPanel(SimulationSettingsModel* settings, SimulationController* simulation,
                            DebugDrawOptions* debugDraw, QWidget* parent = nullptr);

    QQuickWidget* quickWidget() const { return m_quickWidget; }
    // Errors from loading the QML (empty when it loaded).
    QList<QQmlError> errors() const;

    static const char* const kSource;

private:
    QQuickWidget* m_quickWidget;
};

}  // namespace interplay
