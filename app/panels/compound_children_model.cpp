#include "app/panels/compound_children_model.h"

#include "app/document/body_templates.h"
#include "simcore/settings_schema.h"
#include "simcore/shapes/convex_hull.h"

#include <QRegularExpression>
#include <QStringList>

#include <cmath>

namespace interplay {

namespace {

constexpr double kMaxAngle = 360.0;  // degrees, as the Inspector's body orientation

// The numbers the size column shows and takes for a child of `type`, and what they are.
int sizeCount(simcore::ShapeType type) {
    switch (type) {
        case simcore::ShapeType::Box: return 3;
        case simcore::ShapeType::Sphere: return 1;
        case simcore::ShapeType::Capsule:
        case simcore::ShapeType::Cylinder: return 2;
        default: return 0;  // a hull's size is its points (not edited here)
    }
}

QString sizeMeaning(simcore::ShapeType type) {
    switch (type) {
        case simcore::ShapeType::Box: return CompoundChildrenModel::tr("half extents x, y, z (m)");
        case simcore::ShapeType::Sphere: return CompoundChildrenModel::tr("radius (m)");
        case simcore::ShapeType::Capsule:
        case simcore::ShapeType::Cylinder: return CompoundChildrenModel::tr("radius, half height (m)");
        default: return CompoundChildrenModel::tr("the hull's points (edit them on a hull body)");
    }
}

std::vector<float> sizeOf(const simcore::Shape& shape) {
    switch (shape.type) {
        case simcore::ShapeType::Box: return {shape.halfExtents.x, shape.halfExtents.y, shape.halfExtents.z};
        case simcore::ShapeType::Sphere: return {shape.radius};
        case simcore::ShapeType::Capsule:
        case simcore::ShapeType::Cylinder: return {shape.radius, shape.halfHeight};
        default: return {};
    }
}

void setSize(simcore::Shape& shape, const std::vector<float>& size) {
    switch (shape.type) {
        case simcore::ShapeType::Box: shape.halfExtents = {size[0], size[1], size[2]}; break;
        case simcore::ShapeType::Sphere: shape.radius = size[0]; break;
        case simcore::ShapeType::Capsule:
        case simcore::ShapeType::Cylinder:
            shape.radius = size[0];
            shape.halfHeight = size[1];
            break;
        default: break;
    }
}

QString number(float value) { return QString::number(double(value), 'g', 6); }

}  // namespace

simcore::Vec3 eulerDegrees(const simcore::Quat& q) { return glm::degrees(glm::eulerAngles(q)); }

simcore::Quat fromEulerDegrees(const simcore::Vec3& degrees) { return glm::normalize(simcore::Quat(glm::radians(degrees))); }

CompoundChildrenModel::CompoundChildrenModel(QObject* parent) : QAbstractTableModel(parent) {}

void CompoundChildrenModel::setChildren(std::vector<simcore::CompoundChild> children) {
    beginResetModel();
    m_children = std::move(children);
    endResetModel();
}

void CompoundChildrenModel::addChild(simcore::ShapeType type) {
    const int row = rowCount();
    if (row >= int(simcore::limits::kMaxCompoundChildren)) {
        emit refused(tr("A compound has at most %1 children.").arg(simcore::limits::kMaxCompoundChildren));
        return;
    }
    beginInsertRows({}, row, row);
    m_children.push_back({templateShape(type), simcore::Transform{}});
    endInsertRows();
    emit childrenEdited(tr("Add %1 Child").arg(shapeDisplayName(type)));
}

void CompoundChildrenModel::removeChild(int row) {
    if (row < 0 || row >= rowCount()) return;
    if (rowCount() == 1) {
        emit refused(tr("A compound needs at least one child."));
        return;
    }
    beginRemoveRows({}, row, row);
    m_children.erase(m_children.begin() + row);
    endRemoveRows();
    emit childrenEdited(tr("Remove Child %1").arg(row + 1));
}

int CompoundChildrenModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_children.size());
}

int CompoundChildrenModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant CompoundChildrenModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const simcore::CompoundChild& child = m_children[static_cast<std::size_t>(index.row())];
    if (role == Qt::ToolTipRole && index.column() == SizeColumn) return sizeMeaning(child.shape.type);
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    switch (index.column()) {
        case ShapeColumn: return shapeDisplayName(child.shape.type);
        case SizeColumn: {
            if (child.shape.hull) return tr("%1 points").arg(child.shape.hull->sourcePoints().size());
            QStringList parts;
            for (float v : sizeOf(child.shape)) parts << number(v);
            return parts.join(QStringLiteral(" "));
        }
        case X:
        case Y:
        case Z: return number(child.pose.position[index.column() - X]);
        default: return number(eulerDegrees(child.pose.rotation)[index.column() - AngleX]);
    }
}

QVariant CompoundChildrenModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    switch (section) {
        case ShapeColumn: return tr("Shape");
        case SizeColumn: return tr("Size (m)");
        case X: return tr("x (m)");
        case Y: return tr("y (m)");
        case Z: return tr("z (m)");
        case AngleX: return tr("x (°)");
        case AngleY: return tr("y (°)");
        case AngleZ: return tr("z (°)");
        default: return {};
    }
}

Qt::ItemFlags CompoundChildrenModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    const Qt::ItemFlags base = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (index.column() == ShapeColumn) return base;  // another type: remove the child and add one
    if (index.column() == SizeColumn && sizeCount(m_children[static_cast<std::size_t>(index.row())].shape.type) == 0)
        return base;
    return base | Qt::ItemIsEditable;
}

bool CompoundChildrenModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !(flags(index) & Qt::ItemIsEditable)) return false;
    simcore::CompoundChild& child = m_children[static_cast<std::size_t>(index.row())];
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    const QStringList parts = value.toString().split(separators, Qt::SkipEmptyParts);
    const QString where = tr("Child %1").arg(index.row() + 1);
    std::vector<float> numbers;
    for (const QString& part : parts) {
        bool ok = false;
        const double v = part.toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            emit refused(tr("%1: \"%2\" is not a number.").arg(where, part));
            return false;
        }
        numbers.push_back(static_cast<float>(v));
    }
    const auto inRange = [&](const simcore::NumberRange& range, const QString& what) {
        for (float v : numbers)
            if (!range.contains(v)) {
                emit refused(tr("%1: the %2 must be within %3.").arg(where, what, QString::fromStdString(range.describe())));
                return false;
            }
        return true;
    };

    QString what;
    if (index.column() == SizeColumn) {
        const int count = sizeCount(child.shape.type);
        if (int(numbers.size()) != count) {
            emit refused(tr("%1 needs %2 numbers: %3.").arg(where).arg(count).arg(sizeMeaning(child.shape.type)));
            return false;
        }
        if (!inRange(simcore::limits::kSize, tr("size"))) return false;
        setSize(child.shape, numbers);
        what = tr("Child %1 Size").arg(index.row() + 1);
    } else {
        if (numbers.size() != 1) {
            emit refused(tr("%1: enter one number.").arg(where));
            return false;
        }
        if (index.column() <= Z) {
            if (!inRange(simcore::limits::kCoordinate, tr("position"))) return false;
            child.pose.position[index.column() - X] = numbers.front();
            what = tr("Child %1 Position").arg(index.row() + 1);
        } else {
            if (!inRange(simcore::NumberRange{-kMaxAngle, kMaxAngle, false, "°"}, tr("angle"))) return false;
            simcore::Vec3 angles = eulerDegrees(child.pose.rotation);
            angles[index.column() - AngleX] = numbers.front();
            child.pose.rotation = fromEulerDegrees(angles);
            what = tr("Child %1 Orientation").arg(index.row() + 1);
        }
    }
    emit dataChanged(this->index(index.row(), 0), this->index(index.row(), ColumnCount - 1));
    emit childrenEdited(what);
    return true;
}

}  // namespace interplay
