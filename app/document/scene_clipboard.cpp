#include "app/document/scene_clipboard.h"

#include "app/document/scene_document.h"

#include "simcore/io/scene_io.h"
#include "simcore/shapes/shape.h"

#include <QCoreApplication>
#include <QMimeData>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <string>
#include <vector>

namespace interplay {
namespace {

// A clipboard full of errors would fill the status bar: the first few say what is wrong.
constexpr int kMaxErrorsShown = 3;
constexpr float kGapBesideMetres = 0.1f;

QString tr(const char* text) { return QCoreApplication::translate("interplay::clipboard", text); }

// "Box 3" -> "Box", "left elbow" -> "left elbow": the part a copy's number replaces.
QString baseName(const QString& name) {
    static const QRegularExpression trailingNumber(QStringLiteral("\\s*\\d+$"));
    return QString(name).remove(trailingNumber);
}

}  // namespace

simcore::Scene sceneFragment(const simcore::Scene& scene, const QList<int>& indices) {
    QList<int> sorted = indices;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    simcore::Scene fragment;
    fragment.settings = scene.settings;
    // fragmentIndex[i]: where scene body i sits in the fragment, -1 when not copied.
    std::vector<int> fragmentIndex(scene.bodies.size(), -1);
    for (int index : sorted) {
        if (index < 0 || static_cast<std::size_t>(index) >= scene.bodies.size()) continue;
        fragmentIndex[static_cast<std::size_t>(index)] = static_cast<int>(fragment.bodies.size());
        fragment.bodies.push_back(scene.bodies[static_cast<std::size_t>(index)]);
    }
    for (const simcore::SceneJoint& joint : scene.joints) {
        const int a = fragmentIndex.at(joint.bodyA);
        const int b = joint.bodyB ? fragmentIndex.at(*joint.bodyB) : 0;
        if (a < 0 || b < 0) continue;  // a body of it stays behind
        simcore::SceneJoint copy = joint;
        copy.bodyA = static_cast<std::size_t>(a);
        if (joint.bodyB) copy.bodyB = static_cast<std::size_t>(b);
        fragment.joints.push_back(std::move(copy));
    }
    return fragment;
}

QByteArray fragmentText(const simcore::Scene& fragment) {
    // Mesh files by absolute path: the text may be pasted into a scene in another folder.
    simcore::Scene copied = fragment;
    for (simcore::SceneBody& body : copied.bodies)
        if (body.meshFile && !body.meshFile->resolvedPath.empty()) body.meshFile->file = body.meshFile->resolvedPath.generic_string();
    return QByteArray::fromStdString(simcore::serializeScene(copied));
}

ParsedFragment parseFragment(const QByteArray& text) {
    if (text.trimmed().isEmpty()) return {std::nullopt, tr("The clipboard holds no scene: it is empty.")};
    simcore::SceneLoadResult result =
        simcore::parseScene(std::string_view(text.constData(), std::size_t(text.size())), "clipboard", sceneReadOptions({}));
    if (!result.ok()) {
        QStringList errors;
        for (const simcore::Diagnostic& diagnostic : result.diagnostics) {
            if (diagnostic.severity != simcore::Diagnostic::Severity::Error) continue;
            if (errors.size() == kMaxErrorsShown) {
                errors << tr("...");
                break;
            }
            errors << QString::fromStdString(diagnostic.toString());
        }
        return {std::nullopt,
                tr("The clipboard holds no scene that can be pasted: %1").arg(errors.join(QStringLiteral("; ")))};
    }
    if (result.scene->bodies.empty()) {
        return {std::nullopt, tr("The clipboard's scene has no bodies to paste.")};
    }
    return {std::move(result.scene), {}};
}

QString copyBodyName(const SceneDocument& document, const QString& name, const QStringList& alsoTaken) {
    const QString base = baseName(name);
    return document.uniqueBodyName(base.isEmpty() ? tr("Body") : base, alsoTaken);
}

void giveUniqueNames(simcore::Scene& fragment, const SceneDocument& document) {
    QStringList bodyNames;
    for (simcore::SceneBody& body : fragment.bodies) {
        bodyNames << copyBodyName(document, QString::fromStdString(body.body.name), bodyNames);
        body.body.name = bodyNames.last().toStdString();
    }
    QStringList jointNames;
    for (simcore::SceneJoint& joint : fragment.joints) {
        if (joint.joint.name.empty()) continue;  // unnamed joints are told apart by their bodies
        const QString base = baseName(QString::fromStdString(joint.joint.name));
        jointNames << document.uniqueJointName(base.isEmpty() ? tr("Joint") : base, jointNames);
        joint.joint.name = jointNames.last().toStdString();
    }
}

simcore::Aabb fragmentBounds(const simcore::Scene& fragment) {
    simcore::Aabb bounds;
    for (const simcore::SceneBody& body : fragment.bodies) {
        bounds.grow(simcore::worldBounds(body.body.shape, {body.body.position, body.body.orientation}));
    }
    return bounds;
}

void translateFragment(simcore::Scene& fragment, const simcore::Vec3& offset) {
    for (simcore::SceneBody& body : fragment.bodies) body.body.position += offset;
    // Anchors are world points fixed in the bodies; axes are directions and do not move.
    for (simcore::SceneJoint& joint : fragment.joints) {
        joint.joint.anchor += offset;
        joint.joint.anchorB += offset;
    }
}

simcore::Vec3 offsetBeside(const simcore::Scene& fragment) {
    const simcore::Aabb bounds = fragmentBounds(fragment);
    if (bounds.isEmpty()) return simcore::Vec3(0.0f);
    return {bounds.max.x - bounds.min.x + kGapBesideMetres, 0.0f, 0.0f};
}

simcore::Vec3 offsetOnto(const simcore::Scene& fragment, const simcore::Vec3& point) {
    const simcore::Aabb bounds = fragmentBounds(fragment);
    if (bounds.isEmpty()) return simcore::Vec3(0.0f);
    const simcore::Vec3 bottomCentre(bounds.center().x, bounds.min.y, bounds.center().z);
    return point - bottomCentre;
}

QMimeData* fragmentMimeData(const simcore::Scene& fragment) {
    const QByteArray text = fragmentText(fragment);
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(kSceneFragmentMimeType), text);
    data->setText(QString::fromUtf8(text));
    return data;
}

QByteArray fragmentTextOf(const QMimeData& data) {
    const QString ours = QString::fromLatin1(kSceneFragmentMimeType);
    if (data.hasFormat(ours)) return data.data(ours);
    return data.text().toUtf8();
}

}  // namespace interplay
