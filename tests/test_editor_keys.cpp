// The editor's keyboard and file-safety behaviour, in the whole window with real OpenGL under Xvfb
// and real QTest key and mouse events: File → Revert asks first and is undoable; Ctrl+Z reaches the
// document after a field committed its value (widget and QML fields) and while a Scene tree row's
// rename editor is open, and both Ctrl+Y and Ctrl+Shift+Z redo; Escape drops a typed value;
// Space plays and pauses unless the focus is in a text field or a drop-down, and a drop-down
// chosen with the mouse does not keep Space; File → Examples opens untitled copies; an Inspector
// error line moves no field and goes with the selection; every load warning is shown; number
// fields show as many digits as fit.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/scene_tree_model.h"
#include "app/main_window.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/number_field.h"
#include "app/panels/simulation_settings_model.h"
#include "app/panels/simulation_settings_panel.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QMenu>
#include <QQuickItem>
#include <QQuickWidget>
#include <QSettings>
#include <QStatusBar>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <functional>
#include <memory>

using interplay::DocumentManager;
using interplay::MainWindow;

namespace {

std::string sceneText(const simcore::Scene& scene) { return simcore::serializeScene(scene); }

// The first item under `root` (itself included) for which `match` holds, through the visual tree:
// a Repeater's or a popup's items have no QObject parent to find them by.
QQuickItem* findItem(QQuickItem* root, const std::function<bool(QQuickItem*)>& match) {
    if (match(root)) return root;
    for (QQuickItem* child : root->childItems()) {
        if (QQuickItem* found = findItem(child, match)) return found;
    }
    return nullptr;
}

QQuickItem* findNamed(QQuickItem* root, const QString& name) {
    return findItem(root, [&](QQuickItem* item) { return item->objectName() == name; });
}

}  // namespace

class TestEditorKeys : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void revertAsksFirstAndIsUndoable();
    void undoAndRedoKeysReachTheDocumentAfterEnter();
    void undoReachesTheDocumentWhileRenaming();
    void escapeDropsATypedValue();
    void qmlFieldLeavesUndoToTheDocumentAndEscapeDrops();
    void spaceAfterChoosingAPresetPlays();
    void spaceInAFocusedDropDownDoesNotPlay();
    void examplesOpenAsUntitledCopies();
    void inspectorErrorStaysPutAndClearsWithTheSelection();
    void everyLoadWarningIsShown();
    void fieldsShowNumbersThatFit();

private:
    QQuickWidget* showSettingsPanel();
    // Scrolls the QML panel until `item` is in view, as a user would.
    void scrollTo(QQuickItem* item);
    void clickItem(QQuickItem* item);
    float friction(int body) const { return m_window->document()->body(body).body.friction; }
    QUndoStack* history() const { return m_window->document()->undoStack(); }

    std::unique_ptr<MainWindow> m_window;
    QStringList m_questions;
    bool m_confirmAnswer = true;
    QString m_fileAnswer;
    QTemporaryDir m_dir;
};

void TestEditorKeys::initTestCase() {
    test_support::isolateSettings("test_editor_keys");
    QVERIFY(m_dir.isValid());
}

void TestEditorKeys::cleanupTestCase() {
    test_support::removeSettings();
}

void TestEditorKeys::init() {
    test_support::clearSettings();
    m_questions.clear();
    m_confirmAnswer = true;
    m_fileAnswer.clear();
    m_window = std::make_unique<MainWindow>();
    auto& prompts = m_window->documentManager()->prompts();
    prompts.confirm = [this](const QString&, const QString& question) {
        m_questions << question;
        return m_confirmAnswer;
    };
    prompts.unsavedChanges = [](const QString&) { return DocumentManager::UnsavedChoice::Cancel; };
    prompts.error = [](const QString&, const QString& text, const QString& details) {
        QFAIL(qPrintable(text + '\n' + details));
    };
    prompts.chooseFile = [this](DocumentManager::FileChoice, const QString&, const QString&) { return m_fileAnswer; };
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    m_window->viewport()->grabViewport();
}

void TestEditorKeys::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

QQuickWidget* TestEditorKeys::showSettingsPanel() {
    auto* dock = m_window->findChild<QDockWidget*>("settingsDock");
    dock->show();
    dock->raise();
    QQuickWidget* quick = m_window->settingsPanel()->quickWidget();
    if (!QTest::qWaitFor([quick] { return quick->isVisible() && quick->width() > 100; })) return nullptr;
    return quick;
}

