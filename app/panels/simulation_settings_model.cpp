#include "app/panels/simulation_settings_model.h"

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "simcore/io/scene_io.h"
#include "simcore/settings_schema.h"
#include "simcore/world/quality_preset.h"

#include <QUndoStack>

#include <cmath>
#include <utility>

namespace interplay {

namespace {

const simcore::SettingInfo& row(int index) {
    return simcore::settingsSchema()[static_cast<std::size_t>(index)];
}

QString toQString(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString typeName(simcore::SettingType type) {
    switch (type) {
    case simcore::SettingType::Bool: return QStringLiteral("bool");
    case simcore::SettingType::Int: return QStringLiteral("int");
    case simcore::SettingType::Float: return QStringLiteral("float");
    case simcore::SettingType::Vec3: return QStringLiteral("vec3");
    case simcore::SettingType::Choice: return QStringLiteral("choice");
    }
    return {};
}

bool isNumeric(simcore::SettingType type) {
    return type == simcore::SettingType::Int || type == simcore::SettingType::Float || type == simcore::SettingType::Vec3;
}

QVariant toVariant(const simcore::SettingValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b;
    if (const int* i = std::get_if<int>(&value)) return *i;
    if (const float* f = std::get_if<float>(&value)) return static_cast<double>(*f);
    const simcore::Vec3& v = std::get<simcore::Vec3>(value);
    return QVariantList{double(v.x), double(v.y), double(v.z)};
}

// A number from the panel: NaN when it is none (the loader's "must be a finite number" follows).
double toNumber(const QVariant& value) {
    bool ok = false;
    const double number = value.toDouble(&ok);
    return ok ? number : std::nan("");
}

// The panel's value as the setting's, or why it cannot be one: the schema's range check, with the
// loader's words, done on the double as the loader does on a file's number (before narrowing).
std::variant<simcore::SettingValue, std::string> fromVariant(const simcore::SettingInfo& info, const QVariant& value) {
    const std::string name(info.name());
    switch (info.type) {
    case simcore::SettingType::Bool:
        if (value.typeId() != QMetaType::Bool) return name + ": expected true or false";
        return simcore::SettingValue(value.toBool());
    case simcore::SettingType::Int:
    case simcore::SettingType::Choice: {
        const double number = toNumber(value);
        if (!std::isfinite(number) || number != std::floor(number)) return name + ": expected an integer";
        if (info.type == simcore::SettingType::Int) {
            if (auto why = simcore::integerRangeProblem(name, number, info.range)) return *why;
        } else if (number < 0 || number >= static_cast<double>(info.choices.size())) {
            return name + ": no such choice";
        }
        return simcore::SettingValue(static_cast<int>(number));
    }
    case simcore::SettingType::Float: {
        const double number = toNumber(value);
        if (auto why = simcore::rangeProblem(name, number, info.range)) return *why;
        return simcore::SettingValue(static_cast<float>(number));
    }
    case simcore::SettingType::Vec3: {
        const QVariantList list = value.toList();
        if (list.size() != 3) return name + ": expected 3 numbers";
        simcore::Vec3 v;
        for (int i = 0; i < 3; ++i) {
            const double number = toNumber(list[i]);
            if (auto why = simcore::rangeProblem(name + "[" + std::to_string(i) + "]", number, info.range)) return *why;
            v[i] = static_cast<float>(number);
        }
        return simcore::SettingValue(v);
    }
    }
    return name + ": unknown type";
}

}  // namespace

SimulationSettingsModel::SimulationSettingsModel(SceneDocument* document, QObject* parent)
    : QAbstractListModel(parent), m_document(document) {
    const auto refreshed = [this] {
        if (rowCount() > 0) emit dataChanged(index(0), index(rowCount() - 1), {ValueRole});
        emit changed();
    };
    connect(document, &SceneDocument::settingsChanged, this, refreshed);
    connect(document, &SceneDocument::sceneReplaced, this, refreshed);
}

const simcore::WorldSettings& SimulationSettingsModel::settings() const {
    return m_document->scene().settings;
}

int SimulationSettingsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(simcore::settingsSchema().size());
}

QVariant SimulationSettingsModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid)) return {};
    const simcore::SettingInfo& info = row(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case LabelRole: return toQString(info.label);
    case KeyRole: return toQString(info.key);
    case GroupRole: return toQString(simcore::settingGroupName(info.group));
    case FirstInGroupRole: return index.row() == 0 || row(index.row() - 1).group != info.group;
    case UnitRole: return isNumeric(info.type) ? toQString(info.range.unit) : QString();
    case Qt::ToolTipRole:
    case DocRole: return toQString(info.doc);
    case TypeRole: return typeName(info.type);
    case MinimumRole: return isNumeric(info.type) ? QVariant(info.range.min) : QVariant();
    case MaximumRole: return isNumeric(info.type) ? QVariant(info.range.max) : QVariant();
    case RangeRole: return isNumeric(info.type) ? QString::fromStdString(info.range.describe()) : QString();
    case ValueRole: return toVariant(info.get(settings()));
    case ChoicesRole: {
        QStringList names;
        for (std::string_view label : info.choiceLabels) names << toQString(label);
        return names;
    }
    }
    return {};
}

