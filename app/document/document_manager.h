#pragma once
// File handling for one SceneDocument, as Tiled's DocumentManager: New, Open, Save, Save As and
// Revert with their questions, recent files (QSettings), watching the file for changes by other
// programs, autosave and crash recovery. It needs no widgets: every question to the user goes
// through replaceable Prompts (the window answers them with dialogs, tests with lambdas), and
// passing notes go out as statusMessage.

#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>

class QFileSystemWatcher;
class QTimer;

namespace interplay {

class SceneDocument;

class DocumentManager : public QObject {
    Q_OBJECT

public:
    enum class UnsavedChoice { Save, Discard, Cancel };
    enum class FileChoice { Open, Save };
    struct Prompts {
        // "Save changes to NAME?" before they would be lost.
        std::function<UnsavedChoice(const QString& documentName)> unsavedChanges;
        // A yes/no question (reload a file changed on disk, recover an autosave).
        std::function<bool(const QString& title, const QString& question)> confirm;
        // Something failed: a headline and the details (file, JSON path, reason).
        std::function<void(const QString& title, const QString& text, const QString& details)> error;
        // A file to open or save as; empty when cancelled.
        std::function<QString(FileChoice choice, const QString& title, const QString& directory)> chooseFile;
    };

    // Until the owner sets prompts, every question is answered as if cancelled and errors go to
    // the log, so nothing is lost silently and nothing waits on a dialog.
    explicit DocumentManager(SceneDocument* document, QObject* parent = nullptr);

    SceneDocument* document() const { return m_document; }
    Prompts& prompts() { return m_prompts; }

    // Loads a scene file into the document without asking anything; on failure the document is
    // unchanged and *error says why (the caller decides how to show it).
    bool openFile(const QString& path, QString* error = nullptr);

    // The interactive file commands, as the menus run them: they ask before losing changes and
    // report failures through the prompts. Each returns whether it went through.
    bool newScene();
    bool open(const QString& path);
    // A shipped example as an untitled copy ("NAME (example)"): Save asks where to write it.
    bool openExample(const QString& path);
    bool openChosenFile();     // asks for a file, beside the current one or among the examples
    bool importThesisScene();  // asks for a scene of the 2018 thesis app among the examples
    bool save();
    bool saveAs();
    // Asks before dropping unsaved changes, then makes the scene the file's again as one undoable
    // step (the history stays, and the document is clean after it).
    bool revert();
    // Asks to save unsaved changes; false when the user cancels (the caller must not go on).
    bool maybeSave();

    // Absolute paths, most recent first, without duplicates, at most kMaxRecentFiles.
    QStringList recentFiles() const;
    void clearRecentFiles();
    static constexpr int kMaxRecentFiles = 10;
    // Where the example scenes are (the repository's scenes/ folder, or one beside the program).
    static QString examplesDirectory();

    // Crash recovery: the unsaved document is written to recoveryFilePath() every interval.
    static QString recoveryFilePath();
    void setAutosaveInterval(int milliseconds);
    void autosaveNow();
    // At start-up: if an earlier session left a recovery file, offers to restore it. Returns
    // whether a scene was recovered.
    bool offerRecovery();
    // A normal exit, or a save, leaves nothing to recover.
    void removeRecoveryFile();

signals:
    void recentFilesChanged();
    // A passing note for a status bar (saved, opened with warnings, autosave failed).
    void statusMessage(const QString& message, int timeoutMs);

private:
    bool saveTo(const QString& path);
    // The last load's warnings, on the status bar.
    void reportLoadWarnings();
    // Revert without the question (the file changed on disk and the user said reload).
    bool reloadFile();
    void addRecentFile(const QString& path);
    void watchDocumentFile();
    void documentFileChanged(const QString& path);
    void askAboutOutsideChange();

    SceneDocument* m_document;
    Prompts m_prompts;
    QTimer* m_autosaveTimer;
    QFileSystemWatcher* m_watcher;
    QTimer* m_outsideWriteSettled;  // restarted by every change: the question waits for the last
    bool m_askingAboutOutsideChange = false;
    QString m_expectedFileStamp;  // size and time of the file as we last read or wrote it
};

}  // namespace interplay