void TestEditorKeys::scrollTo(QQuickItem* item) {
    for (QQuickItem* ancestor = item->parentItem(); ancestor; ancestor = ancestor->parentItem()) {
        if (!ancestor->inherits("QQuickFlickable")) continue;
        auto* content = qvariant_cast<QQuickItem*>(ancestor->property("contentItem"));
        ancestor->setProperty("contentY", std::max(0.0, item->mapToItem(content, QPointF(0, 0)).y() - 20.0));
        break;
    }
    QTest::qWait(50);
}

void TestEditorKeys::clickItem(QQuickItem* item) {
    QQuickWidget* quick = m_window->settingsPanel()->quickWidget();
    const QPointF centre = item->mapToScene(QPointF(item->width() / 2, item->height() / 2));
    QTest::mouseClick(quick, Qt::LeftButton, {}, centre.toPoint());
}

// ---- Defect 1: Revert --------------------------------------------------------------------------

void TestEditorKeys::revertAsksFirstAndIsUndoable() {
    m_fileAnswer = m_dir.filePath("revert.json");
    QVERIFY(m_window->documentManager()->saveAs());
    const std::string saved = sceneText(m_window->document()->scene());
    const int savedBodies = m_window->document()->bodyCount();
    m_window->action("addBox")->trigger();
    m_window->action("addSphere")->trigger();
    const std::string edited = sceneText(m_window->document()->scene());
    QVERIFY(m_window->isWindowModified());

    // Declined: nothing changes.
    m_confirmAnswer = false;
    m_window->action("revert")->trigger();
    QCOMPARE(m_questions.size(), 1);
    QVERIFY2(m_questions.first().contains("revert.json") && m_questions.first().contains("unsaved"),
             qPrintable(m_questions.first()));
    QCOMPARE(sceneText(m_window->document()->scene()), edited);
    QVERIFY(m_window->isWindowModified());

    // Accepted: the file's scene, clean, with the edits one Undo away and the history before kept.
    m_confirmAnswer = true;
    const int entriesBefore = history()->count();
    m_window->action("revert")->trigger();
    QCOMPARE(m_questions.size(), 2);
    QCOMPARE(sceneText(m_window->document()->scene()), saved);
    QCOMPARE(m_window->simulation()->authoredScene().bodies.size(), std::size_t(savedBodies));
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(history()->count(), entriesBefore + 1);
    QCOMPARE(history()->undoText(), QString("Revert to \"revert.json\""));

    QTest::keyClick(m_window->viewport(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(sceneText(m_window->document()->scene()), edited);
    QCOMPARE(m_window->simulation()->authoredScene().bodies.size(), std::size_t(savedBodies + 2));
    QVERIFY(m_window->isWindowModified());
    QTest::keyClick(m_window->viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(sceneText(m_window->document()->scene()), saved);
    QVERIFY(!m_window->isWindowModified());

    // A clean scene loses nothing: Revert does not ask.
    m_window->action("revert")->trigger();
    QCOMPARE(m_questions.size(), 2);
    QCOMPARE(sceneText(m_window->document()->scene()), saved);
}

// ---- Defect 2: Undo and Redo from fields, Escape ----------------------------------------------------

void TestEditorKeys::undoAndRedoKeysReachTheDocumentAfterEnter() {
    m_window->document()->setSelectedBodies({1});
    interplay::NumberField* field = m_window->inspector()->numberField("friction");
    QVERIFY(field);
    const float before = friction(1);
    QTest::mouseClick(field, Qt::LeftButton);
    QTRY_COMPARE(QApplication::focusWidget(), field);
    field->selectAll();
    QTest::keyClicks(field, "0.25");
    QTest::keyClick(field, Qt::Key_Return);
    QCOMPARE(friction(1), 0.25f);
    QCOMPARE(QApplication::focusWidget(), field);  // Enter leaves the focus in the field

    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(friction(1), before);
    QCOMPARE(field->text(), QString::number(double(before)));
    QTest::keyClick(field, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(friction(1), 0.25f);
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(friction(1), before);
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(friction(1), 0.25f);

    // Typing not yet committed is the field's own to undo first, as in any line edit.
    const int entries = history()->index();
    QTest::keyClick(field, Qt::Key_End);
    QTest::keyClicks(field, "9");
    QCOMPARE(field->text(), QString("0.259"));
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(field->text(), QString("0.25"));
    QCOMPARE(history()->index(), entries);
    QCOMPARE(friction(1), 0.25f);
}

void TestEditorKeys::undoReachesTheDocumentWhileRenaming() {
    const int bodies = m_window->document()->bodyCount();
    m_window->action("addBox")->trigger();
    QCOMPARE(m_window->document()->bodyCount(), bodies + 1);

    QTreeView* tree = m_window->sceneTree();
    const QModelIndex row = m_window->sceneTreeModel()->indexOfBody(0, 0);
    tree->setFocus();
    tree->setCurrentIndex(row);
    QTest::keyClick(tree, Qt::Key_F2);
    QLineEdit* editor = nullptr;
    QTRY_VERIFY((editor = qobject_cast<QLineEdit*>(QApplication::focusWidget())) && editor->parent() == tree->viewport());

    QTest::keyClick(editor, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->bodyCount(), bodies);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(m_window->document()->bodyCount(), bodies + 1);
}

void TestEditorKeys::escapeDropsATypedValue() {
    m_window->document()->setSelectedBodies({1});
    interplay::NumberField* field = m_window->inspector()->numberField("friction");
    const float before = friction(1);
    const int entries = history()->count();
    QTest::mouseClick(field, Qt::LeftButton);
    QTRY_COMPARE(QApplication::focusWidget(), field);
    field->selectAll();
    QTest::keyClicks(field, "0.9");
    QTest::keyClick(field, Qt::Key_Escape);
    QCOMPARE(field->text(), QString::number(double(before)));
    // Clicking away after Escape commits nothing ...
    QTest::mouseClick(m_window->inspector()->nameField(), Qt::LeftButton);
    QTRY_COMPARE(QApplication::focusWidget(), m_window->inspector()->nameField());
    QCOMPARE(friction(1), before);
    QCOMPARE(history()->count(), entries);

    // ... and clicking away from a typed value still commits it.
    QTest::mouseClick(field, Qt::LeftButton);
    QTRY_COMPARE(QApplication::focusWidget(), field);
    field->selectAll();
    QTest::keyClicks(field, "0.9");
    QTest::mouseClick(m_window->inspector()->nameField(), Qt::LeftButton);
    QTRY_COMPARE(friction(1), 0.9f);
    QCOMPARE(history()->count(), entries + 1);
}

void TestEditorKeys::qmlFieldLeavesUndoToTheDocumentAndEscapeDrops() {
    QQuickWidget* quick = showSettingsPanel();
    QVERIFY(quick);
    QQuickItem* gravityY = findNamed(quick->rootObject(), "setting_gravity.1");
    QVERIFY(gravityY);
    const float before = m_window->document()->scene().settings.gravity.y;
    scrollTo(gravityY);
    clickItem(gravityY);
    QTRY_VERIFY(gravityY->hasActiveFocus());
    QTest::keyClick(quick, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(quick, "-5");
    QTest::keyClick(quick, Qt::Key_Return);
    QCOMPARE(m_window->document()->scene().settings.gravity.y, -5.0f);
    QVERIFY(gravityY->hasActiveFocus());

    QTest::keyClick(quick, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.gravity.y, before);
    QTRY_COMPARE(gravityY->property("text").toString(), QString::number(double(before)));
    QTest::keyClick(quick, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.gravity.y, -5.0f);

    // Escape drops typed text; leaving the field afterwards commits nothing.
    const int entries = history()->count();
    QTest::keyClick(quick, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(quick, "-7");
    QTest::keyClick(quick, Qt::Key_Escape);
    QCOMPARE(gravityY->property("text").toString(), QString("-5"));
    QTest::mouseClick(m_window->viewport(), Qt::LeftButton, {}, QPoint(m_window->viewport()->width() / 2, 3));
    QTRY_VERIFY(!gravityY->hasActiveFocus());
    QCOMPARE(m_window->document()->scene().settings.gravity.y, -5.0f);
    QCOMPARE(history()->count(), entries);
}

// ---- Defect 3: Space and drop-downs -------------------------------------------------------------------

void TestEditorKeys::spaceAfterChoosingAPresetPlays() {
    QQuickWidget* quick = showSettingsPanel();
    QVERIFY(quick);
    QQuickItem* preset = findNamed(quick->rootObject(), "presetComboBox");
    QVERIFY(preset);
    auto* popup = qvariant_cast<QObject*>(preset->property("popup"));
    QVERIFY(popup);
    const QStringList names = m_window->findChild<interplay::SimulationSettingsModel*>()->presetNames();
    QVERIFY(names.size() >= 2);
    const int chosen = preset->property("currentIndex").toInt() == 0 ? 1 : 0;

    scrollTo(preset);
    clickItem(preset);
    QTRY_VERIFY(popup->property("opened").toBool());
    auto* list = qvariant_cast<QQuickItem*>(popup->property("contentItem"));
    QVERIFY(list);
    QQuickItem* entry = nullptr;
    QTRY_VERIFY((entry = findItem(list, [&](QQuickItem* item) {
        return item->inherits("QQuickAbstractButton")  // Fusion's entries are MenuItems
                && item->property("text").toString() == names[chosen];
    })));
    clickItem(entry);
    QTRY_VERIFY(!popup->property("visible").toBool());
    QCOMPARE(preset->property("currentIndex").toInt(), chosen);

    QVERIFY(!m_window->simulation()->isPlaying());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(m_window->simulation()->isPlaying());
    QTest::qWait(100);
    QVERIFY(!popup->property("visible").toBool());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(!m_window->simulation()->isPlaying());
    QTest::qWait(100);
    QVERIFY(!popup->property("visible").toBool());
    QCOMPARE(preset->property("currentIndex").toInt(), chosen);
}

void TestEditorKeys::spaceInAFocusedDropDownDoesNotPlay() {
    // Focus in the viewport: Space plays and pauses.
    m_window->viewport()->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), m_window->viewport());
    QTest::keyClick(m_window->viewport(), Qt::Key_Space);
    QVERIFY(m_window->simulation()->isPlaying());
    QTest::keyClick(m_window->viewport(), Qt::Key_Space);
    QVERIFY(!m_window->simulation()->isPlaying());

    // An Inspector drop-down with the keyboard focus opens instead.
    m_window->document()->setSelectedBodies({1});
    QComboBox* motion = m_window->inspector()->motionBox();
    motion->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), motion);
    QTest::keyClick(motion, Qt::Key_Space);
    QVERIFY(!m_window->simulation()->isPlaying());
    QTRY_VERIFY(motion->view()->isVisible());
    motion->hidePopup();

    // So does the QML panel's, reached with Tab.
    QQuickWidget* quick = showSettingsPanel();
    QVERIFY(quick);
    QQuickItem* preset = findNamed(quick->rootObject(), "presetComboBox");
    QVERIFY(preset);
    auto* popup = qvariant_cast<QObject*>(preset->property("popup"));
    scrollTo(preset);
    quick->setFocus(Qt::TabFocusReason);
    preset->forceActiveFocus(Qt::TabFocusReason);
    QTRY_VERIFY(preset->hasActiveFocus());
    const int current = preset->property("currentIndex").toInt();
    QTest::keyClick(quick, Qt::Key_Space);
    QVERIFY(!m_window->simulation()->isPlaying());
    QTRY_VERIFY(popup->property("opened").toBool());
    QTest::keyClick(quick, Qt::Key_Escape);
    QTRY_VERIFY(!popup->property("visible").toBool());
    QCOMPARE(preset->property("currentIndex").toInt(), current);
}

// ---- Defect 9: examples ----------------------------------------------------------------------------

void TestEditorKeys::examplesOpenAsUntitledCopies() {
    const QString shipped = QDir(DocumentManager::examplesDirectory()).filePath("pendulums.json");
    QFile file(shipped);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray shippedBytes = file.readAll();
    file.close();

    auto* examples = m_window->findChild<QMenu*>("examplesMenu");
    QVERIFY(examples);
    QAction* pendulums = nullptr;
    for (QAction* a : examples->actions()) {
        if (a->text() == "pendulums") pendulums = a;
    }
    QVERIFY(pendulums);
    pendulums->trigger();
    QCOMPARE(m_window->windowTitle(), QString("[*]pendulums (example) — Interplay"));
    QVERIFY(m_window->document()->filePath().isEmpty());
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(m_window->document()->bodyCount() > 1);
    QVERIFY(!m_window->documentManager()->recentFiles().contains(shipped));

    // Ctrl+S asks where to save; the shipped file stays as it was.
    m_window->action("addBox")->trigger();
    m_fileAnswer = m_dir.filePath("my_pendulums.json");
    QTest::keyClick(m_window->viewport(), Qt::Key_S, Qt::ControlModifier);
    QCOMPARE(m_window->document()->filePath(), m_fileAnswer);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), shippedBytes);
    QCOMPARE(m_window->windowTitle(), QString("[*]my_pendulums.json — Interplay"));
}

