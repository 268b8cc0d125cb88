// The settings schema is the one source of what a scene may hold: the editor's Simulation panel
// refuses exactly what the loader refuses, with the same message; everything it accepts saves and
// reopens unchanged; and the reader, the writer, the panel, the Inspector and the docs know
// exactly the schema's keys.

#include "app/document/scene_document.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/number_field.h"
#include "app/panels/simulation_settings_model.h"
#include "simcore/io/scene_io.h"
#include "simcore/settings_schema.h"

#include <QApplication>
#include <QFile>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <limits>
#include <string>

namespace {

const simcore::SettingInfo& setting(const QString& key) {
    const simcore::SettingInfo* info = simcore::findSetting(key.toStdString());
    if (!info) qFatal("no setting %s", qPrintable(key));
    return *info;
}

// The shortest text that reads back as the same double, as a file would hold it.
std::string jsonNumber(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

// A v1 scene whose settings hold `key` = `valueJson` and one body.
std::string sceneWith(const std::string& key, const std::string& valueJson) {
    const std::size_t dot = key.find('.');
    const std::string setting = dot == std::string::npos
                                    ? "\"" + key + "\": " + valueJson
                                    : "\"" + key.substr(0, dot) + "\": {\"" + key.substr(dot + 1) + "\": " + valueJson + "}";
    return R"({"format": "interplay.scene", "version": 1, "settings": {)" + setting +
           R"(}, "bodies": [{"shape": {"type": "sphere", "radius": 1}}]})";
}

// What the loader says about that value: its first error's message, or empty when it loads.
QString loaderMessage(const std::string& key, const std::string& valueJson) {
    for (const simcore::Diagnostic& d : simcore::parseScene(sceneWith(key, valueJson), "test").diagnostics)
        if (d.severity == simcore::Diagnostic::Severity::Error) return QString::fromStdString(d.message);
    return {};
}

QVariant panelValue(const simcore::SettingInfo& info, double number, int component) {
    if (info.type != simcore::SettingType::Vec3) return number;
    QVariantList v{0.0, 0.0, 0.0};
    v[component] = number;
    return v;
}

std::string valueJson(const simcore::SettingInfo& info, double number, int component) {
    if (info.type != simcore::SettingType::Vec3) return jsonNumber(number);
    std::string v = "[";
    for (int i = 0; i < 3; ++i) v += (i ? ", " : "") + (i == component ? jsonNumber(number) : std::string("0"));
    return v + "]";
}

}  // namespace

class TestSettingsSchema : public QObject {
    Q_OBJECT

private slots:
    void panelRefusesOutsideTheRange_data();
    void panelRefusesOutsideTheRange();
    void panelRefusesUnknownChoices();
    void acceptedValuesSaveAndReopen_data();
    void acceptedValuesSaveAndReopen();
    void readerReadsEverySchemaKey();
    void readerWarnsAboutKeysOutsideTheSchema();
    void writerAndPanelKnowExactlyTheSchemaKeys();
    void inspectorFieldsUseTheSchemaRanges();
    void propertyKeysAreWhatFilesHold();
    void docsListEverySettingWithItsRange();
};

void TestSettingsSchema::panelRefusesOutsideTheRange_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("component");
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const bool integer = info.type == simcore::SettingType::Int;
        if (!integer && info.type != simcore::SettingType::Float && info.type != simcore::SettingType::Vec3) continue;
        const double inf = std::numeric_limits<double>::infinity();
        // Just outside each end: the next integer, or the next double (an exclusive minimum itself).
        const double below = integer ? info.range.min - 1 : info.range.minExclusive ? info.range.min
                                                                                     : std::nextafter(info.range.min, -inf);
        const double above = integer ? info.range.max + 1 : std::nextafter(info.range.max, inf);
        const QString key = QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size()));
        for (int component = 0; component < (info.type == simcore::SettingType::Vec3 ? 3 : 1); ++component) {
            QTest::addRow("%s[%d] below", qPrintable(key), component) << key << below << component;
            QTest::addRow("%s[%d] above", qPrintable(key), component) << key << above << component;
        }
    }
    // The values of the bug report: accepted by the panel, then refused on File > Open.
    QTest::addRow("gravity y 1e9") << "gravity" << 1e9 << 1;
    QTest::addRow("damping 5000") << "damping.linear" << 5000.0 << 0;
    QTest::addRow("NaN") << "solver.contactHertz" << std::nan("") << 0;
}

