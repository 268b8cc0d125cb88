#include "app/document/document_manager.h"

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"

#include "simcore/io/scene_io.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QSaveFile>
#include <QScopedValueRollback>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>
#include <QtDebug>

#include <numeric>

namespace interplay {
namespace {

constexpr int kDefaultAutosaveMs = 60'000;
// A program that rewrites a file in place (truncate, then write, perhaps in pieces) sends a change
// per piece: the question waits until the file has been quiet this long, so it is asked once.
constexpr int kOutsideWriteSettleMs = 300;
const QString kRecentFilesKey = QStringLiteral("recentFiles");

// Size and modification time: what tells our own write apart from another program's.
QString fileStamp(const QString& path) {
    const QFileInfo info(path);
    if (!info.exists()) return {};
    return QStringLiteral("%1@%2").arg(info.size()).arg(info.lastModified().toMSecsSinceEpoch());
}

QString recoveryMetaPath() { return DocumentManager::recoveryFilePath() + QStringLiteral(".origin"); }

DocumentManager::Prompts unansweredPrompts() {
    DocumentManager::Prompts prompts;
    prompts.unsavedChanges = [](const QString&) { return DocumentManager::UnsavedChoice::Cancel; };
    prompts.confirm = [](const QString&, const QString&) { return false; };
    prompts.error = [](const QString& title, const QString& text, const QString& details) {
        qWarning().noquote() << title << ":" << text << details;
    };
    prompts.chooseFile = [](DocumentManager::FileChoice, const QString&, const QString&) { return QString(); };
    return prompts;
}

}  // namespace

DocumentManager::DocumentManager(SceneDocument* document, QObject* parent)
    : QObject(parent),
      m_document(document),
      m_prompts(unansweredPrompts()),
      m_autosaveTimer(new QTimer(this)),
      m_watcher(new QFileSystemWatcher(this)),
      m_outsideWriteSettled(new QTimer(this)) {
    connect(m_document, &SceneDocument::filePathChanged, this, &DocumentManager::watchDocumentFile);
    connect(m_document, &SceneDocument::saved, this, &DocumentManager::watchDocumentFile);
    // A clean scene (new, opened, reverted) makes any earlier autosave stale.
    connect(m_document, &SceneDocument::sceneReplaced, this, [this] {
        if (!m_document->isModified()) removeRecoveryFile();
    });
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &DocumentManager::documentFileChanged);
    m_outsideWriteSettled->setSingleShot(true);
    m_outsideWriteSettled->setInterval(kOutsideWriteSettleMs);
    connect(m_outsideWriteSettled, &QTimer::timeout, this, &DocumentManager::askAboutOutsideChange);
    connect(m_autosaveTimer, &QTimer::timeout, this, &DocumentManager::autosaveNow);
    m_autosaveTimer->start(kDefaultAutosaveMs);
}

// ---- Opening and saving ------------------------------------------------------------------------

bool DocumentManager::openFile(const QString& path, QString* error) {
    if (!m_document->load(path, error)) return false;
    addRecentFile(path);
    reportLoadWarnings();
    return true;
}

void DocumentManager::reportLoadWarnings() {
    const QStringList& warnings = m_document->loadWarnings();
    if (!warnings.isEmpty()) {
        emit statusMessage(tr("Opened with %n warning(s): %1", nullptr, static_cast<int>(warnings.size()))
                               .arg(warnings.join(QStringLiteral("; "))),
                           10000);
    }
}

bool DocumentManager::newScene() {
    if (!maybeSave()) return false;
    m_document->newEmpty();
    return true;
}

bool DocumentManager::open(const QString& path) {
    if (!maybeSave()) return false;
    QString error;
    if (!openFile(path, &error)) {
        m_prompts.error(tr("Open Scene"), tr("The scene \"%1\" could not be opened.").arg(QFileInfo(path).fileName()),
                        error);
        return false;
    }
    return true;
}

bool DocumentManager::openExample(const QString& path) {
    if (!maybeSave()) return false;
    QString error;
    if (!m_document->loadExample(path, &error)) {
        m_prompts.error(tr("Open Example"),
                        tr("The example \"%1\" could not be opened.").arg(QFileInfo(path).fileName()), error);
        return false;
    }
    reportLoadWarnings();  // not a recent file: reopening it from there would open the shipped file
    return true;
}

bool DocumentManager::openChosenFile() {
    const QString dir =
        m_document->filePath().isEmpty() ? examplesDirectory() : QFileInfo(m_document->filePath()).absolutePath();
    const QString path = m_prompts.chooseFile(FileChoice::Open, tr("Open Scene"), dir);
    return !path.isEmpty() && open(path);
}

