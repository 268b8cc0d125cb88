#include "app/document/scene_tree_model.h"

#include "app/document/body_templates.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"

#include <QDataStream>
#include <QIODevice>
#include <QMimeData>
#include <QUndoStack>

#include <algorithm>

namespace interplay {
namespace {

// internalId of an index: 0 for a group row, 1 + group row for the rows under a group.
constexpr quintptr kGroupId = 0;
constexpr quintptr kBodyId = 1 + SceneTreeModel::kBodiesGroupRow;
constexpr quintptr kJointId = 1 + SceneTreeModel::kJointsGroupRow;

QString motionName(simcore::MotionType motion) {
    switch (motion) {
    case simcore::MotionType::Static: return SceneTreeModel::tr("static");
    case simcore::MotionType::Kinematic: return SceneTreeModel::tr("kinematic");
    case simcore::MotionType::Dynamic: return SceneTreeModel::tr("dynamic");
    }
    return {};
}

}  // namespace

SceneTreeModel::SceneTreeModel(SceneDocument* document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document) {
    connect(document, &SceneDocument::sceneReplaced, this, [this] {
        beginResetModel();
        endResetModel();
    });
    connect(document, &SceneDocument::bodyAboutToBeInserted, this,
            [this](int index) { beginInsertRows(bodiesGroup(), index, index); });
    connect(document, &SceneDocument::bodyInserted, this, [this] {
        endInsertRows();
        emit dataChanged(bodiesGroup(), bodiesGroup());  // the group shows the count
    });
    connect(document, &SceneDocument::bodyAboutToBeRemoved, this,
            [this](int index) { beginRemoveRows(bodiesGroup(), index, index); });
    connect(document, &SceneDocument::bodyRemoved, this, [this] {
        endRemoveRows();
        emit dataChanged(bodiesGroup(), bodiesGroup());
    });
    connect(document, &SceneDocument::bodyAboutToBeMoved, this, [this](int from, int to) {
        // Qt counts the destination in rows before the move.
        beginMoveRows(bodiesGroup(), from, from, bodiesGroup(), to > from ? to + 1 : to);
    });
    connect(document, &SceneDocument::bodyMoved, this, [this] { endMoveRows(); });
    connect(document, &SceneDocument::bodyChanged, this, [this](int index, BodyField field) {
        if (field == BodyField::Name || field == BodyField::Shape || field == BodyField::Motion) {
            emit dataChanged(indexOfBody(index, NameColumn), indexOfBody(index, ColumnCount - 1));
        }
        if (field == BodyField::Name) jointDetailsChanged();
    });
    connect(document, &SceneDocument::jointAboutToBeInserted, this,
            [this](int index) { beginInsertRows(jointsGroup(), index, index); });
    connect(document, &SceneDocument::jointInserted, this, [this] {
        endInsertRows();
        emit dataChanged(jointsGroup(), jointsGroup());
    });
    connect(document, &SceneDocument::jointAboutToBeRemoved, this,
            [this](int index) { beginRemoveRows(jointsGroup(), index, index); });
    connect(document, &SceneDocument::jointRemoved, this, [this] {
        endRemoveRows();
        emit dataChanged(jointsGroup(), jointsGroup());
    });
    connect(document, &SceneDocument::jointChanged, this, [this](int index) {
        emit dataChanged(indexOfJoint(index, NameColumn), indexOfJoint(index, ColumnCount - 1));
    });
}

QModelIndex SceneTreeModel::indexOfBody(int bodyIndex, int column) const {
    if (bodyIndex < 0 || bodyIndex >= m_document->bodyCount()) return {};
    return createIndex(bodyIndex, column, kBodyId);
}

int SceneTreeModel::bodyIndexOf(const QModelIndex& index) const {
    return index.isValid() && index.internalId() == kBodyId ? index.row() : -1;
}

QModelIndex SceneTreeModel::indexOfJoint(int jointIndex, int column) const {
    if (jointIndex < 0 || jointIndex >= m_document->jointCount()) return {};
    return createIndex(jointIndex, column, kJointId);
}

int SceneTreeModel::jointIndexOf(const QModelIndex& index) const {
    return index.isValid() && index.internalId() == kJointId ? index.row() : -1;
}

void SceneTreeModel::jointDetailsChanged() {
    if (m_document->jointCount() == 0) return;
    emit dataChanged(index(0, DetailsColumn, jointsGroup()), index(m_document->jointCount() - 1, DetailsColumn, jointsGroup()));
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (!hasIndex(row, column, parent)) return {};
    if (!parent.isValid()) return createIndex(row, column, kGroupId);
    return createIndex(row, column, 1 + static_cast<quintptr>(parent.row()));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == kGroupId) return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, kGroupId);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return 2;  // the groups
    if (parent.internalId() != kGroupId || parent.column() != 0) return 0;
    return parent.row() == kBodiesGroupRow ? m_document->bodyCount() : m_document->jointCount();
}

int SceneTreeModel::columnCount(const QModelIndex&) const {
    return ColumnCount;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    switch (index.internalId()) {
    case kGroupId:
        if (role != Qt::DisplayRole || index.column() != NameColumn) return {};
        return index.row() == kBodiesGroupRow ? tr("Bodies (%1)").arg(m_document->bodyCount())
                                              : tr("Joints (%1)").arg(m_document->jointCount());
    case kBodyId: return bodyData(index.row(), index.column(), role);
    case kJointId: return jointData(index.row(), index.column(), role);
    }
    return {};
}

