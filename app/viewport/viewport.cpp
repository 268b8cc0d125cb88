#include "app/viewport/viewport.h"

#include "app/document/scene_document.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/debug_overlay.h"
#include "app/viewport/gizmo_overlay.h"

#include "simcore/world/world.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <vector>

namespace interplay {
namespace {

// How near a click must come to a joint's anchors to pick the joint, in widget pixels (device
// independent, as mouse positions are, so the reach is the same on a high-DPI screen).
constexpr float kJointPickPixels = 8.0f;

}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);  // gizmo handles light up under the cursor
    setMinimumSize(160, 120);
    connect(&m_tool, &SelectionTool::cameraChanged, this, &Viewport::cameraChanged);
    connect(&m_tool, &SelectionTool::repaintNeeded, this, qOverload<>(&QWidget::update));
    m_frameClock.start();
}

Viewport::~Viewport() {
    // ~QOpenGLWidget destroys the context after this destructor, and the context then emits
    // aboutToBeDestroyed: it must not call cleanup() on a half-destroyed Viewport.
    if (QOpenGLContext* c = context()) disconnect(c, &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanup);
    cleanup();
}

void Viewport::setSimulation(SimulationController* simulation) {
    if (m_simulation) disconnect(m_simulation, nullptr, this, nullptr);
    m_simulation = simulation;
    m_tool.setSimulation(simulation);
    m_bodiesDirty = true;
    if (m_simulation) {
        connect(m_simulation, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
        const auto markDirty = [this] {
            m_bodiesDirty = true;
            update();
        };
        connect(m_simulation, &SimulationController::worldRebuilt, this, markDirty);
        connect(m_simulation, &SimulationController::bodySpawned, this, markDirty);
        connect(m_simulation, &SimulationController::bodiesEdited, this, markDirty);
        // A moved body is drawn from its live pose: the batches still hold.
        connect(m_simulation, &SimulationController::posesEdited, this, qOverload<>(&QWidget::update));
    }
    overlaysChanged();
}

void Viewport::setDocument(SceneDocument* document) {
    if (m_document) disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_tool.setDocument(document);
    if (m_document) connect(m_document, &SceneDocument::selectionChanged, this, qOverload<>(&QWidget::update));
    update();
}

void Viewport::setDebugDrawOptions(DebugDrawOptions* options) {
    if (m_debugDraw) disconnect(m_debugDraw, nullptr, this, nullptr);
    m_debugDraw = options;
    if (m_debugDraw) connect(m_debugDraw, &DebugDrawOptions::changed, this, &Viewport::overlaysChanged);
    overlaysChanged();
}

void Viewport::overlaysChanged() {
    if (m_simulation) m_simulation->setSnapshotOverlays(DebugOverlay::worldOptions(m_debugDraw));
    update();
}

void Viewport::frameScene() {
    m_framePending = true;
    update();
}

void Viewport::frameSelection() {
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world || !m_document || m_document->selectedBodies().isEmpty()) {
        frameAll();
        return;
    }
    simcore::Aabb box;
    for (int index : m_document->selectedBodies()) {
        const auto& ids = m_simulation->bodyIds();
        if (index >= static_cast<int>(ids.size()) || !world->contains(ids[static_cast<std::size_t>(index)])) continue;
        const simcore::BodyId id = ids[static_cast<std::size_t>(index)];
        box.grow(simcore::worldBounds(world->shape(id), {world->position(id), world->orientation(id)}));
    }
    if (box.isEmpty()) return;
    m_camera.frameBox(box.min, box.max, aspect(), 0.3f);
    emit cameraChanged();
    update();
}

void Viewport::frameAll() {
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world || world->bodyCount() == 0) return;
    simcore::Aabb box;
    for (const simcore::BodyId id : world->bodyIds()) {
        box.grow(simcore::worldBounds(world->shape(id), {world->position(id), world->orientation(id)}));
    }
    m_camera.frameBounds(box.min, box.max, aspect());
    emit cameraChanged();
    update();
}

