#include "app/panels/hull_points_dialog.h"

#include "app/panels/hull_points_model.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace interplay {

HullPointsDialog::HullPointsDialog(std::vector<simcore::Vec3> points, QWidget* parent)
    : QDialog(parent),
      m_model(new HullPointsModel(this)),
      m_table(new QTableView),
      m_status(new QLabel),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel)) {
    setWindowTitle(tr("Hull Points"));
    m_model->setPoints(std::move(points));
    m_table->setModel(m_model);
    m_table->setObjectName(QStringLiteral("hullPoints"));
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_status->setObjectName(QStringLiteral("hullStatus"));
    m_status->setWordWrap(true);

    auto* add = new QPushButton(tr("Add Point"));
    add->setObjectName(QStringLiteral("addPoint"));
    auto* remove = new QPushButton(tr("Remove"));
    remove->setObjectName(QStringLiteral("removePoints"));
    auto* import = new QPushButton(tr("Import…"));
    import->setObjectName(QStringLiteral("importPoints"));
    import->setToolTip(tr("Read points from a file: one \"x y z\" per line, CSV, or an OBJ's vertices"));
    connect(add, &QPushButton::clicked, this, &HullPointsDialog::addPoint);
    connect(remove, &QPushButton::clicked, this, &HullPointsDialog::removeSelectedPoints);
    connect(import, &QPushButton::clicked, this, &HullPointsDialog::chooseFileToImport);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_model, &HullPointsModel::hullChanged, this, &HullPointsDialog::showHull);

    auto* tools = new QHBoxLayout;
    tools->addWidget(add);
    tools->addWidget(remove);
    tools->addStretch();
    tools->addWidget(import);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(tools);
    layout->addWidget(m_table);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);
    resize(420, 480);
    showHull();
}

const std::vector<simcore::Vec3>& HullPointsDialog::points() const { return m_model->points(); }

bool HullPointsDialog::importFile(const QString& path) {
    const PointListResult read = readPointFile(path);
    if (!read.error.isEmpty()) {
        m_status->setText(tr("Not imported: %1").arg(read.error));
        return false;
    }
    m_model->setPoints(read.points);
    return true;
}

void HullPointsDialog::addPoint() {
    const QModelIndex current = m_table->currentIndex();
    const int row = current.isValid() ? current.row() + 1 : m_model->rowCount();
    if (!m_model->insertRows(row, 1)) return;
    m_table->setCurrentIndex(m_model->index(row, 0));
    m_table->edit(m_model->index(row, 0));
}

void HullPointsDialog::removeSelectedPoints() {
    QList<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows()) rows << index.row();
    if (rows.isEmpty() && m_table->currentIndex().isValid()) rows << m_table->currentIndex().row();
    std::sort(rows.begin(), rows.end(), std::greater<>());  // from the bottom, so rows keep their numbers
    for (int row : rows) m_model->removeRows(row, 1);
}

void HullPointsDialog::chooseFileToImport() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Hull Points"), QString(),
                                                      tr("Points (*.txt *.xyz *.csv *.obj);;All files (*)"));
    if (!path.isEmpty()) importFile(path);
}

void HullPointsDialog::showHull() {
    const auto& hull = m_model->hull();
    const bool ok = hull.hull != nullptr;
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
    m_status->setText(ok ? tr("%1 points: a hull of %2 vertices and %3 faces")
                               .arg(m_model->rowCount())
                               .arg(hull.hull->vertices().size())
                               .arg(hull.hull->faces().size())
                         : tr("%1 points: no hull (%2)").arg(m_model->rowCount()).arg(QString::fromStdString(hull.error)));
}

}  // namespace interplay