void TestSettingsSchema::panelRefusesOutsideTheRange() {
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(int, component);
    const simcore::SettingInfo& info = setting(key);
    interplay::SceneDocument document;
    interplay::SimulationSettingsModel model(&document);
    QSignalSpy rejected(&model, &interplay::SimulationSettingsModel::rejected);
    const simcore::WorldSettings before = document.scene().settings;
    const int entries = document.undoStack()->count();

    QVERIFY(!model.setValue(key, panelValue(info, value, component)));

    // The schema's message, word for word.
    const std::string name = info.type == simcore::SettingType::Vec3
                                 ? std::string(info.name()) + "[" + std::to_string(component) + "]"
                                 : std::string(info.name());
    const std::optional<std::string> expected = info.type == simcore::SettingType::Int
                                                    ? simcore::integerRangeProblem(name, value, info.range)
                                                    : simcore::rangeProblem(name, value, info.range);
    QVERIFY(expected);
    QCOMPARE(rejected.count(), 1);
    const QString label = QString::fromLatin1(info.label.data(), static_cast<qsizetype>(info.label.size()));
    QCOMPARE(rejected.at(0).at(0).toString(), label + " not changed: " + QString::fromStdString(*expected));
    QCOMPARE(document.undoStack()->count(), entries);
    QVERIFY(document.scene().settings == before);
    // And the loader refuses the same value in a file with the same words (NaN cannot be written).
    if (std::isfinite(value)) QCOMPARE(loaderMessage(info.key.data(), valueJson(info, value, component)),
                                       QString::fromStdString(*expected));
}

void TestSettingsSchema::panelRefusesUnknownChoices() {
    interplay::SceneDocument document;
    interplay::SimulationSettingsModel model(&document);
    QSignalSpy rejected(&model, &interplay::SimulationSettingsModel::rejected);
    int refusals = 0;
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        if (info.type != simcore::SettingType::Choice) continue;
        const QString key = QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size()));
        QCOMPARE(info.choiceLabels.size(), info.choices.size());  // the panel shows a label per choice
        QVERIFY(!model.setValue(key, -1));
        QVERIFY(!model.setValue(key, static_cast<int>(info.choices.size())));
        refusals += 2;
        QVERIFY(loaderMessage(info.key.data(), "\"bogus\"").startsWith("unknown "));
    }
    QVERIFY(refusals >= 4);  // integrator and position correction
    QCOMPARE(rejected.count(), refusals);
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestSettingsSchema::acceptedValuesSaveAndReopen_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("value");
    const auto add = [](const simcore::SettingInfo& info, const char* what, const QVariant& value) {
        QTest::addRow("%s %s", info.key.data(), what)
            << QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size())) << value;
    };
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        switch (info.type) {
        case simcore::SettingType::Bool:
            add(info, "true", true);
            add(info, "false", false);
            break;
        case simcore::SettingType::Choice:
            for (int i = 0; i < static_cast<int>(info.choices.size()); ++i) add(info, info.choices[i].data(), i);
            break;
        case simcore::SettingType::Int:
            add(info, "min", static_cast<int>(info.range.min));
            add(info, "mid", static_cast<int>(std::floor((info.range.min + info.range.max) / 2)));
            add(info, "max", static_cast<int>(info.range.max));
            break;
        case simcore::SettingType::Float:
        case simcore::SettingType::Vec3: {
            // An exclusive minimum: the smallest float above it.
            const double min = info.range.minExclusive
                                   ? double(std::nextafter(float(info.range.min), std::numeric_limits<float>::infinity()))
                                   : info.range.min;
            const double mid = (info.range.min + info.range.max) / 2;
            for (const auto& [what, number] : {std::pair{"min", min}, {"mid", mid}, {"max", info.range.max}}) {
                if (info.type == simcore::SettingType::Float) add(info, what, number);
                else add(info, what, QVariantList{number, -number, mid});
            }
            break;
        }
        }
    }
}