void Viewport::lookAlong(AxisView view) {
    struct Angles {
        float yaw, pitch;
    };
    // Pitch ±90 is clamped just short of the pole by the camera, where "up" stays defined.
    static constexpr Angles kAngles[] = {{0.0f, 0.0f}, {180.0f, 0.0f}, {90.0f, 0.0f},
                                         {-90.0f, 0.0f}, {0.0f, 90.0f}, {0.0f, -90.0f}};
    const Angles& angles = kAngles[static_cast<int>(view)];
    m_camera.setYawDegrees(angles.yaw);
    m_camera.setPitchDegrees(angles.pitch);
    emit cameraChanged();
    update();
}

void Viewport::setCamera(const Camera& camera) {
    m_camera = camera;
    m_framePending = false;
    emit cameraChanged();
    update();
}

void Viewport::setOrthographic(bool orthographic) {
    if (m_camera.isOrthographic() == orthographic) return;
    m_camera.setOrthographic(orthographic);
    emit cameraChanged();
    update();
}

std::pair<glm::vec3, glm::vec3> Viewport::rayThrough(const QPointF& pixel) const {
    const float w = static_cast<float>(std::max(width(), 1)), h = static_cast<float>(std::max(height(), 1));
    const glm::mat4 inverse = glm::inverse(m_camera.viewProjection(w / h));
    const float x = 2.0f * static_cast<float>(pixel.x()) / w - 1.0f;
    const float y = 1.0f - 2.0f * static_cast<float>(pixel.y()) / h;
    const glm::vec4 nearPoint = inverse * glm::vec4(x, y, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(x, y, 1.0f, 1.0f);
    const glm::vec3 from = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 to = glm::vec3(farPoint) / farPoint.w;
    return {m_camera.isOrthographic() ? from : m_camera.eye(), glm::normalize(to - from)};
}

std::optional<simcore::WorldRayHit> Viewport::pick(const QPointF& pixel) const {
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world) return std::nullopt;
    const auto [origin, direction] = rayThrough(pixel);
    // Unit direction: the fraction is a distance, and the far plane bounds what can be seen.
    return world->castRay(origin, direction, m_camera.rayReach());
}

int Viewport::sceneBodyAt(const QPointF& pixel) const {
    const auto hit = pick(pixel);
    return hit ? m_simulation->sceneIndexOf(hit->body) : -1;
}

std::optional<Viewport::JointPick> Viewport::pickJoint(const QPointF& pixel) const {
    if (!m_simulation) return std::nullopt;
    // Where the joints are drawn: the snapshot's.
    SceneJoints joints(m_simulation->jointIds());
    m_simulation->snapshot().drawOverlays(joints, SceneJoints::jointsOnly());
    const float w = static_cast<float>(width()), h = static_cast<float>(height());
    const glm::vec2 cursor(static_cast<float>(pixel.x()), static_cast<float>(pixel.y()));
    std::optional<JointPick> nearest;
    float nearestPixels = kJointPickPixels;
    const auto& bySceneIndex = joints.bySceneIndex();
    for (std::size_t j = 0; j < bySceneIndex.size(); ++j) {
        if (!bySceneIndex[j]) continue;
        const simcore::DebugJoint& joint = *bySceneIndex[j];
        // Perspective keeps a segment straight on screen, so its projection is where it is drawn;
        // one reaching behind the eye (or beyond the far plane) is not drawn and is skipped.
        const glm::vec3 a = m_camera.project(joint.anchorA, w, h), b = m_camera.project(joint.anchorB, w, h);
        if (a.z > 1.0f || b.z > 1.0f) continue;
        const glm::vec2 from(a), along = glm::vec2(b) - from;
        const float lengthSquared = glm::dot(along, along);  // zero where the anchors meet
        const float t =
            lengthSquared > 0.0f ? std::clamp(glm::dot(cursor - from, along) / lengthSquared, 0.0f, 1.0f) : 0.0f;
        const float pixels = glm::length(cursor - (from + t * along));
        if (pixels <= nearestPixels) {
            const glm::vec3 point = glm::mix(joint.anchorA, joint.anchorB, t);  // near enough under perspective
            nearest = JointPick{static_cast<int>(j), glm::length(point - m_camera.eye())};
            nearestPixels = pixels;
        }
    }
    return nearest;
}

