#include "app/viewport/renderer.h"

#include "app/viewport/look.h"
#include "app/viewport/shape_mesh.h"

#include <QOpenGLShaderProgram>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace interplay {
namespace {

using look::srgb;

constexpr int kMaxCachedMeshes = 512;  // distinct shapes kept on the GPU between worlds
constexpr int kShadowMapSize = 2048;

// Vertex attribute locations, as the shaders declare them.
constexpr unsigned kPositionAttribute = 0;
constexpr unsigned kNormalAttribute = 1;     // meshes; the overlay lines' colour takes the same slot
constexpr unsigned kModelAttribute = 2;      // per instance, a mat4: four vec4 locations
constexpr unsigned kColorAttribute = 6;      // per instance

// Builds the program from the resources :/viewport/shaders/<name>.vert.glsl and .frag.glsl.
std::unique_ptr<QOpenGLShaderProgram> makeProgram(const char* name) {
    auto program = std::make_unique<QOpenGLShaderProgram>();
    const QString base = QStringLiteral(":/viewport/shaders/%1").arg(QLatin1String(name));
    if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, base + QStringLiteral(".vert.glsl")) ||
        !program->addShaderFromSourceFile(QOpenGLShader::Fragment, base + QStringLiteral(".frag.glsl")) ||
        !program->link()) {
        qWarning("Viewport: shader program \"%s\" failed to build:\n%s", name, qPrintable(program->log()));
    }
    return program;
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec3& v) {
    program.setUniformValue(name, v.x, v.y, v.z);
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec2& v) {
    program.setUniformValue(name, v.x, v.y);
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m) {
    // glm and QMatrix4x4 are both column-major in memory; QMatrix4x4's constructor takes rows.
    program.setUniformValue(name, QMatrix4x4(glm::value_ptr(glm::transpose(m))));
}

const void* byteOffset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

// ---- GL lifetime ------------------------------------------------------------------------------

void Renderer::initialize(unsigned defaultFramebuffer) {
    initializeOpenGLFunctions();
    m_bodyProgram = makeProgram("body");
    m_shadowProgram = makeProgram("shadow");
    m_skyProgram = makeProgram("sky");
    m_gridProgram = makeProgram("grid");
    m_flatProgram = makeProgram("flat");
    m_lineProgram = makeProgram("line");
    glGenVertexArrays(1, &m_emptyVao);
    glGenBuffers(1, &m_instanceVbo);

    glGenVertexArrays(1, &m_overlayVao);
    glGenBuffers(1, &m_overlayVbo);
    glBindVertexArray(m_overlayVao);
    glBindBuffer(GL_ARRAY_BUFFER, m_overlayVbo);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          byteOffset(offsetof(OverlayVertex, position)));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          byteOffset(offsetof(OverlayVertex, color)));
    glBindVertexArray(0);
    createShadowMap(defaultFramebuffer);
    m_ready = true;
}

void Renderer::createShadowMap(unsigned defaultFramebuffer) {
    glGenTextures(1, &m_shadowTexture);
    glBindTexture(GL_TEXTURE_2D, m_shadowTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowMapSize, kShadowMapSize, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, nullptr);
    // Linear filtering of a comparison sampler gives hardware 2x2 PCF on top of the shader's 3x3.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenFramebuffers(1, &m_shadowFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_shadowFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_shadowTexture, 0);
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        qWarning("Viewport: shadow framebuffer incomplete; drawing without shadows");
        glDeleteFramebuffers(1, &m_shadowFbo);
        m_shadowFbo = 0;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebuffer);
}

void Renderer::release() {
    if (!m_ready) return;
    releaseMeshes();
    m_bodyProgram.reset();
    m_shadowProgram.reset();
    m_skyProgram.reset();
    m_gridProgram.reset();
    m_flatProgram.reset();
    m_lineProgram.reset();
    glDeleteVertexArrays(1, &m_emptyVao);
    glDeleteVertexArrays(1, &m_overlayVao);
    glDeleteBuffers(1, &m_overlayVbo);
    glDeleteBuffers(1, &m_instanceVbo);
    if (m_shadowFbo) glDeleteFramebuffers(1, &m_shadowFbo);
    glDeleteTextures(1, &m_shadowTexture);
    m_emptyVao = m_overlayVao = m_overlayVbo = m_instanceVbo = m_shadowFbo = m_shadowTexture = 0;
    m_ready = false;
}

void Renderer::releaseMeshes() {
    for (GpuMesh& mesh : m_meshes) {
        glDeleteVertexArrays(1, &mesh.vao);
        glDeleteBuffers(1, &mesh.vbo);
        glDeleteBuffers(1, &mesh.ibo);
    }
    m_meshes.clear();
    m_meshIndex.clear();
}

