#pragma once
// File → Import Geometry and dropped mesh files: what a file of triangles (OBJ, STL, glTF, GLB)
// becomes in the scene, and the preview the dialog shows before anything changes. Model layer:
// Qt Core only; the import itself is simcore_import's (mesh_import.h).
//
// A file becomes one body: a static mesh with its triangles stored in the scene, a static mesh
// that references the file (saved as a path, mesh_file.h), or a dynamic convex hull of its points.
// A compound of convex pieces is not offered: it needs a convex decomposition (V-HACD, CoACD), and
// Debian packages none for C++. The body sits where the file puts the geometry (origin at the
// file's origin), so parts modelled together line up.

#include "simcore/io/mesh_import.h"
#include "simcore/io/scene.h"
#include "simcore/math/aabb.h"

#include <QString>

#include <optional>

class QUndoCommand;

namespace interplay {

class SceneDocument;

enum class GeometryImportKind { MeshInScene, MeshFileReference, ConvexHull };

// Whether `path` names a file Import Geometry reads (by extension: .obj, .stl, .gltf, .glb).
bool isGeometryFile(const QString& path);

// The file read with the dialog's options: counts, bounds in metres after scale and up axis, and
// the convex hull's corner count (for the hull choice), or the import's message.
struct GeometryPreview {
    simcore::ImportedMesh mesh;
    simcore::Aabb bounds;        // of the triangles' vertices
    std::size_t hullCorners = 0; // 0 when the points give no hull
    QString hullError;           // why they give none
    QString error;               // the file could not be imported; empty on success
    QString summary() const;     // "12 triangles, 8 vertices; 2 × 4 × 6 m, from (-1, -2, -3) to (1, 2, 3)"
};
GeometryPreview previewGeometry(const QString& path, const simcore::MeshImportOptions& options);

// The undoable import of `preview` (read from `path` with `options`) as `kind`: one AddBodies, the
// new body selected. Null with *error set when it cannot be made (no hull, or the scene's own
// checks refuse it); then nothing changes.
QUndoCommand* importGeometryCommand(SceneDocument* document, const QString& path, const GeometryPreview& preview,
                                    GeometryImportKind kind, const simcore::MeshImportOptions& options, QString* error);

}  // namespace interplay
