#pragma once
// The viewport's GL side: shader programs (the .glsl files in shaders/, compiled into the program
// as Qt resources), the shape meshes, the shadow map and the passes of a frame: shadow map, sky,
// lit bodies, ground grid, selection outline, debug lines, screen-space overlays (the gizmo). It
// draws what it is handed and knows nothing of worlds or documents. All calls need the owning
// widget's context current; release() must run before that context goes (the widget calls it on
// aboutToBeDestroyed, as in Qt's hellogl2).

#include "app/viewport/camera.h"

#include "simcore/shapes/shape.h"

#include <QOpenGLExtraFunctions>

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <tuple>
#include <vector>

class QOpenGLShaderProgram;

namespace interplay {

// One body of a mesh, drawn instanced: where it is and its colour (linear RGB).
struct BodyInstance {
    glm::mat4 model;
    glm::vec3 color;
};

// A selected body, outlined: its mesh and pose, and the centre and half-size of its shape's local
// bounds (m), about which the outline grows.
struct OutlinedBody {
    int mesh = -1;
    glm::mat4 model{1.0f};
    glm::vec3 localCenter{0.0f};
    glm::vec3 localHalfSize{0.5f};
};

// A debug line's end, with its colour (linear RGB); two make a line.
struct OverlayVertex {
    glm::vec3 position;
    glm::vec3 color;
};

class Renderer : protected QOpenGLExtraFunctions {
public:
    Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;
    ~Renderer();

    void initialize(unsigned defaultFramebuffer);
    void release();
    bool isReady() const { return m_ready; }

    // The mesh of a shape, uploaded on first use; equal shapes share one (a thousand cubes are one
    // upload). Meshes outlive a world, as an edit rebuilds it with mostly the same shapes.
    int meshFor(const simcore::Shape& shape);
    // Drops the mesh cache when edits of sizes have filled it with shapes no longer in use; mesh
    // indices handed out before are then invalid (call it before handing out new ones).
    void trimMeshCache();
    std::size_t meshCount() const { return m_meshes.size(); }

    struct Frame {
        const Camera& camera;
        int width = 0, height = 0;  // widget size (device-independent pixels)
        float devicePixelRatio = 1.0f;
        unsigned defaultFramebuffer = 0;
        const std::vector<std::vector<BodyInstance>>& instancesByMesh;  // indexed by meshFor's answers
        const std::vector<OutlinedBody>& outlined;
        const std::vector<OverlayVertex>& lines;
        // Drawn last, over everything: triangles in widget pixels (x right, y down), such as a
        // transform gizmo's handles, which keep their size and stroke width on screen.
        const std::vector<OverlayVertex>& screenTriangles;
    };
    void render(const Frame& frame);

private:
    struct GpuMesh {
        unsigned vao = 0, vbo = 0, ibo = 0;
        int indexCount = 0;
        // Keeps a hull, mesh or height field alive while its address is part of a cache key, so
        // the address cannot be reused by another.
        std::shared_ptr<const void> shared;
    };
    using MeshKey = std::tuple<int, float, float, float, float, float, const void*>;

    void releaseMeshes();
    void createShadowMap(unsigned defaultFramebuffer);
    // Uploads this frame's instances into one buffer; returns each mesh's first instance in it.
    std::vector<std::size_t> uploadInstances(const std::vector<std::vector<BodyInstance>>& instancesByMesh);
    void drawInstances(const std::vector<std::vector<BodyInstance>>& instancesByMesh,
                       const std::vector<std::size_t>& firstInstance);
    void drawSelectionOutline(const Frame& frame, const glm::mat4& viewProjection);
    void drawLines(const std::vector<OverlayVertex>& lines, const glm::mat4& viewProjection);
    void drawScreenTriangles(const Frame& frame);
    // Light-space box around what is in view, for the shadow map.
    static glm::mat4 lightViewProjection(const Camera& camera);

    bool m_ready = false;
    std::unique_ptr<QOpenGLShaderProgram> m_bodyProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_shadowProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_skyProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_gridProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_flatProgram;  // one colour per draw (selection outline)
    std::unique_ptr<QOpenGLShaderProgram> m_lineProgram;  // per-vertex colour (overlays)
    unsigned m_emptyVao = 0;  // core profile needs a bound VAO even for attribute-less draws
    unsigned m_overlayVao = 0, m_overlayVbo = 0;
    unsigned m_instanceVbo = 0;
    unsigned m_shadowFbo = 0;
    unsigned m_shadowTexture = 0;
    std::vector<GpuMesh> m_meshes;
    std::map<MeshKey, int> m_meshIndex;
};

}  // namespace interplay