glm::vec3 Viewport::placementPoint(float bodyHalfHeight) const {
    glm::vec3 point = m_camera.target();
    point.y = 0.0f;
    // Drop it from above whatever is already below the target, with a little air.
    if (const simcore::World* world = m_simulation ? m_simulation->world() : nullptr) {
        const auto hit = world->castRay(point + glm::vec3(0.0f, 1000.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), 2000.0f);
        if (hit) point.y = hit->point.y;
    }
    point.y += bodyHalfHeight + 0.5f;
    return point;
}

std::optional<glm::vec3> Viewport::surfacePointAt(const QPointF& pixel) const {
    if (const auto hit = pick(pixel)) return hit->point;
    const auto [origin, direction] = rayThrough(pixel);
    if (direction.y >= 0.0f) return std::nullopt;  // looking up: the ground is never met
    const float t = -origin.y / direction.y;
    if (t < 0.0f || t > m_camera.rayReach()) return std::nullopt;
    return origin + t * direction;
}

QImage Viewport::grabViewport() {
    return grabFramebuffer();
}

QSurfaceFormat Viewport::requiredSurfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(4);
    return format;
}

// ---- GL lifetime ------------------------------------------------------------------------------

void Viewport::initializeGL() {
    // The context can be recreated (e.g. the widget moves to another top-level window): release
    // everything tied to the old one first, as hellogl2 does.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanup, Qt::UniqueConnection);
    m_renderer.initialize(defaultFramebufferObject());
    m_bodiesDirty = true;
}

void Viewport::cleanup() {
    if (!m_renderer.isReady()) return;
    // Called from the destructor and from aboutToBeDestroyed; GL calls need the context current.
    makeCurrent();
    m_renderer.release();
    m_bodies.clear();  // its mesh indices went with the meshes
    m_bodiesDirty = true;
    doneCurrent();
}

// ---- Frame ------------------------------------------------------------------------------------

void Viewport::applyPendingFrame() {
    if (!m_framePending || width() <= 0 || height() <= 0) return;
    m_framePending = false;
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world || world->bodyCount() == 0) return;

    // Frame what moves; a floor would otherwise set the scale. Fall back to everything.
    struct Placed {
        simcore::Aabb bounds;
        bool isStatic;
    };
    std::vector<Placed> placed;
    for (const simcore::BodyId id : world->bodyIds()) {
        placed.push_back({simcore::worldBounds(world->shape(id), {world->position(id), world->orientation(id)}),
                          world->motionType(id) == simcore::MotionType::Static});
    }
    simcore::Aabb moving, all;
    for (const Placed& p : placed) {
        all.grow(p.bounds);
        if (!p.isStatic) moving.grow(p.bounds);
    }
    simcore::Aabb box = moving.isEmpty() ? all : moving;
    // Include the floor under the bodies, so where they will land is in view too.
    if (!moving.isEmpty()) {
        for (const Placed& p : placed) {
            if (!p.isStatic) continue;
            const simcore::Aabb& b = p.bounds;
            const bool under = b.max.y <= box.min.y + 1e-3f && b.min.x <= box.max.x && box.min.x <= b.max.x &&
                               b.min.z <= box.max.z && box.min.z <= b.max.z;
            if (under && box.min.y - b.max.y < 20.0f) box.min.y = std::min(box.min.y, b.max.y);
        }
    }
    m_camera.frameBounds(box.min, box.max, aspect());
    emit cameraChanged();
}