void TestSettingsSchema::acceptedValuesSaveAndReopen() {
    QFETCH(QString, key);
    QFETCH(QVariant, value);
    const simcore::SettingInfo& info = setting(key);
    interplay::SceneDocument document;
    interplay::SimulationSettingsModel model(&document);
    QSignalSpy rejected(&model, &interplay::SimulationSettingsModel::rejected);
    QVERIFY2(model.setValue(key, value), qPrintable(rejected.isEmpty() ? QString() : rejected.first().first().toString()));
    const simcore::SettingValue set = info.get(document.scene().settings);

    QTemporaryDir dir;
    const QString path = dir.filePath("scene.json");
    QString error;
    QVERIFY2(document.save(path, &error), qPrintable(error));
    interplay::SceneDocument reopened;
    QVERIFY2(reopened.load(path, &error), qPrintable(error));
    QVERIFY(info.get(reopened.scene().settings) == set);
    QVERIFY(reopened.scene().settings == document.scene().settings);
    // The panel shows what it was given (floats as the nearest float).
    interplay::SimulationSettingsModel reopenedModel(&reopened);
    QCOMPARE(reopenedModel.value(key), model.value(key));
}

void TestSettingsSchema::readerReadsEverySchemaKey() {
    // Each key alone in a file, with a value unlike the default: read without warnings, into its field.
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const simcore::WorldSettings defaults;
        std::string text;
        switch (info.type) {
        case simcore::SettingType::Bool: text = std::get<bool>(info.get(defaults)) ? "false" : "true"; break;
        case simcore::SettingType::Choice: text = "\"" + std::string(info.choices.back()) + "\""; break;
        case simcore::SettingType::Int:
        case simcore::SettingType::Float: text = jsonNumber(info.range.max); break;
        case simcore::SettingType::Vec3: text = "[1, 2, 3]"; break;
        }
        const simcore::SceneLoadResult loaded = simcore::parseScene(sceneWith(std::string(info.key), text), "test");
        QVERIFY2(loaded.ok(), info.key.data());
        QVERIFY2(loaded.diagnostics.empty(), info.key.data());
        QVERIFY2(!(info.get(loaded.scene->settings) == info.get(defaults)), info.key.data());
        // Only that field changed.
        simcore::WorldSettings expected = defaults;
        info.set(expected, info.get(loaded.scene->settings));
        QVERIFY2(loaded.scene->settings == expected, info.key.data());
    }
}

void TestSettingsSchema::readerWarnsAboutKeysOutsideTheSchema() {
    QSet<QString> sections{QString()};
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const std::size_t dot = info.key.find('.');
        if (dot != std::string_view::npos) sections << QString::fromLatin1(info.key.substr(0, dot).data(), qsizetype(dot));
    }
    QCOMPARE(sections.size(), 7);  // the top level, solver, contact, joint, damping, sleep, effects
    for (const QString& section : sections) {
        const std::string key = section.isEmpty() ? "bogus" : section.toStdString() + ".bogus";
        const simcore::SceneLoadResult loaded = simcore::parseScene(sceneWith(key, "1"), "test");
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.diagnostics.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(loaded.diagnostics[0].message), QString("unknown key 'bogus' (ignored)"));
    }
}

void TestSettingsSchema::writerAndPanelKnowExactlyTheSchemaKeys() {
    QStringList schemaKeys;
    for (const simcore::SettingInfo& info : simcore::settingsSchema())
        schemaKeys << QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size()));

    simcore::WorldSettings custom;
    custom.substeps = 5;  // matches no preset, so no "preset" label
    QStringList written;
    for (const std::string& key : simcore::writtenSettingsKeys(custom)) written << QString::fromStdString(key);
    QCOMPARE(written, schemaKeys);
    written.clear();
    for (const std::string& key : simcore::writtenSettingsKeys(simcore::WorldSettings{})) written << QString::fromStdString(key);
    QCOMPARE(written, QStringList{"preset"} + schemaKeys);  // the defaults are the balanced preset

    interplay::SceneDocument document;
    interplay::SimulationSettingsModel model(&document);
    QCOMPARE(model.keys(), schemaKeys);
    QCOMPARE(model.rowCount(), static_cast<int>(schemaKeys.size()));
    // The panel heads each group once: the groups are contiguous, in SettingGroup's order.
    int headings = 0;
    for (std::size_t i = 0; i < simcore::settingsSchema().size(); ++i) {
        const simcore::SettingInfo& info = simcore::settingsSchema()[i];
        if (i > 0) QVERIFY2(simcore::settingsSchema()[i - 1].group <= info.group, info.key.data());
        if (model.index(static_cast<int>(i)).data(interplay::SimulationSettingsModel::FirstInGroupRole).toBool()) ++headings;
    }
    QCOMPARE(headings, static_cast<int>(simcore::SettingGroup::Effects) + 1);
    // Every row has a group, a label, a doc line, and a range when it is a number.
    for (int row = 0; row < model.rowCount(); ++row) {
        const QModelIndex index = model.index(row);
        QVERIFY(!index.data(interplay::SimulationSettingsModel::GroupRole).toString().isEmpty());
        QVERIFY(!index.data(interplay::SimulationSettingsModel::LabelRole).toString().isEmpty());
        QVERIFY(!index.data(interplay::SimulationSettingsModel::DocRole).toString().isEmpty());
        const QString type = index.data(interplay::SimulationSettingsModel::TypeRole).toString();
        QCOMPARE(index.data(interplay::SimulationSettingsModel::RangeRole).toString().isEmpty(),
                 type == "bool" || type == "choice");
    }
}

