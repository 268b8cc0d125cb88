// DocumentManager on its own, under a QCoreApplication: the model layer's file handling needs no
// window and no GUI. Without prompts set it never loses work (every question answered as
// cancelled); with them, Save As, Revert, recent files, autosave and recovery work as in the editor
// (test_main_window covers them through the window's menus).

#include "app/document/body_templates.h"
#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"

#include "simcore/io/scene_io.h"

#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using interplay::DocumentManager;
using interplay::SceneDocument;

namespace {

// One edit, so the document has unsaved changes.
void addBox(SceneDocument& document) {
    const QString name = document.uniqueBodyName(QStringLiteral("Box"));
    document.undoStack()->push(
        new interplay::AddBodies(&document, "Add " + name, {document.bodyCount()},
                                 {interplay::templateBody(simcore::ShapeType::Box, name, {0.0f, 0.5f, 0.0f})}));
}

}  // namespace

class TestDocumentManager : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanupTestCase();
    void unansweredQuestionsKeepTheWork();
    void saveAsRecordsTheFileAndReportsNothingToRecover();
    void autosaveIsRecoveredIntoAFreshDocument();
    void revertAsksAndKeepsTheHistory();
    void anOutsideWriteInPiecesIsAskedAboutOnce();

private:
    QTemporaryDir m_dir;
};

void TestDocumentManager::initTestCase() {
    // A settings file and recovery folder of this process's own (see test_main_window).
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("InterplayTests");
    QCoreApplication::setApplicationName(QString("test_document_manager-%1").arg(QCoreApplication::applicationPid()));
    QVERIFY(m_dir.isValid());
}

void TestDocumentManager::init() {
    QSettings().clear();
    QFile::remove(DocumentManager::recoveryFilePath());
}

void TestDocumentManager::cleanupTestCase() {
    QFile::remove(QSettings().fileName());
    QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
}

void TestDocumentManager::unansweredQuestionsKeepTheWork() {
    SceneDocument document;
    DocumentManager files(&document);
    document.newDefault();
    addBox(document);
    const int bodies = document.bodyCount();
    QVERIFY(document.isModified());

    QVERIFY(!files.maybeSave());
    QVERIFY(!files.newScene());
    QVERIFY(!files.open(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    QVERIFY(!files.saveAs());  // no file chosen
    QCOMPARE(document.bodyCount(), bodies);
    QVERIFY(document.isModified());
    QVERIFY(files.recentFiles().isEmpty());
}

void TestDocumentManager::saveAsRecordsTheFileAndReportsNothingToRecover() {
    SceneDocument document;
    DocumentManager files(&document);
    const QString path = m_dir.filePath("saved");  // no suffix: Save As adds .json
    files.prompts().chooseFile = [&](DocumentManager::FileChoice choice, const QString&, const QString&) {
        return choice == DocumentManager::FileChoice::Save ? path : QString();
    };
    document.newDefault();
    addBox(document);
    files.autosaveNow();
    QVERIFY(QFile::exists(DocumentManager::recoveryFilePath()));

    QVERIFY(files.saveAs());
    QCOMPARE(document.filePath(), path + ".json");
    QVERIFY(!document.isModified());
    QCOMPARE(files.recentFiles(), QStringList{path + ".json"});
    QVERIFY(!QFile::exists(DocumentManager::recoveryFilePath()));  // saved work needs no recovery

    QSignalSpy status(&files, &DocumentManager::statusMessage);
    addBox(document);
    QVERIFY(files.save());  // to the same file, without asking
    QCOMPARE(status.count(), 1);
    QVERIFY(status.first().first().toString().contains(path + ".json"));
}

void TestDocumentManager::autosaveIsRecoveredIntoAFreshDocument() {
    const QString path = m_dir.filePath("origin.json");
    int bodies = 0;
    {
        SceneDocument document;
        DocumentManager files(&document);
        QVERIFY(files.openFile(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
        QVERIFY(document.save(path));
        addBox(document);
        bodies = document.bodyCount();
        files.autosaveNow();
    }  // as if the program had died: nothing removed the recovery file

    SceneDocument document;
    DocumentManager files(&document);
    QStringList questions;
    files.prompts().confirm = [&](const QString&, const QString& question) {
        questions << question;
        return true;
    };
    QVERIFY(files.offerRecovery());
    QCOMPARE(questions.size(), 1);
    QVERIFY2(questions.first().contains("origin.json"), qPrintable(questions.first()));
    QCOMPARE(document.bodyCount(), bodies);
    QCOMPARE(document.filePath(), path);  // Save goes back to the file the work belongs to
    QVERIFY(document.isModified());
}

void TestDocumentManager::revertAsksAndKeepsTheHistory() {
    SceneDocument document;
    DocumentManager files(&document);
    document.newDefault();
    QVERIFY(!files.revert());  // no file to go back to
    const QString path = m_dir.filePath("revert.json");
    QVERIFY(document.save(path));
    const std::string saved = simcore::serializeScene(document.scene());
    addBox(document);
    document.undoStack()->push(new interplay::RemoveBodies(&document, {1}));
    const std::string edited = simcore::serializeScene(document.scene());

    QVERIFY(!files.revert());  // unanswered: the work stays
    QCOMPARE(simcore::serializeScene(document.scene()), edited);

    QStringList questions;
    files.prompts().confirm = [&](const QString&, const QString& question) {
        questions << question;
        return true;
    };
    QVERIFY(files.revert());
    QCOMPARE(questions.size(), 1);
    QCOMPARE(simcore::serializeScene(document.scene()), saved);
    QVERIFY(!document.isModified());
    document.undoStack()->undo();
    QCOMPARE(simcore::serializeScene(document.scene()), edited);
    QVERIFY(document.isModified());
    document.undoStack()->undo();  // the history before the revert is intact
    document.undoStack()->undo();
    QCOMPARE(simcore::serializeScene(document.scene()), saved);
}

void TestDocumentManager::anOutsideWriteInPiecesIsAskedAboutOnce() {
    SceneDocument document;
    DocumentManager files(&document);
    document.newDefault();
    const QString path = m_dir.filePath("pieces.json");
    QVERIFY(document.save(path));
    QStringList questions;
    files.prompts().confirm = [&](const QString&, const QString& question) {
        questions << question;
        return true;
    };

    // Another program rewrites the file in place, not atomically: it truncates it, and the watcher
    // sees that, before it writes the new scene a moment later.
    SceneDocument other;
    QVERIFY(other.load(INTERPLAY_SOURCE_DIR "/scenes/incline.json"));
    const QByteArray text = QByteArray::fromStdString(simcore::serializeScene(other.scene()));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.flush();
    QTest::qWait(100);
    file.write(text.left(text.size() / 2));
    file.flush();
    QTest::qWait(100);
    file.write(text.mid(text.size() / 2));
    file.close();

    QTRY_COMPARE_WITH_TIMEOUT(questions.size(), 1, 5000);
    QTest::qWait(1000);  // and no second question once the writes have settled
    QCOMPARE(questions.size(), 1);
    QCOMPARE(simcore::serializeScene(document.scene()), simcore::serializeScene(other.scene()));
}

QTEST_GUILESS_MAIN(TestDocumentManager)
#include "test_document_manager.moc"
