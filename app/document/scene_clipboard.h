#pragma once
// Copy, cut, paste and duplicate work on a scene fragment: a simcore::Scene holding some bodies and
// the joints among them, written and read by simcore's scene writer and loader, so what goes on
// the clipboard is a valid v1 scene file (docs/scene-format.md) and what comes off it is checked
// as a file opened from disk would be. No widgets and no clipboard here: SceneActions moves the
// text between these functions and QGuiApplication::clipboard().

#include "simcore/io/scene.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

class QMimeData;

namespace interplay {

class SceneDocument;

// The clipboard's own MIME type; the same text is offered as text/plain too, so a text editor
// receives the scene file and a scene file copied as text can be pasted.
inline constexpr char kSceneFragmentMimeType[] = "application/x-interplay-scene+json";

// Bodies `indices` of `scene` (in scene order) and the joints whose bodies are all among them (a
// joint holding one of them to the world included; a joint to any other body left out), renumbered
// to the fragment. The scene's settings come along, so the fragment saved as a file runs as it did.
simcore::Scene sceneFragment(const simcore::Scene& scene, const QList<int>& indices);

// The fragment as scene file text (serializeScene: floats round-trip exactly).
QByteArray fragmentText(const simcore::Scene& fragment);

// The fragment `text` holds, or why it holds none: the loader's errors (JSON path and reason), or
// that the scene has no bodies. Warnings (unknown keys) do not refuse it.
struct ParsedFragment {
    std::optional<simcore::Scene> fragment;
    QString error;  // empty when `fragment` is set
};
ParsedFragment parseFragment(const QByteArray& text);

// The name a copy of `name` takes among `document`'s bodies and `alsoTaken` (names about to be
// added): "Box 3" becomes the next free "Box N", an unnumbered "ground" becomes "ground 1".
QString copyBodyName(const SceneDocument& document, const QString& name, const QStringList& alsoTaken);
// Renames the fragment's bodies (copyBodyName) and its named joints (likewise) so that none takes a
// name the document's bodies or joints use; joints refer to bodies by index, so they stay joined.
void giveUniqueNames(simcore::Scene& fragment, const SceneDocument& document);

// The world bounds of the fragment's bodies (m).
simcore::Aabb fragmentBounds(const simcore::Scene& fragment);
// Moves the fragment's bodies and its joints' anchors by `offset` (m).
void translateFragment(simcore::Scene& fragment, const simcore::Vec3& offset);
// The offset that sets a copy beside its originals, never in them: along +x by the fragment's
// width and a 0.1 m gap.
simcore::Vec3 offsetBeside(const simcore::Scene& fragment);
// The offset that sets the fragment's bounds, centred over `point` (x, z), on it (their bottom at
// the point's height).
simcore::Vec3 offsetOnto(const simcore::Scene& fragment, const simcore::Vec3& point);

// Clipboard data for the fragment: its text under kSceneFragmentMimeType and as text/plain.
QMimeData* fragmentMimeData(const simcore::Scene& fragment);
// The scene text of clipboard data: our MIME type when present, else the plain text.
QByteArray fragmentTextOf(const QMimeData& data);

}  // namespace interplay