void Viewport::paintGL() {
    if (!m_renderer.isReady()) return;
    if (m_bodiesDirty) {
        m_renderer.trimMeshCache();
        m_bodiesDirty = false;
        if (m_simulation) {
            m_bodies.rebuild(*m_simulation, [this](const simcore::Shape& shape) { return m_renderer.meshFor(shape); });
        } else {
            m_bodies.clear();
        }
    }
    applyPendingFrame();

    // Everything drawn comes from the controller's snapshot, the last finished state (a step in
    // flight is never waited for): the bodies' instances, then the overlay's lines.
    static const QList<int> kNothingSelected;
    const QList<int>& selectedBodies = m_document ? m_document->selectedBodies() : kNothingSelected;
    m_bodies.beginFrame(m_renderer.meshCount(), selectedBodies, !m_debugDraw || m_debugDraw->sleepingTint());
    std::vector<OverlayVertex> lines;
    if (m_simulation && !m_bodies.empty()) {
        const WorldSnapshot& snapshot = m_simulation->snapshot();
        for (const WorldSnapshot::Body& body : snapshot.bodies) m_bodies.drawBody(body);
        DebugOverlay overlay(m_debugDraw, m_simulation->jointIds());
        snapshot.drawOverlays(overlay, DebugOverlay::worldOptions(m_debugDraw));
        lines = overlay.finish(m_document ? m_document->selectedJoints() : kNothingSelected, m_simulation->grabLine());
    }
    std::vector<OverlayVertex> gizmo;
    if (const auto placement = m_tool.gizmo().placement()) {
        gizmo = gizmoTriangles(*placement, *m_tool.gizmo().mode(), m_tool.gizmo().highlighted(), m_camera,
                               static_cast<float>(width()), static_cast<float>(height()));
    }
    m_renderer.render({m_camera, width(), height(), static_cast<float>(devicePixelRatio()), defaultFramebufferObject(),
                       m_bodies.instancesByMesh(), m_bodies.outlined(), lines, gizmo});
    if (const std::optional<QRect> band = m_tool.rubberBand()) {
        QPainter painter(this);
        paintRubberBand(painter, *band);
    }

    const qint64 now = m_frameClock.elapsed();
    m_frameTimes.push_back(now);
    while (!m_frameTimes.empty() && m_frameTimes.front() <= now - 1000) m_frameTimes.pop_front();
}

// ---- Mouse and keys: the selection tool's ------------------------------------------------------

bool Viewport::event(QEvent* event) {
    // Keys the tool needs mid-gesture (W while flying, Escape during a gizmo drag) come before the
    // window's shortcuts on them.
    if (event->type() == QEvent::ShortcutOverride && m_tool.wantsKey(static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    return QOpenGLWidget::event(event);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    if (m_tool.mousePress(event)) event->accept();
    else QOpenGLWidget::mousePressEvent(event);
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (!m_tool.mouseMove(event)) QOpenGLWidget::mouseMoveEvent(event);
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_tool.mouseRelease(event)) event->accept();
    else QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::wheelEvent(QWheelEvent* event) {
    m_tool.wheel(event);
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (m_tool.keyPress(event)) event->accept();
    else QOpenGLWidget::keyPressEvent(event);
}

void Viewport::keyReleaseEvent(QKeyEvent* event) {
    if (m_tool.keyRelease(event)) event->accept();
    else QOpenGLWidget::keyReleaseEvent(event);
}

void Viewport::leaveEvent(QEvent* event) {
    m_tool.gizmo().clearHover();
    QOpenGLWidget::leaveEvent(event);
}

void Viewport::focusOutEvent(QFocusEvent* event) {
    m_tool.focusOut();
    QOpenGLWidget::focusOutEvent(event);
}

}  // namespace interplay
