#pragma once
// A compound's children as an editable table for the Inspector: the child's shape type, its size
// (the numbers of its type: half extents, radius, radius and half height), its position (m) and its
// orientation as Euler angles (degrees), all in the body frame. The model keeps a copy of the
// children; an accepted edit changes it and emits childrenEdited, after which the Inspector pushes
// one undo command with the new children (and resets the model from the document either way).
// Model layer: Qt Core only, no widgets.

#include "simcore/shapes/compound_shape.h"

#include <QAbstractTableModel>
#include <QString>

#include <vector>

namespace interplay {

// An orientation as the Inspector shows it: Euler angles in degrees (GLM's x, y, z order), and back.
simcore::Vec3 eulerDegrees(const simcore::Quat& q);
simcore::Quat fromEulerDegrees(const simcore::Vec3& degrees);

class CompoundChildrenModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { ShapeColumn, SizeColumn, X, Y, Z, AngleX, AngleY, AngleZ, ColumnCount };

    explicit CompoundChildrenModel(QObject* parent = nullptr);

    const std::vector<simcore::CompoundChild>& children() const { return m_children; }
    void setChildren(std::vector<simcore::CompoundChild> children);

    // Appends a child of a convex type (its editor template) at the body's origin; removes one
    // (never the last: a compound has at least one child). Each emits childrenEdited.
    void addChild(simcore::ShapeType type);
    void removeChild(int row);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    // Numbers as the user types them; the size column takes the type's numbers separated by spaces
    // or commas. A value out of the scene format's range is refused (refused says why).
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

signals:
    void childrenEdited(const QString& what);  // what changed, for the undo entry's text
    void refused(const QString& message);

private:
    std::vector<simcore::CompoundChild> m_children;
};

}  // namespace interplay