// ---- Defect 10, the smaller ones -----------------------------------------------------------------

void TestEditorKeys::inspectorErrorStaysPutAndClearsWithTheSelection() {
    m_window->document()->setSelectedBodies({1});
    interplay::InspectorPanel* inspector = m_window->inspector();
    interplay::NumberField* field = inspector->numberField("friction");
    auto* message = inspector->findChild<QWidget*>("inspectorMessage");
    QVERIFY(message);
    QTRY_VERIFY(field->isVisible());
    QTest::qWait(50);  // the layout settles on the new selection's header
    const QPoint before = field->mapTo(inspector, QPoint(0, 0));

    QTest::mouseClick(field, Qt::LeftButton);
    field->selectAll();
    QTest::keyClicks(field, "abc");
    QTest::keyClick(field, Qt::Key_Return);
    QVERIFY2(inspector->message().contains("not a number"), qPrintable(inspector->message()));
    QTRY_VERIFY(message->isVisible() && message->height() > 0);
    QTest::qWait(50);  // the layout settles
    QCOMPARE(field->mapTo(inspector, QPoint(0, 0)), before);  // the error line moves no field

    m_window->document()->setSelectedBodies({2});
    QVERIFY(inspector->message().isEmpty());
    QVERIFY(!message->isVisible());
}

