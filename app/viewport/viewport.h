#pragma once
// The 3D view of the running world: lit, shadowed bodies over a ground grid and a sky gradient,
// seen through an orbit camera. Draws the document's selection outlined (selected joints in the
// selection colour, anchors and axis marked), sleeping bodies tinted and the debug overlays
// (bounds, contact points and normals). Mouse and keys go to the SelectionTool (see
// selection_tool.h for the gestures).
// GL resources live as long as the widget's context (released on aboutToBeDestroyed, as in Qt's
// hellogl2 example).

#include "app/viewport/camera.h"
#include "app/viewport/selection_tool.h"

#include "simcore/io/scene.h"

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <glm/glm.hpp>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

class QOpenGLShaderProgram;

namespace interplay {

class DebugDrawOptions;
class SceneDocument;
class SimulationController;

class Viewport : public QOpenGLWidget, protected QOpenGLExtraFunctions {
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
    // Aims the camera at the movable bodies (all bodies if none move) on the next frame, when the
    // widget's size is known.
    void frameScene();
    // Aims the camera at the selected bodies (the whole scene when nothing is selected).
    void frameSelection();

    // The world ray through a widget pixel (origin at the eye, unit direction).
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

    // Renders a frame and returns it as an image (the viewport's framebuffer, resolved from MSAA).
    QImage grabViewport();
    // Frames drawn during the last second.
    int framesPerSecond() const { return static_cast<int>(m_frameTimes.size()); }

    // Colour a body is drawn with (linear RGB): the authored one, else a neutral grey for static
    // bodies and a palette colour picked by scene index for the others.
    static glm::vec3 displayColor(std::size_t sceneIndex, const std::optional<glm::vec3>& authored,
                                  simcore::MotionType motion);

    // What the viewport's shaders need: GL 3.3 core, 24-bit depth, stencil, 4x MSAA. Set it as the
    // default format before the application creates any window (see main()).
    static QSurfaceFormat requiredSurfaceFormat();

    QSize sizeHint() const override { return {960, 640}; }

signals:
    void cameraChanged();

protected:
    void initializeGL() override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    struct GpuMesh {
        unsigned vao = 0, vbo = 0, ibo = 0;
        int indexCount = 0;
        // Keeps a hull alive while its address is part of a cache key, so the address cannot be
        // reused by another hull.
        std::shared_ptr<const simcore::ConvexHull> hull;
    };
    // Bodies with equal shapes share one mesh (a thousand cubes are one upload).
    using MeshKey = std::tuple<int, float, float, float, float, float, const void*>;
    struct BodyDraw {
        simcore::BodyId id;
        int sceneIndex = -1;
        int mesh = -1;
        glm::vec3 color{1.0f};
        glm::vec3 localCenter{0.0f};     // of the shape's local bounds (m), for the outline
        glm::vec3 localHalfSize{0.5f};   // of the shape's local bounds (m)
    };
    struct OverlayVertex {
        glm::vec3 position;
        glm::vec3 color;  // linear RGB
    };
    // Where a joint of the running world holds its bodies now (m): its point on body A, its point
    // on body B (apart for a distance joint, a sliding slider or a strained joint) and its axis.
    struct JointAnchors {
        glm::vec3 onA, onB;
        glm::vec3 axis;  // unit; a hinge's or slider's, on body A
    };

    void cleanup();
    void releaseMeshes();
    void rebuildDrawList();
    int meshFor(const simcore::Shape& shape);
    void applyPendingFrame();
    void createShadowMap();
    void drawBodies(QOpenGLShaderProgram& program, bool shadowPass);
    void drawSelectionOutline(const glm::mat4& viewProjection);
    void drawOverlays(const glm::mat4& viewProjection);
    std::vector<OverlayVertex> overlayLines() const;
    // Scene joint `sceneIndex` as the running world holds it; none if it is not in the world.
    std::optional<JointAnchors> jointAnchors(std::size_t sceneIndex) const;
    // Light-space box around the bodies worth shadowing.
    glm::mat4 lightViewProjection() const;

    SimulationController* m_simulation = nullptr;
    SceneDocument* m_document = nullptr;
    DebugDrawOptions* m_debugDraw = nullptr;
    Camera m_camera;
    bool m_framePending = true;

    // GL state (valid between initializeGL and cleanup).
    bool m_glReady = false;
    QOpenGLShaderProgram* m_bodyProgram = nullptr;
    QOpenGLShaderProgram* m_shadowProgram = nullptr;
    QOpenGLShaderProgram* m_skyProgram = nullptr;
    QOpenGLShaderProgram* m_gridProgram = nullptr;
    QOpenGLShaderProgram* m_flatProgram = nullptr;  // one colour per draw (selection outline)
    QOpenGLShaderProgram* m_lineProgram = nullptr;  // per-vertex colour (overlays)
    unsigned m_emptyVao = 0;  // core profile needs a bound VAO even for attribute-less draws
    unsigned m_overlayVao = 0, m_overlayVbo = 0;
    unsigned m_shadowFbo = 0;
    unsigned m_shadowTexture = 0;
    std::vector<GpuMesh> m_meshes;
    std::map<MeshKey, int> m_meshIndex;
    std::vector<BodyDraw> m_draws;
    bool m_drawListDirty = true;

    SelectionTool m_tool{*this};

    std::deque<qint64> m_frameTimes;  // ms timestamps of the frames of the last second
    QElapsedTimer m_frameClock;
};

}  // namespace interplay