// ---- Meshes -----------------------------------------------------------------------------------

int Renderer::meshFor(const simcore::Shape& shape) {
    // Only the dimensions the type uses go into the key, so equal shapes always share.
    MeshKey key{static_cast<int>(shape.type), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, nullptr};
    switch (shape.type) {
    case simcore::ShapeType::Box:
        std::get<1>(key) = shape.halfExtents.x;
        std::get<2>(key) = shape.halfExtents.y;
        std::get<3>(key) = shape.halfExtents.z;
        break;
    case simcore::ShapeType::Sphere: std::get<4>(key) = shape.radius; break;
    case simcore::ShapeType::Capsule:
    case simcore::ShapeType::Cylinder:
        std::get<4>(key) = shape.radius;
        std::get<5>(key) = shape.halfHeight;
        break;
    case simcore::ShapeType::ConvexHull: std::get<6>(key) = shape.hull.get(); break;
    case simcore::ShapeType::Compound: break;  // drawn child by child (body_batches.h)
    case simcore::ShapeType::Mesh: std::get<6>(key) = shape.mesh.get(); break;
    case simcore::ShapeType::HeightField: std::get<6>(key) = shape.heightField.get(); break;
    }
    if (const auto it = m_meshIndex.find(key); it != m_meshIndex.end()) return it->second;

    const ShapeMesh mesh = buildShapeMesh(shape);
    GpuMesh gpu;
    gpu.shared = shape.hull ? std::shared_ptr<const void>(shape.hull)
                : shape.mesh ? std::shared_ptr<const void>(shape.mesh)
                             : std::shared_ptr<const void>(shape.heightField);
    gpu.indexCount = static_cast<int>(mesh.indices.size());
    glGenVertexArrays(1, &gpu.vao);
    glGenBuffers(1, &gpu.vbo);
    glGenBuffers(1, &gpu.ibo);
    glBindVertexArray(gpu.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                          byteOffset(offsetof(MeshVertex, position)));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                          byteOffset(offsetof(MeshVertex, normal)));
    // The instance attributes advance once per instance; drawInstances points them into the
    // frame's instance buffer.
    for (unsigned column = 0; column < 4; ++column) {
        glEnableVertexAttribArray(kModelAttribute + column);
        glVertexAttribDivisor(kModelAttribute + column, 1);
    }
    glEnableVertexAttribArray(kColorAttribute);
    glVertexAttribDivisor(kColorAttribute, 1);
    glBindVertexArray(0);

    m_meshes.push_back(gpu);
    const int index = static_cast<int>(m_meshes.size()) - 1;
    m_meshIndex.emplace(key, index);
    return index;
}

void Renderer::trimMeshCache() {
    if (m_meshes.size() > static_cast<std::size_t>(kMaxCachedMeshes)) releaseMeshes();
}

// ---- Passes -----------------------------------------------------------------------------------

std::vector<std::size_t> Renderer::uploadInstances(const std::vector<std::vector<BodyInstance>>& instancesByMesh) {
    std::vector<std::size_t> first(instancesByMesh.size());
    std::size_t total = 0;
    for (std::size_t m = 0; m < instancesByMesh.size(); ++m) {
        first[m] = total;
        total += instancesByMesh[m].size();
    }
    glBindBuffer(GL_ARRAY_BUFFER, m_instanceVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(total * sizeof(BodyInstance)), nullptr, GL_STREAM_DRAW);
    for (std::size_t m = 0; m < instancesByMesh.size(); ++m) {
        const auto& instances = instancesByMesh[m];
        if (instances.empty()) continue;
        glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first[m] * sizeof(BodyInstance)),
                        static_cast<GLsizeiptr>(instances.size() * sizeof(BodyInstance)), instances.data());
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return first;
}

