#pragma once
// The document: the authored scene, its file path, its undo history and the selection. "Modified"
// is derived from the undo stack's clean state, so undoing back to the saved state makes the
// document clean again; selection changes never touch the stack. No widgets here: views and panels
// observe the document through its signals.
//
// The mutators in the "Edits" section are called by undo commands (undo_commands.h), as in Tiled's
// MapDocument: everything else changes the scene by pushing a command, so every edit is undoable.

#include "simcore/io/scene.h"
#include "simcore/io/scene_io.h"

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>

class QUndoStack;

namespace interplay {

// How the editor reads scene text: mesh files relative to `sceneFolder`, through the importer.
simcore::SceneReadOptions sceneReadOptions(const QString& sceneFolder);

// What an edit of a body changed, so views refresh only what they show of it.
enum class BodyField {
    Name,
    Shape,
    Motion,
    Mass,  // mass or density
    Friction,
    Restitution,
    RollingResistance,
    Position,
    Orientation,
    Pose,  // position, orientation and velocities at once (Apply Simulated Pose)
    Turn,  // position and orientation by one turn of several bodies about their centre (the gizmo)
    LinearVelocity,
    AngularVelocity,
    Color,
    Ccd,
};

// Whether an edit of `field` moves or turns bodies, so that the joints on them ride along.
constexpr bool isPlacementField(BodyField field) {
    return field == BodyField::Position || field == BodyField::Orientation || field == BodyField::Pose ||
           field == BodyField::Turn;
}

// What an edit of a joint changed (continuous edits of the same field merge).
enum class JointField {
    Name,
    Anchor,
    AnchorB,  // a distance joint's point on body B
    Axis,
    Placement,  // anchors and axis together, carried with the bodies (Apply Simulated Pose)
    Limits,   // on/off and bounds
    Motor,    // on/off, speed and maximum force or torque
    Lengths,  // a distance joint's minimum and maximum length
    Spring,
    CollideConnected,
};

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    const simcore::Scene& scene() const { return m_scene; }
    int bodyCount() const { return static_cast<int>(m_scene.bodies.size()); }
    const simcore::SceneBody& body(int index) const { return m_scene.bodies.at(static_cast<std::size_t>(index)); }
    QString bodyName(int index) const { return QString::fromStdString(body(index).body.name); }
    int jointCount() const { return static_cast<int>(m_scene.joints.size()); }
    const simcore::SceneJoint& joint(int index) const { return m_scene.joints.at(static_cast<std::size_t>(index)); }
    // The joint's name, or "hinge joint" for an unnamed one (never its row: rows shift).
    QString jointName(int index) const;
    QUndoStack* undoStack() const { return m_undoStack; }

    // Absolute path of the file the scene is saved in; empty for a new or imported scene.
    QString filePath() const { return m_filePath; }
    // File name for titles; "Untitled" for a new scene, "NAME (imported)" for a thesis import,
    // "NAME (example)" for an example.
    QString displayName() const;
    bool isModified() const;

    // Reads a v1 or thesis-format scene. On failure returns false, sets *error to the loader's
    // diagnostics (file, JSON path and reason, one per line) and leaves the document as it was.
    // A thesis scene is imported: it gets no file path (Save asks where to write v1) and starts
    // modified.
    bool load(const QString& path, QString* error = nullptr);
    // Reads a shipped example as load() does, as an untitled copy: no file path (Save asks where,
    // so the example is never overwritten), clean, titled "NAME (example)".
    bool loadExample(const QString& path, QString* error = nullptr);
    // Writes the scene as v1 through QSaveFile: on any failure the old file is left intact. On
    // success the document takes the path and becomes clean.
    bool save(const QString& path, QString* error = nullptr);
    // Warnings of the last successful load (unknown keys and the like), one per entry.
    QStringList loadWarnings() const { return m_loadWarnings; }