QVariant SceneTreeModel::bodyData(int row, int column, int role) const {
    const simcore::BodyCreationSettings& body = m_document->body(row).body;
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        switch (column) {
        case NameColumn: return QString::fromStdString(body.name);
        case TypeColumn: return shapeDisplayName(body.shape.type);
        case DetailsColumn: return motionName(body.motion);
        }
        return {};
    case Qt::ToolTipRole:
        return tr("%1: %2, %3").arg(QString::fromStdString(body.name), shapeDisplayName(body.shape.type), motionName(body.motion));
    default: return {};
    }
}

QVariant SceneTreeModel::jointData(int row, int column, int role) const {
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    const simcore::SceneJoint& joint = m_document->joint(row);
    const QString bodies = tr("%1 – %2").arg(m_document->bodyName(static_cast<int>(joint.bodyA)),
                                             joint.bodyB ? m_document->bodyName(static_cast<int>(*joint.bodyB)) : tr("world"));
    const QString type = QString::fromLatin1(simcore::jointTypeName(joint.joint.type));
    const QString name = m_document->jointName(row);
    if (role == Qt::ToolTipRole) return tr("%1: %2 joint, %3").arg(name, type, bodies);
    switch (column) {
    case NameColumn: return name;
    case TypeColumn: return type;
    case DetailsColumn: return bodies;
    }
    return {};
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const int body = bodyIndexOf(index);
    if (body < 0 || index.column() != NameColumn || role != Qt::EditRole) return false;
    const QString name = value.toString().trimmed();
    if (name == m_document->bodyName(body)) return true;
    if (!m_document->bodyNameProblem(body, name).isEmpty()) return false;  // the view keeps the old name
    simcore::SceneBody renamed = m_document->body(body);
    renamed.body.name = name.toStdString();
    m_document->undoStack()->push(new ChangeBodies(m_document,
                                                   tr("Rename %1 to %2").arg(m_document->bodyName(body), name),
                                                   BodyField::Name, {body}, {std::move(renamed)}));
    return true;
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case NameColumn: return tr("Name");
    case TypeColumn: return tr("Type");
    case DetailsColumn: return tr("Details");
    }
    return {};
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    if (index.internalId() == kGroupId) {
        return index.row() == kBodiesGroupRow ? Qt::ItemIsEnabled | Qt::ItemIsDropEnabled : Qt::ItemIsEnabled;
    }
    if (index.internalId() == kJointId) return Qt::ItemIsEnabled | Qt::ItemIsSelectable;  // edited in the Inspector
    Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled;
    if (index.column() == NameColumn) flags |= Qt::ItemIsEditable;
    return flags;
}

QMimeData* SceneTreeModel::mimeData(const QModelIndexList& indexes) const {
    QList<int> rows;
    for (const QModelIndex& index : indexes) {
        const int body = bodyIndexOf(index);
        if (body >= 0 && !rows.contains(body)) rows << body;
    }
    std::sort(rows.begin(), rows.end());
    QByteArray encoded;
    QDataStream stream(&encoded, QIODevice::WriteOnly);
    stream << rows;
    auto* data = new QMimeData;
    data->setData(kBodyRowsMimeType, encoded);
    return data;
}

bool SceneTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int,
                                     const QModelIndex& parent) const {
    return action == Qt::MoveAction && data && data->hasFormat(kBodyRowsMimeType) &&
           (parent == bodiesGroup() || bodyIndexOf(parent) >= 0);
}

bool SceneTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                  const QModelIndex& parent) {
    if (!canDropMimeData(data, action, row, column, parent)) return false;
    QList<int> dragged;
    QDataStream stream(data->data(kBodyRowsMimeType));
    stream >> dragged;
    dragged.removeIf([this](int i) { return i < 0 || i >= m_document->bodyCount(); });
    if (dragged.isEmpty()) return false;

    // Dropped on a body: insert before it. On the group's empty space: at the end.
    int target = bodyIndexOf(parent) >= 0 ? parent.row() : row;
    if (target < 0 || target > m_document->bodyCount()) target = m_document->bodyCount();
    const int firstFinal =
        target - static_cast<int>(std::count_if(dragged.begin(), dragged.end(), [target](int i) { return i < target; }));

    // The order wanted: the other bodies as they are, the dragged ones as a block at firstFinal.
    std::vector<int> order(static_cast<std::size_t>(m_document->bodyCount()));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::vector<int> wanted;
    for (int i : order) {
        if (!dragged.contains(i)) wanted.push_back(i);
    }
    wanted.insert(wanted.begin() + firstFinal, dragged.begin(), dragged.end());
    // Reach it with single moves, fixing one position at a time from the top.
    std::vector<std::pair<int, int>> moves;  // (from, to), applied in sequence
    for (std::size_t position = 0; position < wanted.size(); ++position) {
        if (order[position] == wanted[position]) continue;
        const auto current = std::find(order.begin() + static_cast<std::ptrdiff_t>(position), order.end(), wanted[position]);
        moves.emplace_back(static_cast<int>(current - order.begin()), static_cast<int>(position));
        order.erase(current);
        order.insert(order.begin() + static_cast<std::ptrdiff_t>(position), wanted[position]);
    }
    if (moves.empty()) return true;  // dropped where they already are: nothing to undo

    QUndoStack* stack = m_document->undoStack();
    stack->beginMacro(tr("Reorder %1").arg(bodiesLabel(*m_document, dragged)));
    for (const auto& [from, to] : moves) stack->push(new ReorderBody(m_document, from, to));
    stack->endMacro();
    return true;
}

}  // namespace interplay
