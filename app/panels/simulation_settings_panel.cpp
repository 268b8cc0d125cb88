#include "app/panels/simulation_settings_panel.h"

#include "app/panels/simulation_settings_model.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/debug_draw_options.h"

#include <QLabel>
#include <QQmlContext>
#include <QQuickWidget>
#include <QVBoxLayout>

namespace interplay {

const char* const SimulationSettingsPanel::kSource = "qrc:/qml/SimulationSettings.qml";

SimulationSettingsPanel::SimulationSettingsPanel(SimulationSettingsModel* settings, SimulationController* simulation,
                                                 DebugDrawOptions* debugDraw, QWidget* parent)
    : QWidget(parent), m_quickWidget(new QQuickWidget(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_quickWidget);

    QQmlContext* context = m_quickWidget->rootContext();
    context->setContextProperty(QStringLiteral("settingsModel"), settings);
    context->setContextProperty(QStringLiteral("simulation"), simulation);
    context->setContextProperty(QStringLiteral("debugDraw"), debugDraw);
    m_quickWidget->setResizeMode(QQuickWidget::SizeRootObjectToView);
    m_quickWidget->setMinimumSize(240, 200);
    m_quickWidget->setSource(QUrl(QString::fromLatin1(kSource)));

    if (m_quickWidget->status() == QQuickWidget::Error) {
        // Say so in the panel rather than leave it blank; the details go to the log as well.
        QStringList lines;
        for (const QQmlError& error : m_quickWidget->errors()) {
            qWarning("Simulation settings panel: %s", qPrintable(error.toString()));
            lines << error.toString();
        }
        auto* message = new QLabel(tr("The settings panel could not be loaded:\n%1").arg(lines.join(u'\n')), this);
        message->setWordWrap(true);
        layout->addWidget(message);
    }
}

QList<QQmlError> SimulationSettingsPanel::errors() const {
    return m_quickWidget->errors();
}

}  // namespace interplay