    // The built-in scene the editor starts with: a ground and one body of each shape.
    void newDefault();
    // An empty scene: only the default ground.
    void newEmpty();
    // A scene recovered from an autosave of `originalPath` (empty if it never had a file): takes
    // that path and stays modified until saved.
    void restoreRecovered(simcore::Scene scene, const QString& originalPath);

    // "Box 3": the base name with the smallest number no body uses yet (nor any of `alsoTaken`,
    // names about to be added).
    QString uniqueBodyName(const QString& base, const QStringList& alsoTaken = {}) const;
    // "Joint 2": as uniqueBodyName, among the joints.
    QString uniqueJointName(const QString& base, const QStringList& alsoTaken = {}) const;
    // Why the engine would refuse `joint` between this scene's bodies, or an empty string.
    QString jointProblem(const simcore::SceneJoint& joint) const;
    // Why body `index` cannot be called `name`, or an empty string: joints name their bodies in
    // the file, so a name must stay unique where a joint uses it.
    QString bodyNameProblem(int index, const QString& name) const;

    // ---- Selection (not part of the history; never dirties the document) ----
    // Bodies and joints by index: sorted, deduplicated, out-of-range dropped.
    const QList<int>& selectedBodies() const { return m_selection; }
    const QList<int>& selectedJoints() const { return m_selectedJoints; }
    void setSelection(QList<int> bodies, QList<int> joints);
    void setSelectedBodies(QList<int> indices) { setSelection(std::move(indices), {}); }
    void setSelectedJoints(QList<int> indices) { setSelection({}, std::move(indices)); }

    // ---- Edits: called by undo commands only ----
    // Joints refer to bodies by index: inserting, removing and moving bodies renumbers them. A
    // body must have no joints when it is taken out (RemoveBodies takes its joints first).
    void insertBody(int index, simcore::SceneBody body);
    simcore::SceneBody takeBody(int index);
    void moveBody(int from, int to);  // `to` is the index the body ends up at
    void insertJoint(int index, simcore::SceneJoint joint);
    simcore::SceneJoint takeJoint(int index);
    // Indices of the joints attached to body `index`, ascending.
    QList<int> jointsOf(int index) const;
    void setBody(int index, simcore::SceneBody body, BodyField field);
    void setJoint(int index, simcore::SceneJoint joint, JointField field);
    void setSettings(const simcore::WorldSettings& settings);
    void setCameraBookmarks(std::vector<simcore::CameraBookmark> bookmarks);

signals:
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& filePath);
    // The whole scene was replaced (new, open, revert): views rebuild everything they show.
    void sceneReplaced();
    void bodyAboutToBeInserted(int index);
    void bodyInserted(int index);
    void bodyAboutToBeRemoved(int index);
    void bodyRemoved(int index);
    void bodyAboutToBeMoved(int from, int to);
    void bodyMoved(int from, int to);
    void bodyChanged(int index, interplay::BodyField field);
    void settingsChanged();
    void cameraBookmarksChanged();
    void jointAboutToBeInserted(int index);
    void jointInserted(int index);
    void jointAboutToBeRemoved(int index);
    void jointRemoved(int index);
    void jointChanged(int index, interplay::JointField field);
    void selectionChanged();
    // The scene was written to `path` (the file watcher re-arms on it).
    void saved(const QString& path);

private:
    void replaceScene(simcore::Scene scene, const QString& filePath, bool startModified);
    void setFilePath(const QString& filePath);
    // Renumbers the selected bodies after bodies changed places.
    void renumberSelection(const std::function<int(int)>& newIndex);

    simcore::Scene m_scene;
    QUndoStack* m_undoStack = nullptr;
    QString m_filePath;
    // The title of a scene read from a file it is not saved to: "NAME (imported)", "NAME (example)".
    QString m_nameWithoutFile;
    QStringList m_loadWarnings;
    QList<int> m_selection;
    QList<int> m_selectedJoints;
};

}  // namespace interplay

Q_DECLARE_METATYPE(interplay::BodyField)
Q_DECLARE_METATYPE(interplay::JointField)