void TestSettingsSchema::inspectorFieldsUseTheSchemaRanges() {
    interplay::SceneDocument document;
    interplay::InspectorPanel inspector(&document);
    const auto rangeOf = [](const QString& qualified) -> std::optional<simcore::NumberRange> {
        for (const simcore::PropertyInfo& p : simcore::propertySchema()) {
            const QString name = QString::fromLatin1(simcore::propertyOwnerName(p.owner).data()) + "." +
                                 QString::fromLatin1(p.key.data(), static_cast<qsizetype>(p.key.size()));
            if (name == qualified) return p.range;
        }
        return std::nullopt;
    };
    QSet<QString> edited;
    for (const interplay::NumberField* field : inspector.findChildren<interplay::NumberField*>()) {
        const QStringList keys = field->property("schemaKeys").toStringList();
        if (field->objectName().startsWith("orientation.")) {
            QVERIFY(keys.isEmpty());  // Euler angles in degrees: no one file value
            continue;
        }
        QVERIFY2(!keys.isEmpty(), qPrintable(field->objectName()));
        for (const QString& key : keys) edited << key;
        if (keys.first().startsWith("hinge.limits.")) continue;  // shown in degrees
        // The field takes exactly its property's range (both ends; an exclusive end the loader refuses).
        const std::optional<simcore::NumberRange> range = rangeOf(keys.first());
        QVERIFY2(range, qPrintable(keys.first()));
        // One field for several properties (a radius of three shapes) needs them to agree; the mass
        // field switches to density's range when the body gives a density (test_document).
        if (field->objectName() != "mass")
            for (const QString& key : keys)
                QVERIFY2(rangeOf(key)->min == range->min && rangeOf(key)->max == range->max, qPrintable(key));
        const auto accepts = [&](double v) { return std::holds_alternative<double>(field->parse(QString::number(v, 'g', 17))); };
        const double inf = std::numeric_limits<double>::infinity();
        QVERIFY2(accepts(range->min) && accepts(range->max), qPrintable(field->objectName()));
        QVERIFY2(!accepts(std::nextafter(range->min, -inf)) && !accepts(std::nextafter(range->max, inf)),
                 qPrintable(field->objectName()));
    }
    QSet<QString> numeric;
    for (const simcore::PropertyInfo& p : simcore::propertySchema()) {
        if (!p.range) continue;
        numeric << QString::fromLatin1(simcore::propertyOwnerName(p.owner).data()) + "." +
                       QString::fromLatin1(p.key.data(), static_cast<qsizetype>(p.key.size()));
    }
    // What the Inspector edits otherwise: the orientation as Euler angles, the colour in a colour
    // dialog; hull points, a compound's children (a table of their own), a surface's samples and a mesh
    // file's scale (applied on import) are not edited.
    const QSet<QString> notNumberFields{"body.orientation",     "body.color",          "convexHull.points",
                                        "compoundChild.position", "compoundChild.orientation", "mesh.vertices",
                                        "mesh.scale",
                                        "heightField.rows",      "heightField.columns", "heightField.cellSize",
                                        "heightField.heightScale", "heightField.heights"};
    QCOMPARE(edited, numeric - notNumberFields);
    QVERIFY(numeric.contains(notNumberFields));

    // A field refuses what the schema refuses; the spring's minimum is the loader's (any positive).
    interplay::NumberField* friction = inspector.numberField("friction");
    QVERIFY(friction);
    QVERIFY(std::holds_alternative<QString>(friction->parse(QString::number(simcore::limits::kFriction.max * 1.01))));
    QVERIFY(std::holds_alternative<double>(friction->parse(QString::number(simcore::limits::kFriction.max))));
    interplay::NumberField* hertz = inspector.numberField("springHertz");
    QVERIFY(hertz);
    QVERIFY(std::holds_alternative<double>(hertz->parse("0.0001")));
}