void Renderer::drawInstances(const std::vector<std::vector<BodyInstance>>& instancesByMesh,
                             const std::vector<std::size_t>& firstInstance) {
    for (std::size_t m = 0; m < instancesByMesh.size() && m < m_meshes.size(); ++m) {
        const auto count = static_cast<GLsizei>(instancesByMesh[m].size());
        if (count == 0) continue;
        const GpuMesh& mesh = m_meshes[m];
        glBindVertexArray(mesh.vao);
        // GL 3.3 has no base instance: point the instance attributes at this mesh's run instead.
        glBindBuffer(GL_ARRAY_BUFFER, m_instanceVbo);
        const std::size_t base = firstInstance[m] * sizeof(BodyInstance);
        for (unsigned column = 0; column < 4; ++column) {
            glVertexAttribPointer(kModelAttribute + column, 4, GL_FLOAT, GL_FALSE, sizeof(BodyInstance),
                                  byteOffset(base + offsetof(BodyInstance, model) + column * sizeof(glm::vec4)));
        }
        glVertexAttribPointer(kColorAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(BodyInstance),
                              byteOffset(base + offsetof(BodyInstance, color)));
        glDrawElementsInstanced(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, count);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
}

glm::mat4 Renderer::lightViewProjection(const Camera& camera) {
    // Shadow the region around what is in view: the camera target, out to a distance that grows
    // with the zoom, but never wider than needed for the movable bodies.
    const glm::vec3 center = camera.target();
    const float radius = std::clamp(1.5f * camera.distance(), 4.0f, 80.0f);
    const glm::vec3 eye = center + look::kLightDirection * (radius + 100.0f);
    const glm::mat4 view = glm::lookAt(eye, center, glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, 1.0f, 2.0f * radius + 200.0f);
    return projection * view;
}

void Renderer::render(const Frame& frame) {
    if (!m_ready) return;
    const Camera& camera = frame.camera;
    const int pixelWidth = static_cast<int>(std::lround(static_cast<float>(frame.width) * frame.devicePixelRatio));
    const int pixelHeight = static_cast<int>(std::lround(static_cast<float>(frame.height) * frame.devicePixelRatio));
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(std::max(frame.height, 1));
    const glm::mat4 viewProjection = camera.viewProjection(aspect);
    const glm::mat4 lightViewProjection = Renderer::lightViewProjection(camera);
    const glm::vec3 eye = camera.eye();
    const bool haveBodies = std::any_of(frame.instancesByMesh.begin(), frame.instancesByMesh.end(),
                                        [](const auto& instances) { return !instances.empty(); });
    const std::vector<std::size_t> firstInstance =
        haveBodies ? uploadInstances(frame.instancesByMesh) : std::vector<std::size_t>{};

    // 1. Shadow map: depth of the bodies seen from the light. Back faces only, which moves the
    //    stored depth to the far side of each body and keeps lit faces free of acne.
    if (haveBodies && m_shadowFbo) {
        glBindFramebuffer(GL_FRAMEBUFFER, m_shadowFbo);
        glViewport(0, 0, kShadowMapSize, kShadowMapSize);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        m_shadowProgram->bind();
        setUniform(*m_shadowProgram, "uLightViewProjection", lightViewProjection);
        drawInstances(frame.instancesByMesh, firstInstance);
        glCullFace(GL_BACK);
        glBindFramebuffer(GL_FRAMEBUFFER, frame.defaultFramebuffer);
    }
    glViewport(0, 0, pixelWidth, pixelHeight);

    // 2. Sky: a gradient by view direction, so it tilts with the camera.
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    m_skyProgram->bind();
    setUniform(*m_skyProgram, "uInverseViewProjection", glm::inverse(viewProjection));
    setUniform(*m_skyProgram, "uZenith", srgb(look::kSkyZenith));
    setUniform(*m_skyProgram, "uHorizon", srgb(look::kSkyHorizon));
    setUniform(*m_skyProgram, "uBelow", srgb(look::kBelowHorizon));
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Distance fog fades the floor's far edge into the horizon.
    const float fogStart = std::max(4.0f * camera.distance(), 30.0f);
    const glm::vec2 fogRange(fogStart, 3.0f * fogStart);

    // 3. Bodies, lit and shadowed.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    if (haveBodies) {
        m_bodyProgram->bind();
        setUniform(*m_bodyProgram, "uViewProjection", viewProjection);
        setUniform(*m_bodyProgram, "uLightViewProjection", lightViewProjection);
        setUniform(*m_bodyProgram, "uEye", eye);
        setUniform(*m_bodyProgram, "uLightDir", look::kLightDirection);
        setUniform(*m_bodyProgram, "uLightColor", glm::vec3(0.86f, 0.83f, 0.78f));
        setUniform(*m_bodyProgram, "uSkyAmbient", 0.34f * srgb(look::kSkyHorizon));
        setUniform(*m_bodyProgram, "uGroundAmbient", 0.12f * srgb(look::kBelowHorizon));
        setUniform(*m_bodyProgram, "uFogColor", srgb(look::kSkyHorizon));
        setUniform(*m_bodyProgram, "uFogRange", fogRange);
        m_bodyProgram->setUniformValue("uShadowTexel", 1.0f / static_cast<float>(kShadowMapSize));
        m_bodyProgram->setUniformValue("uShadowMap", 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, m_shadowTexture);
        if (!m_shadowFbo) {
            // No shadow pass: make every lookup fall outside the map, i.e. lit.
            setUniform(*m_bodyProgram, "uLightViewProjection", glm::mat4(0.0f));
        }
        drawInstances(frame.instancesByMesh, firstInstance);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    // 4. Grid on y = 0, over the floor: blended, not depth-written, pulled slightly towards the
    //    camera so it wins against a floor whose top face is also at y = 0 (no z-fighting).
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    // Keep destination alpha at 1 so the grabbed image and the window composition stay opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    m_gridProgram->bind();
    const glm::vec3 target = camera.target();
    const float extent = std::max(60.0f, 20.0f * camera.distance());
    setUniform(*m_gridProgram, "uViewProjection", viewProjection);
    // Snap the centre to the major spacing so lines do not swim as the camera pans.
    setUniform(*m_gridProgram, "uCenter", glm::round(glm::vec2(target.x, target.z) / 10.0f) * 10.0f);
    m_gridProgram->setUniformValue("uExtent", extent);
    setUniform(*m_gridProgram, "uEye", eye);
    setUniform(*m_gridProgram, "uFadeRange", glm::vec2(0.5f * fogStart, 1.5f * fogStart));
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);

    // 5. Selection and debug overlays, over everything.
    if (haveBodies) {
        drawSelectionOutline(frame, viewProjection);
        drawLines(frame.lines, viewProjection);
    }
    // 6. Screen-space overlays (the transform gizmo), over the debug lines too.
    drawScreenTriangles(frame);
}

