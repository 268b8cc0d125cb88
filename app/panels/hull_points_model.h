#pragma once
// The points a convex hull is built from, as an editable table (x, y, z in metres, the body's
// frame), and the reader of a file of points the Inspector's hull editor imports. Model layer: Qt
// Core only, no widgets.

#include "simcore/math/math.h"
#include "simcore/shapes/convex_hull.h"

#include <QAbstractTableModel>
#include <QString>

#include <memory>
#include <vector>

namespace interplay {

struct PointListResult {
    std::vector<simcore::Vec3> points;
    QString error;  // empty on success; names the line and what is wrong with it
};

// Reads one point per line: three numbers separated by spaces, tabs, commas or semicolons (a
// spreadsheet's CSV, a plain x y z list), or an OBJ file's "v x y z" vertex lines (its other lines
// are skipped). Blank lines and lines starting with '#' are skipped. Fails on a line that is not
// a point, a number that is not finite or outside the scene format's coordinate range, or more
// points than a hull may have.
PointListResult parsePointList(const QString& text);
// The same for a file, with a size cap so a wrong file choice cannot stall the editor.
PointListResult readPointFile(const QString& path);

class HullPointsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit HullPointsModel(QObject* parent = nullptr);

    const std::vector<simcore::Vec3>& points() const { return m_points; }
    void setPoints(std::vector<simcore::Vec3> points);
    // The hull these points give, or why they give none (fewer than four, coplanar, ...).
    const simcore::ConvexHull::BuildResult& hull() const { return m_hull; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    // New rows copy the point above them (or the origin), so the hull keeps its volume.
    bool insertRows(int row, int count, const QModelIndex& parent = {}) override;
    bool removeRows(int row, int count, const QModelIndex& parent = {}) override;

signals:
    void hullChanged();

private:
    void rebuildHull();

    std::vector<simcore::Vec3> m_points;
    simcore::ConvexHull::BuildResult m_hull;
};

}  // namespace interplay
