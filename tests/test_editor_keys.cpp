// The editor's keyboard and file-safety behaviour, in the whole window with real OpenGL under Xvfb
// and real QTest key and mouse events: File → Revert asks first and is undoable.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include "simcore/io/scene_io.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

using interplay::DocumentManager;
using interplay::MainWindow;

namespace {

std::string sceneText(const simcore::Scene& scene) { return simcore::serializeScene(scene); }

}  // namespace

class TestEditorKeys : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();

    void revertAsksFirstAndIsUndoable();

private:
    QUndoStack* history() const { return m_window->document()->undoStack(); }

    std::unique_ptr<MainWindow> m_window;
    QStringList m_questions;
    bool m_confirmAnswer = true;
    QString m_fileAnswer;
    QTemporaryDir m_dir;
};

void TestEditorKeys::initTestCase() {
    // Settings and recovery files of this process's own, never the user's.
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("InterplayTests");
    QCoreApplication::setApplicationName(QString("test_editor_keys-%1").arg(QCoreApplication::applicationPid()));
    QVERIFY(m_dir.isValid());
}

void TestEditorKeys::cleanupTestCase() {
    QFile::remove(QSettings().fileName());
    QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
}

void TestEditorKeys::init() {
    QSettings().clear();
    QFile::remove(DocumentManager::recoveryFilePath());
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
    m_window->resize(1400, 900);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->viewport()->grabViewport();
}

void TestEditorKeys::cleanup() {
    if (m_window) {
        history()->setClean();  // close without a prompt
        m_window->close();
    }
    m_window.reset();
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

// The viewport needs GL 3.3 core, set before the application creates any window (as main() does).
int main(int argc, char* argv[]) {
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());
    QApplication app(argc, argv);
    TestEditorKeys test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_editor_keys.moc"
