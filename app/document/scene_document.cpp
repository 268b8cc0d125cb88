#include "app/document/scene_document.h"

#include "simcore/io/scene_io.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

#include <exception>

namespace interplay {

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent), m_undoStack(new QUndoStack(this)) {
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

SceneDocument::~SceneDocument() = default;

QString SceneDocument::displayName() const {
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

bool SceneDocument::isModified() const {
    return !m_undoStack->isClean();
}

bool SceneDocument::load(const QString& path, QString* error) {
    simcore::SceneLoadResult result;
    try {
        // encodeName gives the bytes the file system expects for this path.
        result = simcore::loadSceneFile(std::filesystem::path(QFile::encodeName(path).toStdString()));
    } catch (const std::exception& e) {
        // The loader reports problems as diagnostics; this only guards against the unexpected.
        if (error) *error = tr("%1: %2").arg(path, QString::fromStdString(e.what()));
        return false;
    }

    QStringList errors, warnings;
    for (const simcore::Diagnostic& d : result.diagnostics) {
        (d.severity == simcore::Diagnostic::Severity::Error ? errors : warnings) << QString::fromStdString(d.toString());
    }
    if (!result.ok()) {
        if (error) *error = errors.isEmpty() ? tr("%1: the scene could not be read.").arg(path) : errors.join(u'\n');
        return false;
    }

    m_loadWarnings = warnings;
    replaceScene(std::move(*result.scene), QFileInfo(path).absoluteFilePath());
    return true;
}

void SceneDocument::newDefault() {
    m_loadWarnings.clear();
    replaceScene(simcore::defaultScene(), QString());
}

void SceneDocument::replaceScene(simcore::Scene scene, const QString& filePath) {
    m_scene = std::move(scene);
    // History refers to the old scene; a fresh document starts clean with no history.
    m_undoStack->clear();
    m_undoStack->setClean();
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    emit sceneReplaced();
}

}  // namespace interplay