QHash<int, QByteArray> SimulationSettingsModel::roleNames() const {
    return {{KeyRole, "key"},         {GroupRole, "group"}, {FirstInGroupRole, "firstInGroup"},
            {LabelRole, "label"},     {UnitRole, "unit"},   {DocRole, "doc"},
            {TypeRole, "type"},       {MinimumRole, "minimum"}, {MaximumRole, "maximum"},
            {RangeRole, "range"},     {ValueRole, "value"}, {ChoicesRole, "choices"}};
}

QStringList SimulationSettingsModel::keys() const {
    QStringList keys;
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) keys << toQString(info.key);
    return keys;
}

QVariant SimulationSettingsModel::value(const QString& key) const {
    const simcore::SettingInfo* info = simcore::findSetting(key.toStdString());
    return info ? toVariant(info->get(settings())) : QVariant();
}

bool SimulationSettingsModel::setValue(const QString& key, const QVariant& value) {
    const simcore::SettingInfo* info = simcore::findSetting(key.toStdString());
    if (!info) {
        refuse(key, tr("no such setting"));
        return false;
    }
    const QString label = toQString(info->label);
    const auto converted = fromVariant(*info, value);
    if (const std::string* why = std::get_if<std::string>(&converted)) {
        refuse(label, QString::fromStdString(*why));
        return false;
    }
    simcore::WorldSettings after = settings();
    info->set(after, std::get<simcore::SettingValue>(converted));
    return push(label, key, after);
}

int SimulationSettingsModel::preset() const {
    const std::optional<simcore::QualityPreset> matching = simcore::matchingQualityPreset(settings());
    return matching ? static_cast<int>(*matching) : -1;  // -1: custom settings
}

QStringList SimulationSettingsModel::presetNames() const {
    QStringList names;
    for (simcore::QualityPreset preset : simcore::kQualityPresets) {
        const QString name = QString::fromLatin1(simcore::qualityPresetName(preset));
        names << name.left(1).toUpper() + name.mid(1);
    }
    return names;
}

void SimulationSettingsModel::setPreset(int preset) {
    if (preset < 0 || preset >= static_cast<int>(simcore::kQualityPresets.size())) return;
    simcore::WorldSettings after = settings();
    simcore::applyQualityPreset(after, simcore::kQualityPresets[static_cast<std::size_t>(preset)]);
    push(tr("Quality %1").arg(presetNames().at(preset)), QStringLiteral("preset"), after);
}

bool SimulationSettingsModel::setSettings(const QString& what, const simcore::WorldSettings& after) {
    return push(what, QStringLiteral("*"), after);
}

void SimulationSettingsModel::setInteracting(bool interacting) {
    if (interacting == m_interacting) return;
    m_interacting = interacting;
    m_pushedWhileInteracting = false;
    emit interactingChanged(interacting);
}

void SimulationSettingsModel::refuse(const QString& what, const QString& why) {
    emit rejected(tr("%1 not changed: %2").arg(what, why));
    // Controls showing the refused value go back to the document's.
    if (rowCount() > 0) emit dataChanged(index(0), index(rowCount() - 1), {ValueRole});
    emit changed();
}

bool SimulationSettingsModel::push(const QString& what, const QString& key, const simcore::WorldSettings& after) {
    simcore::Scene candidate = m_document->scene();
    candidate.settings = after;
    for (const simcore::Diagnostic& d : simcore::checkScene(candidate)) {
        if (d.severity != simcore::Diagnostic::Severity::Error) continue;
        refuse(what, QString::fromStdString(d.message));
        return false;
    }
    const bool mergeable = m_interacting && std::exchange(m_pushedWhileInteracting, true);
    m_document->undoStack()->push(new ChangeSettings(m_document, tr("Change %1").arg(what), key, after, mergeable));
    return true;
}

}  // namespace interplay
