// Help in the whole window under Xvfb with real key events: F1 opens a non-modal list of every
// editor control and Escape closes it; Help → About Interplay names the program, its version and
// Qt's; every control the app lists is a row of README.md's controls table, so the two stay in sync.

#include "app/document/scene_document.h"
#include "app/help_dialog.h"
#include "app/main_window.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTableWidget>
#include <QTest>
#include <QRegularExpression>
#include <QTimer>
#include <QUndoStack>

#include <memory>

using interplay::MainWindow;

namespace {

// README.md's controls table as "input | does" lines, with markdown code marks dropped as the app
// shows plain text.
QStringList readmeControlRows() {
    QFile readme(QStringLiteral(INTERPLAY_SOURCE_DIR "/README.md"));
    if (!readme.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
    const QStringList lines = QString::fromUtf8(readme.readAll()).split('\n');
    const qsizetype header = lines.indexOf(QStringLiteral("| input | does |"));
    QStringList rows;
    if (header < 0) return rows;
    for (qsizetype i = header + 2; i < lines.size() && lines[i].startsWith('|'); ++i) {
        rows << QString(lines[i]).remove('`').trimmed();
    }
    return rows;
}

// The version CMake's project() gives, read from the top-level CMakeLists.txt.
QString projectVersion() {
    QFile lists(QStringLiteral(INTERPLAY_SOURCE_DIR "/CMakeLists.txt"));
    if (!lists.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
    const auto match = QRegularExpression(QStringLiteral("project\\(Interplay VERSION ([0-9.]+)"))
                           .match(QString::fromUtf8(lists.readAll()));
    return match.captured(1);
}

QString tableRow(const interplay::EditorControl& control) {
    return QStringLiteral("| %1 | %2 |").arg(QString::fromUtf8(control.input), QString::fromUtf8(control.does));
}

}  // namespace

class TestEditorHelp : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void everyControlIsInTheReadme();
    void f1ShowsEveryControlAndEscapeCloses();
    void aboutNamesVersionAndQt();

private:
    std::unique_ptr<MainWindow> m_window;
};

void TestEditorHelp::initTestCase() { test_support::isolateSettings("test_editor_help"); }

void TestEditorHelp::cleanupTestCase() { test_support::removeSettings(); }

void TestEditorHelp::init() {
    test_support::clearSettings();
    m_window = std::make_unique<MainWindow>();
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
}

void TestEditorHelp::cleanup() {
    test_support::closeWithoutPrompt(m_window);
}

void TestEditorHelp::everyControlIsInTheReadme() {
    const QStringList readme = readmeControlRows();
    QVERIFY2(!readme.isEmpty(), "README.md has no \"| input | does |\" controls table");
    QVERIFY(!interplay::editorControls().empty());
    for (const interplay::EditorControl& control : interplay::editorControls()) {
        QVERIFY2(readme.contains(tableRow(control)),
                 qPrintable(QStringLiteral("README.md's controls table lacks the row: %1").arg(tableRow(control))));
    }
    // And the README lists nothing the app does not.
    QCOMPARE(readme.size(), qsizetype(interplay::editorControls().size()));
}

void TestEditorHelp::f1ShowsEveryControlAndEscapeCloses() {
    QVERIFY(!m_window->findChild<interplay::HelpDialog*>());
    QTest::keyClick(m_window.get(), Qt::Key_F1);
    auto* dialog = m_window->findChild<interplay::HelpDialog*>();
    QVERIFY(dialog);
    QTRY_VERIFY(dialog->isVisible());
    QVERIFY(!dialog->isModal());
    QVERIFY(!QApplication::activeModalWidget());

    auto* table = dialog->findChild<QTableWidget*>(QStringLiteral("controlsTable"));
    QVERIFY(table);
    const auto controls = interplay::editorControls();
    QCOMPARE(table->rowCount(), int(controls.size()));
    for (int row = 0; row < table->rowCount(); ++row) {
        QCOMPARE(table->item(row, 0)->text(), QString::fromUtf8(controls[row].input));
        QCOMPARE(table->item(row, 1)->text(), QString::fromUtf8(controls[row].does));
    }
    // F1 itself is listed, so the list tells how to find it again.
    QVERIFY(!table->findItems(QStringLiteral("F1"), Qt::MatchExactly).isEmpty());

    if (qEnvironmentVariableIsSet("INTERPLAY_HELP_SCREENSHOT")) {
        QTest::qWait(300);
        dialog->grab().save(qEnvironmentVariable("INTERPLAY_HELP_SCREENSHOT"));
    }

    QTRY_COMPARE(QApplication::activeWindow(), dialog);
    QTest::keyClick(dialog, Qt::Key_Escape);
    QTRY_VERIFY(!dialog->isVisible());

    // A second F1 shows the same window again rather than a second one.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QTest::keyClick(m_window.get(), Qt::Key_F1);
    QTRY_VERIFY(dialog->isVisible());
    QCOMPARE(m_window->findChildren<interplay::HelpDialog*>().size(), 1);
}

void TestEditorHelp::aboutNamesVersionAndQt() {
    auto* help = m_window->menuBar()->findChild<QMenu*>(QStringLiteral("helpMenu"));
    QVERIFY(help);
    QAction* about = m_window->action(QStringLiteral("about"));
    QVERIFY(about);
    QVERIFY(help->actions().contains(about));
    QVERIFY(help->actions().contains(m_window->action(QStringLiteral("helpControls"))));

    // QMessageBox::about waits in its own loop: read and close it from inside that loop.
    QString shownText;
    bool closed = false;
    QTimer::singleShot(0, this, [&] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        QVERIFY(box);
        shownText = box->text();
        box->close();
        closed = true;
    });
    about->trigger();
    QVERIFY(closed);
    const QString version = projectVersion();
    QVERIFY2(!version.isEmpty(), "no VERSION in the top-level project()");
    QVERIFY2(shownText.contains(QStringLiteral("Interplay ") + version), qPrintable(shownText));
    QVERIFY2(shownText.contains(QString::fromLatin1(qVersion())), qPrintable(shownText));
    QVERIFY2(shownText.contains(QStringLiteral("simcore")), qPrintable(shownText));
}

QTEST_MAIN(TestEditorHelp)
#include "test_editor_help.moc"
