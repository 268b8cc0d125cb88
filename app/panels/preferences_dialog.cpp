#include "app/panels/preferences_dialog.h"

#include "app/viewport/gizmo_tool.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSettings>
#include <QVBoxLayout>

namespace interplay {
namespace {

// A field for the step stored under `key`, which it stores again on every change. The range keeps
// a step one can see on screen and still snap with: 1 mm to 100 m, 0.1° to 180°.
QDoubleSpinBox* stepField(const char* key, double fallback, double min, double max, int decimals, const QString& suffix) {
    auto* field = new QDoubleSpinBox;
    field->setRange(min, max);
    field->setDecimals(decimals);
    field->setSuffix(suffix);
    field->setValue(preferredGizmoStep(key, fallback));
    // Typed digits are stored once the value is complete (Enter, Tab or leaving the field), the
    // arrows at once.
    field->setKeyboardTracking(false);
    QObject::connect(field, &QDoubleSpinBox::valueChanged, field,
                     [key](double value) { QSettings().setValue(QLatin1String(key), value); });
    return field;
}

}  // namespace

PreferencesDialog::PreferencesDialog(QWidget* parent)
    : QDialog(parent),
      m_gridStep(stepField(kGizmoGridStepKey, kDefaultGizmoGridStep, 0.001, 100.0, 3, tr(" m"))),
      m_angleStep(stepField(kGizmoAngleStepKey, kDefaultGizmoAngleStep, 0.1, 180.0, 1, tr("°"))) {
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    m_gridStep->setObjectName(QStringLiteral("gridStepField"));
    m_angleStep->setObjectName(QStringLiteral("angleStepField"));
    m_gridStep->setToolTip(tr("How far a gizmo drag moves between snaps (with Snap on, or Ctrl held)"));
    m_angleStep->setToolTip(tr("How far a gizmo ring turns between snaps (with Snap on, or Ctrl held)"));

    auto* form = new QFormLayout;
    form->addRow(tr("Gizmo &grid step:"), m_gridStep);
    form->addRow(tr("Gizmo &angle step:"), m_angleStep);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

}  // namespace interplay
