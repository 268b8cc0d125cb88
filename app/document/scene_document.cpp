#include "app/document/scene_document.h"

#include "app/document/scene_edits.h"

#include "simcore/io/mesh_import.h"
#include "simcore/io/scene_io.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QUndoStack>

#include <algorithm>
#include <exception>

namespace interplay {
namespace {

// The loader detects the format itself; the document only needs to know whether to treat the file
// as an import. A thesis file has an "objects" array and no "format" tag.
bool isThesisFormat(const QByteArray& text) {
    const QJsonObject root = QJsonDocument::fromJson(text).object();
    return !root.contains(QStringLiteral("format")) && root.value(QStringLiteral("objects")).isArray();
}

}  // namespace

simcore::SceneReadOptions sceneReadOptions(const QString& sceneFolder) {
    simcore::SceneReadOptions options;
    options.sceneFolder = QFile::encodeName(sceneFolder).toStdString();
    options.loadMeshFile = simcore::importMeshFile;
    return options;
}

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent), m_undoStack(new QUndoStack(this)) {
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

SceneDocument::~SceneDocument() {
    // The undo stack (a child, destroyed after this destructor) emits cleanChanged as it clears.
    m_undoStack->disconnect(this);
}

QString SceneDocument::displayName() const {
    if (!m_filePath.isEmpty()) return QFileInfo(m_filePath).fileName();
    if (!m_nameWithoutFile.isEmpty()) return m_nameWithoutFile;
    return tr("Untitled");
}

bool SceneDocument::isModified() const {
    return !m_undoStack->isClean();
}

bool SceneDocument::load(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    // The loader's limit (test_editor_soak checks that both give this message), checked on the
    // file's size, so a huge file is refused without reading it into memory.
    if (static_cast<std::uintmax_t>(file.size()) > simcore::kMaxSceneFileBytes) {
        simcore::Diagnostic tooLarge;
        tooLarge.file = path.toStdString();
        tooLarge.message = "the file is larger than " + std::to_string(simcore::kMaxSceneFileBytes >> 20) + " MiB; it is not a scene";
        if (error) *error = QString::fromStdString(tooLarge.toString());
        return false;
    }
    const QByteArray text = file.readAll();
    simcore::SceneLoadResult result;
    try {
        result = simcore::parseScene(std::string_view(text.constData(), static_cast<std::size_t>(text.size())),
                                     path.toStdString(), sceneReadOptions(QFileInfo(path).absolutePath()));
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
    const QFileInfo info(path);
    if (isThesisFormat(text)) {
        m_nameWithoutFile = tr("%1 (imported)").arg(info.fileName());
        replaceScene(std::move(*result.scene), QString(), true);
    } else {
        m_nameWithoutFile.clear();
        replaceScene(std::move(*result.scene), info.absoluteFilePath(), false);
    }
    return true;
}

bool SceneDocument::loadExample(const QString& path, QString* error) {
    if (!load(path, error)) return false;
    if (m_filePath.isEmpty()) return true;  // a thesis scene is imported without its path already
    m_nameWithoutFile = tr("%1 (example)").arg(QFileInfo(m_filePath).completeBaseName());
    setFilePath(QString());
    return true;
}

bool SceneDocument::save(const QString& path, QString* error) {
    // Mesh file references are rewritten relative to the folder saved to (Save As elsewhere).
    const std::string text = simcore::serializeScene(m_scene, QFile::encodeName(QFileInfo(path).absolutePath()).toStdString());
    // QSaveFile writes a temporary file and renames it over the target on commit(): a failure at
    // any point leaves the old file as it was.
    QSaveFile file(path);
    const bool written = file.open(QIODevice::WriteOnly) &&
                         file.write(text.data(), static_cast<qint64>(text.size())) == static_cast<qint64>(text.size()) &&
                         file.commit();
    if (!written) {
        if (error) *error = tr("%1 could not be written: %2").arg(path, file.errorString());
        return false;
    }
    m_nameWithoutFile.clear();
    setFilePath(QFileInfo(path).absoluteFilePath());
    m_undoStack->setClean();
    emit saved(m_filePath);
    return true;
}

void SceneDocument::newDefault() {
    m_loadWarnings.clear();
    m_nameWithoutFile.clear();
    replaceScene(simcore::defaultScene(), QString(), false);
}

void SceneDocument::newEmpty() {
    simcore::Scene scene = simcore::defaultScene();
    std::erase_if(scene.bodies, [](const simcore::SceneBody& b) { return b.body.motion != simcore::MotionType::Static; });
    m_loadWarnings.clear();
    m_nameWithoutFile.clear();
    replaceScene(std::move(scene), QString(), false);
}

void SceneDocument::restoreRecovered(simcore::Scene scene, const QString& originalPath) {
    m_loadWarnings.clear();
    m_nameWithoutFile.clear();
    replaceScene(std::move(scene), originalPath, true);
}

QString SceneDocument::uniqueBodyName(const QString& base, const QStringList& alsoTaken) const {
    for (int n = 1;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        const std::string name = candidate.toStdString();
        const bool used = alsoTaken.contains(candidate) ||
                          std::any_of(m_scene.bodies.begin(), m_scene.bodies.end(),
                                      [&](const simcore::SceneBody& b) { return b.body.name == name; });
        if (!used) return candidate;
    }
}

QString SceneDocument::uniqueJointName(const QString& base, const QStringList& alsoTaken) const {
    for (int n = 1;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        const std::string name = candidate.toStdString();
        const bool used = alsoTaken.contains(candidate) ||
                          std::any_of(m_scene.joints.begin(), m_scene.joints.end(),
                                      [&](const simcore::SceneJoint& j) { return j.joint.name == name; });
        if (!used) return candidate;
    }
}

QString SceneDocument::jointName(int index) const {
    const simcore::JointCreationSettings& settings = joint(index).joint;
    if (!settings.name.empty()) return QString::fromStdString(settings.name);
    return tr("%1 joint").arg(QString::fromLatin1(simcore::jointTypeName(settings.type)));
}

QString SceneDocument::jointProblem(const simcore::SceneJoint& joint) const {
    // The loader's checks, on the scene with the joint in it.
    simcore::Scene candidate = m_scene;
    candidate.joints.push_back(joint);
    for (const simcore::Diagnostic& d : simcore::checkScene(candidate))
        if (d.severity == simcore::Diagnostic::Severity::Error) return QString::fromStdString(d.message);
    return {};
}

QString SceneDocument::bodyNameProblem(int index, const QString& name) const {
    if (name.trimmed().isEmpty()) return tr("A body needs a name.");
    const std::string wanted = name.toStdString();
    for (int other = 0; other < bodyCount(); ++other) {
        if (other == index || m_scene.bodies[static_cast<std::size_t>(other)].body.name != wanted) continue;
        if (!jointsOf(index).isEmpty() || !jointsOf(other).isEmpty())
            return tr("Another body is called \"%1\", and a joint names its bodies in the file: choose a name of "
                      "its own.")
                .arg(name);
    }
    return {};
}

void SceneDocument::setSelection(QList<int> bodies, QList<int> joints) {
    const auto tidy = [](QList<int>& indices, int count) {
        std::sort(indices.begin(), indices.end());
        indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
        indices.removeIf([count](int i) { return i < 0 || i >= count; });
    };
    tidy(bodies, bodyCount());
    tidy(joints, jointCount());
    if (bodies == m_selection && joints == m_selectedJoints) return;
    m_selection = std::move(bodies);
    m_selectedJoints = std::move(joints);
    emit selectionChanged();
}

void SceneDocument::insertBody(int index, simcore::SceneBody body) {
    Q_ASSERT(index >= 0 && index <= bodyCount());
    emit bodyAboutToBeInserted(index);
    insertSceneBody(m_scene, index, std::move(body));
    renumberSelection([index](int i) { return indexAfterInsert(i, index); });
    emit bodyInserted(index);
}

simcore::SceneBody SceneDocument::takeBody(int index) {
    Q_ASSERT(index >= 0 && index < bodyCount());
    Q_ASSERT(jointsOf(index).isEmpty());
    emit bodyAboutToBeRemoved(index);
    simcore::SceneBody body = takeSceneBody(m_scene, index);
    const bool wasSelected = m_selection.removeAll(index) > 0;
    renumberSelection([index](int i) { return indexAfterRemove(i, index); });
    emit bodyRemoved(index);
    if (wasSelected) emit selectionChanged();
    return body;
}

void SceneDocument::moveBody(int from, int to) {
    Q_ASSERT(from >= 0 && from < bodyCount() && to >= 0 && to < bodyCount());
    if (from == to) return;
    emit bodyAboutToBeMoved(from, to);
    // Selection and joints follow the bodies, not the rows.
    moveSceneBody(m_scene, from, to);
    renumberSelection([from, to](int i) { return indexAfterMove(i, from, to); });
    emit bodyMoved(from, to);
}

void SceneDocument::renumberSelection(const std::function<int(int)>& newIndex) {
    for (int& selected : m_selection) selected = newIndex(selected);
    std::sort(m_selection.begin(), m_selection.end());
}

void SceneDocument::insertJoint(int index, simcore::SceneJoint joint) {
    Q_ASSERT(index >= 0 && index <= jointCount());
    emit jointAboutToBeInserted(index);
    m_scene.joints.insert(m_scene.joints.begin() + index, std::move(joint));
    for (int& selected : m_selectedJoints) selected = indexAfterInsert(selected, index);
    emit jointInserted(index);
}

simcore::SceneJoint SceneDocument::takeJoint(int index) {
    Q_ASSERT(index >= 0 && index < jointCount());
    emit jointAboutToBeRemoved(index);
    simcore::SceneJoint joint = std::move(m_scene.joints[static_cast<std::size_t>(index)]);
    m_scene.joints.erase(m_scene.joints.begin() + index);
    const bool wasSelected = m_selectedJoints.removeAll(index) > 0;
    for (int& selected : m_selectedJoints) selected = indexAfterRemove(selected, index);
    emit jointRemoved(index);
    if (wasSelected) emit selectionChanged();
    return joint;
}

QList<int> SceneDocument::jointsOf(int index) const {
    QList<int> attached;
    const auto body = static_cast<std::size_t>(index);
    for (std::size_t j = 0; j < m_scene.joints.size(); ++j) {
        const simcore::SceneJoint& joint = m_scene.joints[j];
        if (joint.bodyA == body || joint.bodyB == body) attached << static_cast<int>(j);
    }
    return attached;
}

void SceneDocument::setBody(int index, simcore::SceneBody body, BodyField field) {
    m_scene.bodies.at(static_cast<std::size_t>(index)) = std::move(body);
    emit bodyChanged(index, field);
}

void SceneDocument::setJoint(int index, simcore::SceneJoint joint, JointField field) {
    m_scene.joints.at(static_cast<std::size_t>(index)) = std::move(joint);
    emit jointChanged(index, field);
}

void SceneDocument::setSettings(const simcore::WorldSettings& settings) {
    m_scene.settings = settings;
    emit settingsChanged();
}

void SceneDocument::setCameraBookmarks(std::vector<simcore::CameraBookmark> bookmarks) {
    m_scene.editor.cameraBookmarks = std::move(bookmarks);
    emit cameraBookmarksChanged();
}

void SceneDocument::replaceScene(simcore::Scene scene, const QString& filePath, bool startModified) {
    m_scene = std::move(scene);
    m_selection.clear();
    m_selectedJoints.clear();
    // History refers to the old scene; a fresh document starts with no history.
    m_undoStack->clear();
    if (startModified) {
        m_undoStack->resetClean();  // no reachable clean state: modified until saved
    } else {
        m_undoStack->setClean();
    }
    emit modifiedChanged(isModified());
    setFilePath(filePath);
    emit sceneReplaced();
    emit selectionChanged();
}

void SceneDocument::setFilePath(const QString& filePath) {
    if (m_filePath == filePath) return;
    m_filePath = filePath;
    emit filePathChanged(m_filePath);
}

}  // namespace interplay
