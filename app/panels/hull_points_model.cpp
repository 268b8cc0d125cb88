#include "app/panels/hull_points_model.h"

#include "simcore/settings_schema.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace interplay {

namespace {

constexpr qint64 kMaxPointFileBytes = 16 * 1024 * 1024;  // far above 4096 points in any text form
constexpr int kCoordinateDigits = 6;
constexpr int kEditDigits = 9;  // every float prints back to itself


}  // namespace

PointListResult parsePointList(const QString& text) {
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    PointListResult result;
    const QStringList lines = text.split(QLatin1Char('\n'));
    // An OBJ file is read for its vertices only; anything else must be all points.
    const bool obj = std::any_of(lines.begin(), lines.end(), [](const QString& line) {
        return line.trimmed().startsWith(QLatin1String("v "));
    });
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i].trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) continue;
        if (obj) {
            if (!line.startsWith(QLatin1String("v "))) continue;
            line = line.mid(2).trimmed();
        }
        const QStringList fields = line.split(separators, Qt::SkipEmptyParts);
        const QString where = QObject::tr("line %1").arg(i + 1);
        // OBJ vertices may carry a fourth (w) or colour fields: the first three are the point.
        if (fields.size() != 3 && !(obj && fields.size() > 3)) {
            result.error = QObject::tr("%1: expected three numbers (x y z), got \"%2\"").arg(where, line.left(60));
            return result;
        }
        simcore::Vec3 point{0.0f};
        for (int axis = 0; axis < 3; ++axis) {
            bool ok = false;
            const double value = fields[axis].toDouble(&ok);
            if (!ok || !std::isfinite(value)) {
                result.error = QObject::tr("%1: \"%2\" is not a number").arg(where, fields[axis].left(30));
                return result;
            }
            if (!simcore::limits::kCoordinate.contains(value)) {
                result.error = QObject::tr("%1: %2 is outside the coordinate range %3")
                                   .arg(where, fields[axis], QString::fromStdString(simcore::limits::kCoordinate.describe()));
                return result;
            }
            point[axis] = static_cast<float>(value);
        }
        if (result.points.size() == simcore::limits::kMaxHullPoints) {
            result.error = QObject::tr("more than %1 points: a convex hull may have at most %1")
                               .arg(simcore::limits::kMaxHullPoints);
            return result;
        }
        result.points.push_back(point);
    }
    if (result.points.empty()) result.error = QObject::tr("no points found");
    return result;
}

PointListResult readPointFile(const QString& path) {
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {{}, QObject::tr("%1: %2").arg(name, file.errorString())};
    if (file.size() > kMaxPointFileBytes) {
        return {{}, QObject::tr("%1: %2 MiB is too large for a file of points (at most %3 MiB)")
                        .arg(name)
                        .arg(file.size() / (1024 * 1024))
                        .arg(kMaxPointFileBytes / (1024 * 1024))};
    }
    PointListResult result = parsePointList(QString::fromUtf8(file.readAll()));
    if (!result.error.isEmpty()) result.error = QObject::tr("%1: %2").arg(name, result.error);
    return result;
}

HullPointsModel::HullPointsModel(QObject* parent) : QAbstractTableModel(parent) { rebuildHull(); }

void HullPointsModel::setPoints(std::vector<simcore::Vec3> points) {
    beginResetModel();
    m_points = std::move(points);
    endResetModel();
    rebuildHull();
}

int HullPointsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_points.size());
}

int HullPointsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : 3; }

QVariant HullPointsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const float value = m_points[static_cast<std::size_t>(index.row())][index.column()];
    if (role == Qt::DisplayRole) return QString::number(value, 'g', kCoordinateDigits);
    // Text, not a number: a number would get a spin box limited to [0, 99.99] and two decimals.
    if (role == Qt::EditRole) return QString::number(value, 'g', kEditDigits);
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant HullPointsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    static const char* const axes[] = {"x (m)", "y (m)", "z (m)"};
    return tr(axes[section]);
}

Qt::ItemFlags HullPointsModel::flags(const QModelIndex& index) const {
    return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

bool HullPointsModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole) return false;
    bool ok = false;
    const double number = value.toDouble(&ok);
    if (!ok || !std::isfinite(number) || !simcore::limits::kCoordinate.contains(number)) return false;
    m_points[static_cast<std::size_t>(index.row())][index.column()] = static_cast<float>(number);
    emit dataChanged(index, index);
    rebuildHull();
    return true;
}

bool HullPointsModel::insertRows(int row, int count, const QModelIndex& parent) {
    if (parent.isValid() || row < 0 || row > rowCount() || count < 1 ||
        m_points.size() + static_cast<std::size_t>(count) > simcore::limits::kMaxHullPoints)
        return false;
    const simcore::Vec3 copied = row > 0 ? m_points[static_cast<std::size_t>(row - 1)] : simcore::Vec3{0.0f};
    beginInsertRows(parent, row, row + count - 1);
    m_points.insert(m_points.begin() + row, static_cast<std::size_t>(count), copied);
    endInsertRows();
    rebuildHull();
    return true;
}

bool HullPointsModel::removeRows(int row, int count, const QModelIndex& parent) {
    if (parent.isValid() || row < 0 || count < 1 || row + count > rowCount()) return false;
    beginRemoveRows(parent, row, row + count - 1);
    m_points.erase(m_points.begin() + row, m_points.begin() + row + count);
    endRemoveRows();
    rebuildHull();
    return true;
}

void HullPointsModel::rebuildHull() {
    m_hull = simcore::ConvexHull::build(m_points);
    emit hullChanged();
}

}  // namespace interplay