void TestEditorKeys::everyLoadWarningIsShown() {
    // A saved scene with three keys the loader does not know, each one warning.
    const QString path = m_dir.filePath("typos.json");
    QVERIFY(m_window->document()->save(path));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    root["frobnicate"] = 1;
    root["colour_typo"] = 2;
    QJsonArray bodies = root["bodies"].toArray();
    QJsonObject first = bodies[0].toObject();
    first["spinn"] = 3;
    bodies[0] = first;
    root["bodies"] = bodies;
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QJsonDocument(root).toJson());
    file.close();

    QVERIFY(m_window->documentManager()->open(path));
    QCOMPARE(m_window->document()->loadWarnings().size(), 3);
    const QString shown = m_window->statusBar()->currentMessage();
    for (const QString& key : QStringList{"frobnicate", "colour_typo", "spinn"}) {
        QVERIFY2(shown.contains(key), qPrintable(key + " missing from: " + shown));
    }
    // Longer than the status bar has room for: the full text is its tooltip.
    QCOMPARE(m_window->statusBar()->toolTip(), shown);
}

void TestEditorKeys::fieldsShowNumbersThatFit() {
    m_window->document()->setSelectedBodies({1});
    interplay::InspectorPanel* inspector = m_window->inspector();
    const auto fits = [](const QLineEdit* field) {
        return field->fontMetrics().horizontalAdvance(field->text()) < field->contentsRect().width();
    };
    // A wide field shows six digits.
    interplay::NumberField* friction = inspector->numberField("friction");
    QTRY_VERIFY(friction->isVisible());
    QTest::mouseClick(friction, Qt::LeftButton);
    friction->selectAll();
    QTest::keyClicks(friction, "0.123456");
    QTest::keyClick(friction, Qt::Key_Return);
    QCOMPARE(friction->text(), QString("0.123456"));

    // A vector component too narrow for six digits of 1.29314e-06 shows fewer, never a cut tail;
    // the tooltip has the six.
    interplay::NumberField* x = inspector->numberField("position.x");
    QTest::mouseClick(x, Qt::LeftButton);
    x->selectAll();
    QTest::keyClicks(x, "1.29314e-06");
    QTest::keyClick(x, Qt::Key_Return);
    QCOMPARE(m_window->document()->body(1).body.position.x, 1.29314e-06f);
    QVERIFY2(fits(x), qPrintable(x->text()));
    const auto shown = x->parse(x->text());
    QVERIFY(std::holds_alternative<double>(shown));
    QVERIFY(std::abs(std::get<double>(shown) - 1.29314e-06) < 0.1e-06);
    QVERIFY2(x->toolTip().contains("1.29314e-06"), qPrintable(x->toolTip()));
    // Tabbing through the shortened text changes nothing.
    const int entries = history()->count();
    QTest::mouseClick(x, Qt::LeftButton);
    QTest::keyClick(x, Qt::Key_Return);
    QCOMPARE(history()->count(), entries);
    QCOMPARE(m_window->document()->body(1).body.position.x, 1.29314e-06f);
}

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorKeys test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_keys.moc"