bool DocumentManager::importThesisScene() {
    const QString path = m_prompts.chooseFile(FileChoice::Open, tr("Import Thesis Scene"),
                                              QDir(examplesDirectory()).filePath(QStringLiteral("thesis")));
    return !path.isEmpty() && open(path);  // the document recognises the format and imports it
}

bool DocumentManager::saveTo(const QString& path) {
    QString error;
    if (!m_document->save(path, &error)) {
        m_prompts.error(tr("Save Scene"), tr("The scene was not saved. The file on disk is unchanged."), error);
        return false;
    }
    removeRecoveryFile();
    return true;
}

bool DocumentManager::save() {
    if (m_document->filePath().isEmpty()) return saveAs();
    if (!saveTo(m_document->filePath())) return false;
    emit statusMessage(tr("Saved %1").arg(m_document->filePath()), 4000);
    return true;
}

bool DocumentManager::saveAs() {
    const QString dir = m_document->filePath().isEmpty() ? QDir::homePath() : m_document->filePath();
    QString path = m_prompts.chooseFile(FileChoice::Save, tr("Save Scene As"), dir);
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    if (!saveTo(path)) return false;
    addRecentFile(path);
    return true;
}

bool DocumentManager::revert() {
    if (m_document->filePath().isEmpty()) return false;
    // Undo brings the edits back, but they would vanish from view on a stray click: ask first.
    if (m_document->isModified() &&
        !m_prompts.confirm(tr("Revert"), tr("Drop the unsaved changes to \"%1\" and go back to the saved file? "
                                            "Edit → Undo brings them back.")
                                             .arg(m_document->displayName()))) {
        return false;
    }
    return reloadFile();
}

bool DocumentManager::reloadFile() {
    SceneDocument saved;  // reads the file as Open would, without touching the document
    QString error;
    if (!saved.load(m_document->filePath(), &error)) {
        m_prompts.error(tr("Revert"), tr("The file could not be read again; the scene is as it was."), error);
        return false;
    }
    const simcore::Scene& scene = saved.scene();
    QUndoStack* history = m_document->undoStack();
    if (simcore::serializeScene(scene) != simcore::serializeScene(m_document->scene())) {
        // One undoable step made of the ordinary edits, as text editors and Qt Creator revert: the
        // history before it stays, so the dropped changes are one Undo away.
        history->beginMacro(tr("Revert to \"%1\"").arg(m_document->displayName()));
        QList<int> bodies(m_document->bodyCount()), joints(m_document->jointCount());
        std::iota(bodies.begin(), bodies.end(), 0);
        std::iota(joints.begin(), joints.end(), 0);
        if (!bodies.isEmpty() || !joints.isEmpty()) history->push(new RemoveBodies(m_document, bodies, joints));
        QList<int> savedBodies(static_cast<qsizetype>(scene.bodies.size()));
        std::iota(savedBodies.begin(), savedBodies.end(), 0);
        if (!savedBodies.isEmpty()) history->push(new AddBodies(m_document, tr("Add Bodies"), savedBodies, scene.bodies));
        for (std::size_t i = 0; i < scene.joints.size(); ++i) {
            history->push(new AddJoint(m_document, tr("Add Joint"), static_cast<int>(i), scene.joints[i]));
        }
        if (!(scene.settings == m_document->scene().settings)) {
            history->push(new ChangeSettings(m_document, tr("Settings"), QString(), scene.settings));
        }
        history->endMacro();
        m_document->setSelection({}, {});
    }
    history->setClean();  // the scene is the file's again
    removeRecoveryFile();
    return true;
}

bool DocumentManager::maybeSave() {
    if (!m_document->isModified()) return true;
    switch (m_prompts.unsavedChanges(m_document->displayName())) {
    case UnsavedChoice::Save: return save();
    case UnsavedChoice::Discard: return true;
    case UnsavedChoice::Cancel: return false;
    }
    return false;
}

// ---- Recent files and examples -------------------------------------------------------------------

QStringList DocumentManager::recentFiles() const { return QSettings().value(kRecentFilesKey).toStringList(); }

void DocumentManager::clearRecentFiles() {
    QSettings().remove(kRecentFilesKey);
    emit recentFilesChanged();
}

void DocumentManager::addRecentFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList files = recentFiles();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    QSettings().setValue(kRecentFilesKey, files);
    emit recentFilesChanged();
}

