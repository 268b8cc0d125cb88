#include "app/panels/import_geometry_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace interplay {

ImportGeometryDialog::ImportGeometryDialog(const QString& path, QWidget* parent)
    : QDialog(parent), m_path(path), m_kind(new QComboBox), m_upAxis(new QComboBox), m_summary(new QLabel),
      m_kindNote(new QLabel), m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel)) {
    setObjectName(QStringLiteral("importGeometryDialog"));
    setWindowTitle(tr("Import Geometry"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    auto* file = new QLabel(QFileInfo(path).fileName());
    file->setToolTip(path);
    form->addRow(tr("File"), file);

    m_kind->setObjectName(QStringLiteral("importKind"));
    m_kind->addItem(tr("Static mesh, triangles stored in the scene"), int(GeometryImportKind::MeshInScene));
    m_kind->addItem(tr("Static mesh, the scene refers to this file"), int(GeometryImportKind::MeshFileReference));
    m_kind->addItem(tr("Dynamic body, convex hull of the points"), int(GeometryImportKind::ConvexHull));
    form->addRow(tr("Make"), m_kind);

    auto* scaleRow = new QHBoxLayout;
    const char* axes[] = {"scaleX", "scaleY", "scaleZ"};
    for (int k = 0; k < 3; ++k) {
        m_scale[k] = new QDoubleSpinBox;
        m_scale[k]->setObjectName(QString::fromLatin1(axes[k]));
        // The scene format's range for a file mesh's scale; a negative factor mirrors.
        m_scale[k]->setRange(-1e5, 1e5);
        m_scale[k]->setDecimals(4);
        m_scale[k]->setValue(1.0);
        scaleRow->addWidget(m_scale[k]);
        connect(m_scale[k], &QDoubleSpinBox::valueChanged, this, &ImportGeometryDialog::updatePreview);
    }
    form->addRow(tr("Scale x, y, z"), scaleRow);
    m_upAxis->setObjectName(QStringLiteral("upAxis"));
    m_upAxis->addItem(tr("Y up (glTF, most game tools)"), int(simcore::UpAxis::Y));
    m_upAxis->addItem(tr("Z up (CAD, most STL, Blender without conversion)"), int(simcore::UpAxis::Z));
    m_upAxis->addItem(tr("X up"), int(simcore::UpAxis::X));
    form->addRow(tr("The file's up axis"), m_upAxis);
    layout->addLayout(form);

    m_summary->setObjectName(QStringLiteral("importPreview"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);
    m_kindNote->setObjectName(QStringLiteral("importKindNote"));
    m_kindNote->setWordWrap(true);
    layout->addWidget(m_kindNote);
    auto* compoundNote = new QLabel(tr("A compound of convex pieces is not offered: it needs a convex decomposition "
                                       "library, and Debian packages none for C++."));
    compoundNote->setWordWrap(true);
    compoundNote->setEnabled(false);  // greyed: a remark, not a choice
    layout->addWidget(compoundNote);
    layout->addWidget(m_buttons);
    // Word-wrapped texts change as the options do: room for the longest (the importer's messages
    // and the notes run to three lines), so the dialog does not jump or clip them.
    for (QLabel* label : {m_summary, m_kindNote}) label->setMinimumHeight(3 * label->fontMetrics().lineSpacing());
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ImportGeometryDialog::updatePreview);
    connect(m_upAxis, &QComboBox::currentIndexChanged, this, &ImportGeometryDialog::updatePreview);
    setMinimumWidth(520);
    updatePreview();
}

GeometryImportKind ImportGeometryDialog::kind() const { return GeometryImportKind(m_kind->currentData().toInt()); }

simcore::MeshImportOptions ImportGeometryDialog::options() const {
    simcore::MeshImportOptions options;
    for (int k = 0; k < 3; ++k) options.scale[k] = float(m_scale[k]->value());
    options.upAxis = simcore::UpAxis(m_upAxis->currentData().toInt());
    return options;
}

void ImportGeometryDialog::updatePreview() {
    m_preview = previewGeometry(m_path, options());
    m_summary->setText(m_preview.summary());
    QString note;
    bool possible = m_preview.error.isEmpty();
    switch (kind()) {
        case GeometryImportKind::MeshInScene:
            note = tr("A static body; the scene file holds every triangle.");
            break;
        case GeometryImportKind::MeshFileReference:
            note = tr("A static body; the scene file keeps a path to this file (relative to the scene's folder once saved), "
                      "with this scale and up axis.");
            break;
        case GeometryImportKind::ConvexHull:
            possible = possible && m_preview.hullCorners > 0;
            note = m_preview.hullCorners > 0 ? tr("A dynamic body of density 1000 kg/m³: the hull has %1 corners.").arg(m_preview.hullCorners)
                                             : tr("No convex hull: %1").arg(m_preview.hullError);
            break;
    }
    m_kindNote->setText(note);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(possible);
}

}  // namespace interplay
