#pragma once
// The scene as a tree for the Scene dock: a group row per kind of object, "Bodies" and "Joints",
// the objects under it in scene order. Bodies can be renamed (setData) and dragged to a new place
// (dropMimeData), both as undo commands on the document; joints are listed with the bodies they
// join, and can be selected (the Inspector edits them). The model follows the document's signals,
// so undo and redo update it the same way as the original edit.

#include <QAbstractItemModel>

namespace interplay {

class SceneDocument;

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    // Type: a body's shape or a joint's kind. Details: a body's motion, or the bodies a joint joins.
    enum Column { NameColumn, TypeColumn, DetailsColumn, ColumnCount };
    static constexpr int kBodiesGroupRow = 0;
    static constexpr int kJointsGroupRow = 1;
    static inline const QString kBodyRowsMimeType = QStringLiteral("application/x-interplay-body-rows");

    explicit SceneTreeModel(SceneDocument* document, QObject* parent = nullptr);

    // The index of body `bodyIndex` (column 0), and back; -1 for anything that is not a body.
    QModelIndex indexOfBody(int bodyIndex, int column = NameColumn) const;
    int bodyIndexOf(const QModelIndex& index) const;
    // The same for joints.
    QModelIndex indexOfJoint(int jointIndex, int column = NameColumn) const;
    int jointIndexOf(const QModelIndex& index) const;
    QModelIndex bodiesGroup() const { return index(kBodiesGroupRow, 0); }
    QModelIndex jointsGroup() const { return index(kJointsGroupRow, 0); }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override { return {kBodyRowsMimeType}; }
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    // Moves the dragged bodies (in their order) to `row` under the Bodies group, one undoable
    // "Reorder" per body grouped in one macro.
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

private:
    QVariant bodyData(int body, int column, int role) const;
    QVariant jointData(int joint, int column, int role) const;
    void jointDetailsChanged();  // a body a joint names was renamed

    SceneDocument* m_document;
};

}  // namespace interplay