void Renderer::drawSelectionOutline(const Frame& frame, const glm::mat4& viewProjection) {
    if (frame.outlined.empty()) return;
    const Camera& camera = frame.camera;
    // Stencil outline: mark the bodies' silhouettes, then draw them grown by a few pixels where
    // the mark is not. Both passes ignore depth, so a selected body stays findable behind others.
    const float pixelsToMetres = 2.0f * std::tan(0.5f * glm::radians(camera.fovYDegrees())) /
                                 static_cast<float>(std::max(frame.height, 1));
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xFF);
    m_flatProgram->bind();
    setUniform(*m_flatProgram, "uViewProjection", viewProjection);
    setUniform(*m_flatProgram, "uColor", srgb(look::kSelectionColor));
    for (int pass = 0; pass < 2; ++pass) {
        const bool markPass = pass == 0;
        glColorMask(!markPass, !markPass, !markPass, !markPass);
        glStencilFunc(markPass ? GL_ALWAYS : GL_NOTEQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, markPass ? GL_REPLACE : GL_KEEP);
        for (const OutlinedBody& body : frame.outlined) {
            if (body.mesh < 0 || static_cast<std::size_t>(body.mesh) >= m_meshes.size()) continue;
            glm::mat4 model = body.model;
            if (!markPass) {
                // Grow the shape about its bounds' centre by the outline width on every side.
                const glm::vec3 position(body.model[3]);
                // An orthographic pixel is as wide at every depth as a perspective one at the target.
                const float depth = camera.isOrthographic()
                                        ? camera.distance()
                                        : std::max(glm::length(position - camera.eye()), camera.nearPlane());
                const glm::vec3 grow = glm::vec3(look::kOutlinePixels * pixelsToMetres * depth);
                model = model * glm::translate(glm::mat4(1.0f), body.localCenter) *
                        glm::scale(glm::mat4(1.0f), (body.localHalfSize + grow) / body.localHalfSize) *
                        glm::translate(glm::mat4(1.0f), -body.localCenter);
            }
            setUniform(*m_flatProgram, "uModel", model);
            const GpuMesh& mesh = m_meshes[static_cast<std::size_t>(body.mesh)];
            glBindVertexArray(mesh.vao);
            glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
}

void Renderer::drawLines(const std::vector<OverlayVertex>& lines, const glm::mat4& viewProjection) {
    if (lines.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, m_overlayVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(OverlayVertex)), lines.data(),
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    // On top of everything: contacts lie between bodies, where depth would hide them.
    glDisable(GL_DEPTH_TEST);
    m_lineProgram->bind();
    setUniform(*m_lineProgram, "uViewProjection", viewProjection);
    glBindVertexArray(m_overlayVao);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
}

void Renderer::drawScreenTriangles(const Frame& frame) {
    const std::vector<OverlayVertex>& triangles = frame.screenTriangles;
    if (triangles.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, m_overlayVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(OverlayVertex)), triangles.data(),
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);  // strokes are wound either way
    m_lineProgram->bind();
    // Widget pixels to clip space, y down as Qt's pixels are.
    const glm::mat4 pixels = glm::ortho(0.0f, static_cast<float>(std::max(frame.width, 1)),
                                        static_cast<float>(std::max(frame.height, 1)), 0.0f, -1.0f, 1.0f);
    setUniform(*m_lineProgram, "uViewProjection", pixels);
    glBindVertexArray(m_overlayVao);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.size()));
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace interplay
