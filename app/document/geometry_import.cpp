#include "app/document/geometry_import.h"

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "simcore/io/scene_io.h"
#include "simcore/shapes/convex_hull.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace interplay {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("interplay::geometryImport", text); }

QString number(float value) { return QString::number(double(value), 'g', 4); }

QString point(const simcore::Vec3& p) { return QStringLiteral("(%1, %2, %3)").arg(number(p.x), number(p.y), number(p.z)); }

std::filesystem::path nativePath(const QString& path) { return QFile::encodeName(path).toStdString(); }

}  // namespace

bool isGeometryFile(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("obj") || suffix == QLatin1String("stl") || suffix == QLatin1String("gltf") ||
           suffix == QLatin1String("glb");
}

QString GeometryPreview::summary() const {
    if (!error.isEmpty()) return error;
    const simcore::Vec3 size = bounds.max - bounds.min;
    QString text = tr("%1 triangles, %2 vertices; %3 × %4 × %5 m, from %6 to %7")
                       .arg(mesh.triangles.size())
                       .arg(mesh.vertices.size())
                       .arg(number(size.x), number(size.y), number(size.z), point(bounds.min), point(bounds.max));
    if (mesh.droppedTriangles > 0) text += tr("; %1 degenerate triangles left out").arg(mesh.droppedTriangles);
    return text;
}

GeometryPreview previewGeometry(const QString& path, const simcore::MeshImportOptions& options) {
    GeometryPreview preview;
    preview.mesh = simcore::importMesh(nativePath(path), options);
    if (!preview.mesh.ok()) {
        preview.error = QString::fromStdString(preview.mesh.error);
        return preview;
    }
    for (const simcore::TriangleMesh::Indices& t : preview.mesh.triangles)
        for (std::uint32_t v : t) preview.bounds.grow(preview.mesh.vertices[v]);
    const simcore::HullPoints hull = simcore::hullPoints(preview.mesh);
    preview.hullCorners = hull.points.size();
    preview.hullError = QString::fromStdString(hull.error);
    return preview;
}

QUndoCommand* importGeometryCommand(SceneDocument* document, const QString& path, const GeometryPreview& preview,
                                    GeometryImportKind kind, const simcore::MeshImportOptions& options, QString* error) {
    const auto fail = [&](const QString& why) -> QUndoCommand* {
        if (error) *error = why;
        return nullptr;
    };
    if (!preview.error.isEmpty()) return fail(preview.error);
    const QFileInfo info(path);
    simcore::SceneBody body;
    body.body.name = document->uniqueBodyName(info.completeBaseName()).toStdString();
    if (kind == GeometryImportKind::ConvexHull) {
        const simcore::HullPoints points = simcore::hullPoints(preview.mesh);
        if (!points.error.empty()) return fail(tr("%1: %2").arg(info.fileName(), QString::fromStdString(points.error)));
        const simcore::ConvexHull::BuildResult built = simcore::ConvexHull::build(points.points);
        if (!built.hull) return fail(tr("%1: %2").arg(info.fileName(), QString::fromStdString(built.error)));
        body.body.shape = simcore::Shape::convexHull(built.hull);
        body.body.motion = simcore::MotionType::Dynamic;
    } else {
        simcore::TriangleMesh::BuildResult built = simcore::TriangleMesh::build(preview.mesh.vertices, preview.mesh.triangles);
        if (!built.mesh) return fail(tr("%1: %2").arg(info.fileName(), QString::fromStdString(built.error)));
        body.body.shape = simcore::Shape::triangleMesh(std::move(built.mesh));
        body.body.motion = simcore::MotionType::Static;
        if (kind == GeometryImportKind::MeshFileReference) {
            // Relative to the scene's folder when it has one; saving rewrites it for where it goes.
            simcore::MeshFileReference reference;
            reference.resolvedPath = simcore::resolveMeshFile(nativePath(info.absoluteFilePath()).string(), {});
            const QString folder = document->filePath().isEmpty() ? QString() : QFileInfo(document->filePath()).absolutePath();
            reference.file = folder.isEmpty() ? reference.resolvedPath.generic_string()
                                              : QDir(folder).relativeFilePath(info.absoluteFilePath()).toStdString();
            reference.scale = options.scale;
            reference.upAxis = options.upAxis;
            body.meshFile = std::move(reference);
        }
    }
    // The loader's checks on the scene with the body in it, as for every other edit.
    simcore::Scene candidate = document->scene();
    candidate.bodies.push_back(body);
    for (const simcore::Diagnostic& d : simcore::checkScene(candidate))
        if (d.severity == simcore::Diagnostic::Severity::Error)
            return fail(tr("%1 cannot be added: %2").arg(info.fileName(), QString::fromStdString(d.message)));
    return new AddBodies(document, tr("Import %1").arg(info.fileName()), {document->bodyCount()}, {std::move(body)});
}

}  // namespace interplay
