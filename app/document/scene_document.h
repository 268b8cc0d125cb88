#pragma once
// The document: the authored scene, its file path and its undo history. "Modified" is derived from
// the undo stack's clean state, so undoing back to the saved state makes the document clean again.
// No widgets here: views and panels observe the document through its signals.

#include "simcore/io/scene.h"

#include <QObject>
#include <QString>
#include <QStringList>

class QUndoStack;

namespace interplay {

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    const simcore::Scene& scene() const { return m_scene; }
    QUndoStack* undoStack() const { return m_undoStack; }

    // Absolute path of the file the scene came from; empty for the built-in default scene.
    QString filePath() const { return m_filePath; }
    // File name for titles, or "Untitled" when the scene has no file.
    QString displayName() const;

    bool isModified() const;

    // Reads a v1 or thesis-format scene. On failure returns false, sets *error to the loader's
    // diagnostics (one per line) and leaves the document as it was.
    bool load(const QString& path, QString* error = nullptr);
    // Warnings of the last successful load (unknown keys and the like), one per entry.
    QStringList loadWarnings() const { return m_loadWarnings; }

    // Replaces the document with the built-in default scene, without a file.
    void newDefault();

signals:
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& filePath);
    // The whole scene was replaced (new, open): views rebuild everything they show.
    void sceneReplaced();

private:
    void replaceScene(simcore::Scene scene, const QString& filePath);

    simcore::Scene m_scene;
    QUndoStack* m_undoStack = nullptr;
    QString m_filePath;
    QStringList m_loadWarnings;
};

}  // namespace interplay