void TestSettingsSchema::propertyKeysAreWhatFilesHold() {
    // The default scene (every shape type) saves and loads without a warning; the key lists are
    // the file format's.
    const simcore::Scene scene = simcore::defaultScene();
    const std::string text = simcore::serializeScene(scene);
    const simcore::SceneLoadResult loaded = simcore::parseScene(text, "default");
    QVERIFY(loaded.ok());
    QVERIFY(loaded.diagnostics.empty());
    const auto keys = [](simcore::PropertyOwner owner) {
        QStringList list;
        for (std::string_view key : simcore::propertyKeys(owner))
            list << QString::fromLatin1(key.data(), static_cast<qsizetype>(key.size()));
        return list;
    };
    QCOMPARE(keys(simcore::PropertyOwner::Box), (QStringList{"type", "halfExtents"}));
    QCOMPARE(keys(simcore::PropertyOwner::Capsule), (QStringList{"type", "radius", "halfHeight"}));
    QCOMPARE(keys(simcore::PropertyOwner::Hinge),
             (QStringList{"name", "type", "bodyA", "bodyB", "anchor", "collideConnected", "axis", "limits", "motor"}));
    QCOMPARE(keys(simcore::PropertyOwner::Joint), (QStringList{"name", "type", "bodyA", "bodyB", "anchor", "collideConnected"}));
    QCOMPARE(simcore::propertyKeys(simcore::PropertyOwner::Hinge, "motor").size(), std::size_t(2));
    QCOMPARE(simcore::propertyKeys(simcore::PropertyOwner::Slider, "motor").back(), std::string_view("maxForce"));
    // A key a body does not take is a warning naming it.
    const simcore::SceneLoadResult extra = simcore::parseScene(
        R"({"format": "interplay.scene", "version": 1, "bodies": [{"shape": {"type": "sphere", "radius": 1}, "spin": 1}]})",
        "test");
    QVERIFY(extra.ok());
    QCOMPARE(extra.diagnostics.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(extra.diagnostics[0].path), QString("/bodies/0/spin"));
}

void TestSettingsSchema::docsListEverySettingWithItsRange() {
    QFile file(INTERPLAY_SOURCE_DIR "/docs/scene-format.md");
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n');
    QStringList missing;
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        const QString key = "`" + QString::fromLatin1(info.key.data(), static_cast<qsizetype>(info.key.size())) + "`";
        const bool numeric = info.type == simcore::SettingType::Int || info.type == simcore::SettingType::Float ||
                             info.type == simcore::SettingType::Vec3;
        QString range = numeric ? QString::fromStdString(info.range.describe()) : QString();
        if (info.type == simcore::SettingType::Choice) {
            QStringList names;
            for (std::string_view name : info.choices) names << "`" + QString::fromLatin1(name.data()) + "`";
            range = names.join(", ");
        }
        const bool found = std::any_of(lines.begin(), lines.end(), [&](const QString& line) {
            return line.startsWith("| " + key + " ") && line.contains(range);
        });
        if (!found)
            missing << QString("| %1 | %2 | %3 | %4 |")
                           .arg(key, range.isEmpty() ? QString("true/false") : range,
                                QString::fromLatin1(settingGroupName(info.group).data()),
                                QString::fromLatin1(info.doc.data(), static_cast<qsizetype>(info.doc.size())));
    }
    // The rows as they should read, one per line (a failure message would be cut short).
    for (const QString& row : missing) qWarning("%s", qPrintable(row));
    QVERIFY2(missing.isEmpty(), "docs/scene-format.md lacks the settings rows above");
}

QTEST_MAIN(TestSettingsSchema)
#include "test_settings_schema.moc"