QString DocumentManager::examplesDirectory() {
    // Installed: scenes/ beside the program. From a build tree: the repository's scenes/.
    const QString beside = QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("scenes"));
    if (QFileInfo(beside).isDir()) return beside;
    return QStringLiteral(INTERPLAY_SCENES_DIR);
}

// ---- Watching the file, autosave and recovery -------------------------------------------------------

void DocumentManager::watchDocumentFile() {
    if (!m_watcher->files().isEmpty()) m_watcher->removePaths(m_watcher->files());
    const QString path = m_document->filePath();
    m_expectedFileStamp = path.isEmpty() ? QString() : fileStamp(path);
    // Saving replaces the file (write and rename), which drops it from the watch: add it again.
    if (!path.isEmpty() && QFileInfo::exists(path)) m_watcher->addPath(path);
}

void DocumentManager::documentFileChanged(const QString& path) {
    if (path != m_document->filePath()) return;
    // Writing in place, or replacing the file, can drop it from the watch: add it again.
    if (QFileInfo::exists(path)) m_watcher->addPath(path);
    m_outsideWriteSettled->start();
}

void DocumentManager::askAboutOutsideChange() {
    const QString path = m_document->filePath();
    if (path.isEmpty() || m_askingAboutOutsideChange) return;  // a change during the question: it reloads the latest
    const QString stamp = fileStamp(path);
    // Deleted (nothing to reload; saving will recreate it), or our own write.
    if (stamp.isEmpty() || stamp == m_expectedFileStamp) return;
    m_expectedFileStamp = stamp;  // ask once per outside change
    const QString name = QFileInfo(path).fileName();
    const QString question =
        m_document->isModified()
            ? tr("\"%1\" was changed by another program. Reload it and lose your unsaved changes?").arg(name)
            : tr("\"%1\" was changed by another program. Reload it?").arg(name);
    const QScopedValueRollback asking(m_askingAboutOutsideChange, true);
    if (m_prompts.confirm(tr("File Changed"), question)) {
        m_expectedFileStamp = fileStamp(path);  // what the reload read
        reloadFile();
    }
}

QString DocumentManager::recoveryFilePath() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("recovery/autosave.json"));
}

void DocumentManager::setAutosaveInterval(int milliseconds) { m_autosaveTimer->start(milliseconds); }

void DocumentManager::autosaveNow() {
    if (!m_document->isModified()) return;
    const QString path = recoveryFilePath();
    QDir().mkpath(QFileInfo(path).absolutePath());
    // Mesh file references relative to the recovery file's folder, where recovery reads them from.
    const std::string text =
        simcore::serializeScene(m_document->scene(), QFile::encodeName(QFileInfo(path).absolutePath()).toStdString());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), static_cast<qint64>(text.size())) < 0 ||
        !file.commit()) {
        emit statusMessage(tr("Autosave failed: %1").arg(file.errorString()), 8000);
        return;
    }
    // Which file the recovered scene belongs to, so Save after recovery goes to the right place.
    QSaveFile origin(recoveryMetaPath());
    if (origin.open(QIODevice::WriteOnly)) {
        origin.write(m_document->filePath().toUtf8());
        origin.commit();
    }
}

void DocumentManager::removeRecoveryFile() {
    QFile::remove(recoveryFilePath());
    QFile::remove(recoveryMetaPath());
}

bool DocumentManager::offerRecovery() {
    const QString path = recoveryFilePath();
    if (!QFileInfo::exists(path)) return false;
    QFile originFile(recoveryMetaPath());
    const QString origin = originFile.open(QIODevice::ReadOnly) ? QString::fromUtf8(originFile.readAll()) : QString();
    const QString name =
        origin.isEmpty() ? tr("an untitled scene") : QStringLiteral("\"%1\"").arg(QFileInfo(origin).fileName());
    if (!m_prompts.confirm(tr("Recover Scene"),
                           tr("Interplay did not close normally. Recover the unsaved changes to %1?").arg(name))) {
        removeRecoveryFile();
        return false;
    }
    const simcore::SceneLoadResult result =
        simcore::loadSceneFile(std::filesystem::path(QFile::encodeName(path).toStdString()),
                               sceneReadOptions(QFileInfo(path).absolutePath()));
    if (!result.ok()) {
        QStringList errors;
        for (const simcore::Diagnostic& d : result.diagnostics) errors << QString::fromStdString(d.toString());
        m_prompts.error(tr("Recover Scene"), tr("The recovery file could not be read."), errors.join(u'\n'));
        return false;
    }
    m_document->restoreRecovered(*result.scene, origin);
    return true;
}

}  // namespace interplay
