#pragma once
// The 3D view of the running world: lit, shadowed bodies over a ground grid and a sky gradient,
// seen through an orbit camera. Draws the document's selection outlined (selected joints in the
// selection colour, anchors and axis marked), sleeping bodies tinted and the debug overlays
// (bounds, contact points and normals). The widget wires three parts together: everything it
// draws comes from the controller's WorldSnapshot, what World::draw emitted when the last batch of
// steps finished, so drawing never waits for a step in flight (BodyBatches gathers the bodies,
// DebugOverlay the lines; picking asks the world itself, after the step in flight), the
// Renderer draws it, and the SelectionTool handles mouse and keys (see selection_tool.h for the
// gestures, gizmo_tool.h for the transform gizmo, which gizmo_overlay draws). GL resources live as
// long as the widget's context (released on aboutToBeDestroyed, as in Qt's hellogl2 example).

#include "app/viewport/body_batches.h"
#include "app/viewport/camera.h"
#include "app/viewport/renderer.h"
#include "app/viewport/selection_tool.h"

#include "simcore/world/world.h"  // WorldRayHit

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <glm/glm.hpp>

#include <deque>
#include <optional>
#include <utility>

namespace interplay {

class DebugDrawOptions;
class SceneDocument;
class SimulationController;

class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    void setSimulation(SimulationController* simulation);
    // The document whose selection is drawn and edited; drags push commands on it.
    void setDocument(SceneDocument* document);
    void setDebugDrawOptions(DebugDrawOptions* options);

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }
    // Shows the view of `camera` (a bookmark's), instead of any framing still pending.
    void setCamera(const Camera& camera);
    // Aims the camera at the movable bodies (all bodies if none move) on the next frame, when the
    // widget's size is known.
    void frameScene();
    // Aims the camera at the selected bodies (Frame All when nothing is selected).
    void frameSelection();
    // Aims the camera at every body's bounds, their bounding sphere filling 80 % of the view.
    void frameAll();

    // Blender's numpad views, in Y-up terms: Front looks along -Z, Right along -X, Top along -Y
    // (as near as the camera's pitch limit allows); Back, Left and Bottom the opposite ways. The
    // target and distance stay.
    enum class AxisView { Front, Back, Right, Left, Top, Bottom };
    void lookAlong(AxisView view);
    void setOrthographic(bool orthographic);

    // The transform gizmo on the selection: move, rotate or none; world or local axes.
    void setGizmoMode(std::optional<gizmo::Mode> mode) { m_tool.gizmo().setMode(mode); }
    std::optional<gizmo::Mode> gizmoMode() const { return m_tool.gizmo().mode(); }
    void setGizmoSpace(gizmo::Space space) { m_tool.gizmo().setSpace(space); }
    gizmo::Space gizmoSpace() const { return m_tool.gizmo().space(); }
    void setGizmoSnapping(bool snapping) { m_tool.gizmo().setSnapping(snapping); }
    bool gizmoSnapping() const { return m_tool.gizmo().snapping(); }
    // Where the gizmo is drawn now, if it is.
    std::optional<gizmo::Placement> gizmoPlacement() const { return m_tool.gizmo().placement(); }

    // The world ray through a widget pixel (unit direction; the origin is the eye, or under an
    // orthographic projection the pixel's point on the near plane, the rays being parallel).
    std::pair<glm::vec3, glm::vec3> rayThrough(const QPointF& pixel) const;
    // The closest body under a widget pixel, by World::castRay.
    std::optional<simcore::WorldRayHit> pick(const QPointF& pixel) const;
    // The scene body under a pixel, or -1 (nothing, or a body thrown in while running).
    int sceneBodyAt(const QPointF& pixel) const;
    // The scene joint whose live anchors, or the segment between them (a distance joint's rod),
    // pass nearest to a widget pixel, if within a few pixels, and how far from the eye that point
    // of it is (m).
    struct JointPick {
        int joint = -1;
        float distance = 0.0f;
    };
    std::optional<JointPick> pickJoint(const QPointF& pixel) const;
    // Where a new body of this size could go: the ground point under the view's centre, raised so
    // the body clears the bodies already there (m).
    glm::vec3 placementPoint(float bodyHalfHeight) const;
    // The point under a widget pixel on the body surface there, else on the ground plane y = 0, or
    // nothing where the ray meets neither (the sky): where Paste puts bodies (m).
    std::optional<glm::vec3> surfacePointAt(const QPointF& pixel) const;

    // Renders a frame and returns it as an image (the viewport's framebuffer, resolved from MSAA).
    QImage grabViewport();
    // Frames drawn during the last second.
    int framesPerSecond() const { return static_cast<int>(m_frameTimes.size()); }

    // What the viewport's shaders need: GL 3.3 core, 24-bit depth, stencil, 4x MSAA. Set it as the
    // default format before the application creates any window (see main()).
    static QSurfaceFormat requiredSurfaceFormat();

    QSize sizeHint() const override { return {960, 640}; }

signals:
    void cameraChanged();

protected:
    bool event(QEvent* event) override;
    void initializeGL() override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void cleanup();
    // The debug draw options changed: the snapshot takes what the overlay draws, and the view redraws.
    void overlaysChanged();
    void applyPendingFrame();
    float aspect() const { return static_cast<float>(width()) / static_cast<float>(std::max(height(), 1)); }

    SimulationController* m_simulation = nullptr;
    SceneDocument* m_document = nullptr;
    DebugDrawOptions* m_debugDraw = nullptr;
    Camera m_camera;
    bool m_framePending = true;

    Renderer m_renderer;       // GL state, valid between initializeGL and cleanup
    BodyBatches m_bodies;
    bool m_bodiesDirty = true;  // the world was rebuilt or its bodies edited: meshes and colours to redo
    SelectionTool m_tool{*this};

    std::deque<qint64> m_frameTimes;  // ms timestamps of the frames of the last second
    QElapsedTimer m_frameClock;
};

}  // namespace interplay
