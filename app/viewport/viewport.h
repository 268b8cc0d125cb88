#pragma once
// The 3D view of the running world: lit, shadowed bodies over a ground grid and a sky gradient,
// seen through an orbit camera. Reads the world through the SimulationController and never
// changes it. GL resources live as long as the widget's context (released on aboutToBeDestroyed,
// as in Qt's hellogl2 example).

#include "app/viewport/camera.h"

#include "simcore/dynamics/body.h"

#include <QImage>
#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <QPoint>
#include <QSurfaceFormat>

#include <glm/glm.hpp>

#include <map>
#include <optional>
#include <tuple>
#include <vector>

class QOpenGLShaderProgram;

namespace interplay {

class SimulationController;

class Viewport : public QOpenGLWidget, protected QOpenGLExtraFunctions {
    Q_OBJECT

public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    void setSimulation(SimulationController* simulation);

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }
    // Aims the camera at the movable bodies (all bodies if none move) on the next frame, when the
    // widget's size is known.
    void frameScene();

    // Renders a frame and returns it as an image (the viewport's framebuffer, resolved from MSAA).
    QImage grabViewport();

    // Colour a body is drawn with (linear RGB): the authored one, else a neutral grey for static
    // bodies and a palette colour picked by scene index for the others.
    static glm::vec3 displayColor(std::size_t sceneIndex, const std::optional<glm::vec3>& authored,
                                  simcore::MotionType motion);

    // What the viewport's shaders need: GL 3.3 core, 24-bit depth, 4x MSAA. Set it as the default
    // format before the application creates any window (see main()).
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

private:
    struct GpuMesh {
        unsigned vao = 0, vbo = 0, ibo = 0;
        int indexCount = 0;
    };
    // Bodies with equal shapes share one mesh (a thousand cubes are one upload).
    using MeshKey = std::tuple<int, float, float, float, float, float, const void*>;
    struct BodyDraw {
        simcore::BodyId id;
        int mesh = -1;
        glm::vec3 color{1.0f};
    };

    void cleanup();
    void releaseMeshes();
    void rebuildDrawList();
    int meshFor(const simcore::Shape& shape);
    void applyPendingFrame();
    void createShadowMap();
    void drawBodies(QOpenGLShaderProgram& program, bool shadowPass);
    // Light-space box around the bodies worth shadowing.
    glm::mat4 lightViewProjection() const;

    SimulationController* m_simulation = nullptr;
    Camera m_camera;
    bool m_framePending = true;

    // GL state (valid between initializeGL and cleanup).
    bool m_glReady = false;
    QOpenGLShaderProgram* m_bodyProgram = nullptr;
    QOpenGLShaderProgram* m_shadowProgram = nullptr;
    QOpenGLShaderProgram* m_skyProgram = nullptr;
    QOpenGLShaderProgram* m_gridProgram = nullptr;
    unsigned m_emptyVao = 0;  // core profile needs a bound VAO even for attribute-less draws
    unsigned m_shadowFbo = 0;
    unsigned m_shadowTexture = 0;
    std::vector<GpuMesh> m_meshes;
    std::map<MeshKey, int> m_meshIndex;
    std::vector<BodyDraw> m_draws;
    bool m_drawListDirty = true;

    // Mouse gesture in progress.
    enum class Drag { None, Orbit, Pan };
    Drag m_drag = Drag::None;
    QPoint m_lastMouse;
};

}  // namespace interplay
