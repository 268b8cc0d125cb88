#pragma once
// The Inspector's editor of a convex hull's points: a table to edit, add and remove points, and
// Import... to read them from a file of points (x y z lines, CSV or an OBJ's vertices). The hull
// the points give is rebuilt as they change and OK stays off until they give one.

#include "simcore/math/math.h"

#include <QDialog>

#include <vector>

class QDialogButtonBox;
class QLabel;
class QTableView;

namespace interplay {

class HullPointsModel;

class HullPointsDialog : public QDialog {
    Q_OBJECT
public:
    explicit HullPointsDialog(std::vector<simcore::Vec3> points, QWidget* parent = nullptr);

    const std::vector<simcore::Vec3>& points() const;
    HullPointsModel* model() const { return m_model; }
    // Reads a file of points into the table, replacing its rows (the import button's work, after
    // its file dialog). Returns false and shows why when the file is refused; the table is then
    // unchanged.
    bool importFile(const QString& path);

private:
    void addPoint();
    void removeSelectedPoints();
    void chooseFileToImport();
    void showHull();

    HullPointsModel* m_model;
    QTableView* m_table;
    QLabel* m_status;
    QDialogButtonBox* m_buttons;
};

}  // namespace interplay
