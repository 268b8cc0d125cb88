#pragma once
// Edit → Preferences: the editor's own settings, kept in QSettings rather than in a scene. For now
// the transform gizmo's snapping steps (gizmo_tool.h), each stored as soon as it is changed, so the
// next drag snaps to it.

#include <QDialog>

class QDoubleSpinBox;

namespace interplay {

class PreferencesDialog : public QDialog {
    Q_OBJECT

public:
    explicit PreferencesDialog(QWidget* parent = nullptr);

    QDoubleSpinBox* gridStepField() const { return m_gridStep; }
    QDoubleSpinBox* angleStepField() const { return m_angleStep; }

private:
    QDoubleSpinBox* m_gridStep;
    QDoubleSpinBox* m_angleStep;
};

}  // namespace interplay
