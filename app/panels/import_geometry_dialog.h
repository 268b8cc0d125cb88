#pragma once
// File → Import Geometry…'s dialog (and a dropped mesh file's): what the file will become, with its
// scale and up axis, and a preview of what that gives - triangle and vertex counts and the bounds
// in metres after scale, or the importer's message (then OK stays off). Re-reads the file as the
// options change, so the numbers shown are the ones the scene will get.

#include "app/document/geometry_import.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;

namespace interplay {

class ImportGeometryDialog : public QDialog {
    Q_OBJECT
public:
    explicit ImportGeometryDialog(const QString& path, QWidget* parent = nullptr);

    QString path() const { return m_path; }
    GeometryImportKind kind() const;
    simcore::MeshImportOptions options() const;
    const GeometryPreview& preview() const { return m_preview; }

private:
    void updatePreview();

    QString m_path;
    GeometryPreview m_preview;
    QComboBox* m_kind;
    QDoubleSpinBox* m_scale[3];
    QComboBox* m_upAxis;
    QLabel* m_summary;
    QLabel* m_kindNote;
    QDialogButtonBox* m_buttons;
};

}  // namespace interplay
