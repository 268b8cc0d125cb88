#include "app/viewport/viewport.h"

#include "app/simulation/simulation_controller.h"
#include "app/viewport/shape_mesh.h"

#include "simcore/world/world.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QWheelEvent>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace interplay {
namespace {

// ---- Look -------------------------------------------------------------------------------------
// Colours are written in sRGB (as a designer picks them) and converted to linear for lighting;
// the shaders convert back to sRGB on output.

glm::vec3 srgb(unsigned rgb) {
    const auto channel = [](unsigned v) {
        const float c = static_cast<float>(v) / 255.0f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    return {channel((rgb >> 16) & 0xFF), channel((rgb >> 8) & 0xFF), channel(rgb & 0xFF)};
}

const std::array<unsigned, 8> kPalette = {
    0xE4572E,  // vermilion
    0x2E86AB,  // blue
    0xF3A712,  // amber
    0x4C9F70,  // green
    0xA23B72,  // magenta
    0x17BEBB,  // teal
    0x7D5BA6,  // violet
    0x9BC53D,  // lime
};
constexpr unsigned kStaticColor = 0xA7ABB0;  // neutral grey: the floor should not compete with the bodies

constexpr unsigned kSkyZenith = 0x6F9BD1;
constexpr unsigned kSkyHorizon = 0xD9E3EC;
constexpr unsigned kBelowHorizon = 0xC3C9D0;  // close to a lit floor, so a floor's edge does not stand out

// Towards the light (world space): high and from the front left of the default camera, so the faces
// turned to the viewer are lit and shadows fall behind the bodies, to the right.
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(-0.35f, 1.0f, 0.55f));
constexpr int kShadowMapSize = 2048;

// ---- Shaders (GLSL 3.30 core) -----------------------------------------------------------------

const char* kBodyVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat4 uLightViewProjection;
out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vLightClip;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(uModel) * aNormal;  // rigid transform: no inverse-transpose needed
    vLightClip = uLightViewProjection * world;
    gl_Position = uViewProjection * world;
}
)";

const char* kBodyFragmentShader = R"(#version 330 core
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vLightClip;
uniform vec3 uColor;
uniform vec3 uEye;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
uniform vec3 uFogColor;
uniform vec2 uFogRange;
uniform float uShadowTexel;
uniform sampler2DShadow uShadowMap;
out vec4 fragColor;

float lightVisibility(vec3 n) {
    vec3 p = vLightClip.xyz / vLightClip.w * 0.5 + 0.5;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    // Slope-scaled bias against acne on faces lit at grazing angles.
    float cosTheta = clamp(dot(n, uLightDir), 0.0, 1.0);
    p.z -= uShadowTexel * (1.5 + 3.0 * sqrt(1.0 - cosTheta * cosTheta) / max(cosTheta, 0.2));
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            sum += texture(uShadowMap, vec3(p.xy + vec2(x, y) * uShadowTexel, p.z));
    return sum / 9.0;
}

void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uEye - vWorldPos);
    float diffuse = max(dot(n, uLightDir), 0.0);
    float visible = diffuse > 0.0 ? lightVisibility(n) : 0.0;
    // Hemispheric ambient: sky from above, bounce from the floor below.
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
    // A weak fill from the opposite side keeps shadowed faces from going flat.
    float fill = 0.18 * max(dot(n, normalize(vec3(-uLightDir.x, 0.3, -uLightDir.z))), 0.0);
    vec3 h = normalize(uLightDir + v);
    float specular = diffuse > 0.0 ? 0.25 * pow(max(dot(n, h), 0.0), 48.0) : 0.0;
    vec3 color = uColor * (ambient + fill + uLightColor * diffuse * visible) + uLightColor * specular * visible;
    float fog = smoothstep(uFogRange.x, uFogRange.y, length(uEye - vWorldPos));
    color = mix(color, uFogColor, fog);
    fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
)";

const char* kShadowVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProjection;
void main() { gl_Position = uLightViewProjection * uModel * vec4(aPosition, 1.0); }
)";

const char* kShadowFragmentShader = R"(#version 330 core
void main() {}
)";

// Full-screen triangle; the fragment shader turns each pixel into a view ray.
const char* kSkyVertexShader = R"(#version 330 core
out vec2 vNdc;
void main() {
    vNdc = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    gl_Position = vec4(vNdc, 0.0, 1.0);
}
)";

const char* kSkyFragmentShader = R"(#version 330 core
in vec2 vNdc;
uniform mat4 uInverseViewProjection;
uniform vec3 uZenith;
uniform vec3 uHorizon;
uniform vec3 uBelow;
out vec4 fragColor;
void main() {
    vec4 nearPoint = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    vec3 color = dir.y >= 0.0 ? mix(uHorizon, uZenith, pow(dir.y, 0.6))
                              : mix(uHorizon, uBelow, clamp(-dir.y * 6.0, 0.0, 1.0));
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
)";

// A square on y = 0 around the camera target; lines are computed per pixel (anti-aliased with
// fwidth) so they stay one pixel wide at any distance and fade before they turn into moire.
const char* kGridVertexShader = R"(#version 330 core
uniform mat4 uViewProjection;
uniform vec2 uCenter;
uniform float uExtent;
out vec3 vWorldPos;
void main() {
    vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
    vWorldPos = vec3(uCenter.x + corner.x * uExtent, 0.0, uCenter.y + corner.y * uExtent);
    gl_Position = uViewProjection * vec4(vWorldPos, 1.0);
}
)";

const char* kGridFragmentShader = R"(#version 330 core
in vec3 vWorldPos;
uniform vec3 uEye;
uniform vec2 uFadeRange;
out vec4 fragColor;

// Coverage of the lines at integer values of coord (about 1.2 pixels wide).
float lines(vec2 coord) {
    vec2 width = fwidth(coord);
    vec2 distance = abs(fract(coord - 0.5) - 0.5) / max(width * 1.2, vec2(1e-6));
    float coverage = 1.0 - min(min(distance.x, distance.y), 1.0);
    // Lines closer than a few pixels apart would alias; fade them out instead.
    return coverage * (1.0 - smoothstep(0.15, 0.4, max(width.x, width.y)));
}

float axisLine(float value) {
    float width = fwidth(value) * 1.6;
    return 1.0 - min(abs(value) / max(width, 1e-6), 1.0);
}

void main() {
    vec2 xz = vWorldPos.xz;
    float minor = lines(xz);         // 1 m
    float major = lines(xz / 10.0);  // 10 m
    vec3 color = vec3(0.16, 0.17, 0.19);
    float alpha = max(minor * 0.28, major * 0.55);
    // World axes: X in red along z = 0, Z in blue along x = 0.
    float ax = axisLine(xz.y), az = axisLine(xz.x);
    if (ax > 0.0 || az > 0.0) {
        color = ax >= az ? vec3(0.75, 0.12, 0.10) : vec3(0.10, 0.25, 0.80);
        alpha = max(alpha, max(ax, az) * 0.8);
    }
    alpha *= 1.0 - smoothstep(uFadeRange.x, uFadeRange.y, length(uEye - vWorldPos));
    if (alpha <= 0.002) discard;
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), alpha);
}
)";

QOpenGLShaderProgram* makeProgram(QObject* parent, const char* vertex, const char* fragment) {
    auto* program = new QOpenGLShaderProgram(parent);
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program->link()) {
        qWarning("Viewport: shader program failed to build:\n%s", qPrintable(program->log()));
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

glm::mat4 modelMatrix(const simcore::Transform& t) {
    glm::mat4 m = glm::mat4_cast(t.rotation);
    m[3] = glm::vec4(t.position, 1.0f);
    return m;
}

}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
}

Viewport::~Viewport() {
    cleanup();
}

void Viewport::setSimulation(SimulationController* simulation) {
    if (m_simulation) disconnect(m_simulation, nullptr, this, nullptr);
    m_simulation = simulation;
    m_drawListDirty = true;
    if (m_simulation) {
        connect(m_simulation, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
        connect(m_simulation, &SimulationController::worldRebuilt, this, [this] {
            m_drawListDirty = true;
            update();
        });
    }
    update();
}

void Viewport::frameScene() {
    m_framePending = true;
    update();
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

glm::vec3 Viewport::displayColor(std::size_t sceneIndex, const std::optional<glm::vec3>& authored,
                                 simcore::MotionType motion) {
    if (authored) return *authored;
    if (motion == simcore::MotionType::Static) return srgb(kStaticColor);
    return srgb(kPalette[sceneIndex % kPalette.size()]);
}

// ---- GL lifetime ------------------------------------------------------------------------------

void Viewport::initializeGL() {
    // The context can be recreated (e.g. the widget moves to another top-level window): release
    // everything tied to the old one first, as hellogl2 does.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanup, Qt::UniqueConnection);
    initializeOpenGLFunctions();

    m_bodyProgram = makeProgram(this, kBodyVertexShader, kBodyFragmentShader);
    m_shadowProgram = makeProgram(this, kShadowVertexShader, kShadowFragmentShader);
    m_skyProgram = makeProgram(this, kSkyVertexShader, kSkyFragmentShader);
    m_gridProgram = makeProgram(this, kGridVertexShader, kGridFragmentShader);
    glGenVertexArrays(1, &m_emptyVao);
    createShadowMap();

    m_drawListDirty = true;
    m_glReady = true;
}

void Viewport::createShadowMap() {
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
    glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
}

void Viewport::cleanup() {
    if (!m_glReady) return;
    // Called from the destructor and from aboutToBeDestroyed; GL calls need the context current.
    makeCurrent();
    releaseMeshes();
    delete m_bodyProgram;
    delete m_shadowProgram;
    delete m_skyProgram;
    delete m_gridProgram;
    m_bodyProgram = m_shadowProgram = m_skyProgram = m_gridProgram = nullptr;
    glDeleteVertexArrays(1, &m_emptyVao);
    if (m_shadowFbo) glDeleteFramebuffers(1, &m_shadowFbo);
    glDeleteTextures(1, &m_shadowTexture);
    m_emptyVao = m_shadowFbo = m_shadowTexture = 0;
    m_glReady = false;
    doneCurrent();
}

void Viewport::releaseMeshes() {
    for (GpuMesh& mesh : m_meshes) {
        glDeleteVertexArrays(1, &mesh.vao);
        glDeleteBuffers(1, &mesh.vbo);
        glDeleteBuffers(1, &mesh.ibo);
    }
    m_meshes.clear();
    m_meshIndex.clear();
    m_draws.clear();
    m_drawListDirty = true;
}

// ---- Meshes -----------------------------------------------------------------------------------

int Viewport::meshFor(const simcore::Shape& shape) {
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
    }
    if (const auto it = m_meshIndex.find(key); it != m_meshIndex.end()) return it->second;

    const ShapeMesh mesh = buildShapeMesh(shape);
    GpuMesh gpu;
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
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                          reinterpret_cast<const void*>(offsetof(MeshVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                          reinterpret_cast<const void*>(offsetof(MeshVertex, normal)));
    glBindVertexArray(0);

    m_meshes.push_back(gpu);
    const int index = static_cast<int>(m_meshes.size()) - 1;
    m_meshIndex.emplace(key, index);
    return index;
}

void Viewport::rebuildDrawList() {
    // A new world may hold entirely different shapes: start the cache afresh.
    releaseMeshes();
    m_drawListDirty = false;
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world) return;
    const auto& ids = m_simulation->bodyIds();
    const auto& colors = m_simulation->authoredColors();
    m_draws.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!world->contains(ids[i])) continue;
        const std::optional<glm::vec3> authored = i < colors.size() ? colors[i] : std::nullopt;
        m_draws.push_back({ids[i], meshFor(world->shape(ids[i])), displayColor(i, authored, world->motionType(ids[i]))});
    }
}

// ---- Frame ------------------------------------------------------------------------------------

void Viewport::applyPendingFrame() {
    if (!m_framePending || width() <= 0 || height() <= 0) return;
    m_framePending = false;
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world || world->bodyCount() == 0) return;

    // Frame what moves; a floor would otherwise set the scale. Fall back to everything.
    const simcore::BodyStorage& bodies = world->bodies();
    simcore::Aabb moving, all;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const simcore::Aabb b = simcore::worldBounds(bodies.shape[i], bodies.transform(i));
        all.grow(b);
        if (bodies.motion[i] != simcore::MotionType::Static) moving.grow(b);
    }
    simcore::Aabb box = moving.isEmpty() ? all : moving;
    // Include the floor under the bodies, so where they will land is in view too.
    if (!moving.isEmpty()) {
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (bodies.motion[i] != simcore::MotionType::Static) continue;
            const simcore::Aabb b = simcore::worldBounds(bodies.shape[i], bodies.transform(i));
            const bool under = b.max.y <= box.min.y + 1e-3f && b.min.x <= box.max.x && box.min.x <= b.max.x &&
                               b.min.z <= box.max.z && box.min.z <= b.max.z;
            if (under && box.min.y - b.max.y < 20.0f) box.min.y = std::min(box.min.y, b.max.y);
        }
    }
    m_camera.frameBox(box.min, box.max, static_cast<float>(width()) / static_cast<float>(height()), 0.15f);
    emit cameraChanged();
}

glm::mat4 Viewport::lightViewProjection() const {
    // Shadow the region around what is in view: the camera target, out to a distance that grows
    // with the zoom, but never wider than needed for the movable bodies.
    const glm::vec3 center = m_camera.target();
    const float radius = std::clamp(1.5f * m_camera.distance(), 4.0f, 80.0f);
    const glm::vec3 eye = center + kLightDirection * (radius + 100.0f);
    const glm::mat4 view = glm::lookAt(eye, center, glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, 1.0f, 2.0f * radius + 200.0f);
    return projection * view;
}

void Viewport::drawBodies(QOpenGLShaderProgram& program, bool shadowPass) {
    const simcore::World* world = m_simulation->world();
    const simcore::BodyStorage& bodies = world->bodies();
    for (const BodyDraw& draw : m_draws) {
        const int dense = bodies.denseIndex(draw.id);
        if (dense < 0 || draw.mesh < 0) continue;
        setUniform(program, "uModel", modelMatrix(bodies.transform(static_cast<std::size_t>(dense))));
        if (!shadowPass) setUniform(program, "uColor", draw.color);
        const GpuMesh& mesh = m_meshes[static_cast<std::size_t>(draw.mesh)];
        glBindVertexArray(mesh.vao);
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

void Viewport::paintGL() {
    if (!m_glReady) return;
    if (m_drawListDirty) rebuildDrawList();
    applyPendingFrame();

    const float dpr = static_cast<float>(devicePixelRatio());
    const int pixelWidth = static_cast<int>(std::lround(width() * dpr));
    const int pixelHeight = static_cast<int>(std::lround(height() * dpr));
    const float aspect = static_cast<float>(width()) / static_cast<float>(std::max(height(), 1));
    const glm::mat4 viewProjection = m_camera.viewProjection(aspect);
    const glm::mat4 lightViewProjection = this->lightViewProjection();
    const glm::vec3 eye = m_camera.eye();
    const bool haveBodies = m_simulation && m_simulation->world() && !m_draws.empty();

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
        drawBodies(*m_shadowProgram, true);
        glCullFace(GL_BACK);
        glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    }
    glViewport(0, 0, pixelWidth, pixelHeight);

    // 2. Sky: a gradient by view direction, so it tilts with the camera.
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    m_skyProgram->bind();
    setUniform(*m_skyProgram, "uInverseViewProjection", glm::inverse(viewProjection));
    setUniform(*m_skyProgram, "uZenith", srgb(kSkyZenith));
    setUniform(*m_skyProgram, "uHorizon", srgb(kSkyHorizon));
    setUniform(*m_skyProgram, "uBelow", srgb(kBelowHorizon));
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Distance fog fades the floor's far edge into the horizon.
    const float fogStart = std::max(4.0f * m_camera.distance(), 30.0f);
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
        setUniform(*m_bodyProgram, "uLightDir", kLightDirection);
        setUniform(*m_bodyProgram, "uLightColor", glm::vec3(0.86f, 0.83f, 0.78f));
        setUniform(*m_bodyProgram, "uSkyAmbient", 0.34f * srgb(kSkyHorizon));
        setUniform(*m_bodyProgram, "uGroundAmbient", 0.12f * srgb(kBelowHorizon));
        setUniform(*m_bodyProgram, "uFogColor", srgb(kSkyHorizon));
        setUniform(*m_bodyProgram, "uFogRange", fogRange);
        m_bodyProgram->setUniformValue("uShadowTexel", 1.0f / static_cast<float>(kShadowMapSize));
        m_bodyProgram->setUniformValue("uShadowMap", 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, m_shadowTexture);
        if (!m_shadowFbo) {
            // No shadow pass: make every lookup fall outside the map, i.e. lit.
            setUniform(*m_bodyProgram, "uLightViewProjection", glm::mat4(0.0f));
        }
        drawBodies(*m_bodyProgram, false);
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
    const glm::vec3 target = m_camera.target();
    const float extent = std::max(60.0f, 20.0f * m_camera.distance());
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
}

// ---- Mouse ------------------------------------------------------------------------------------

void Viewport::mousePressEvent(QMouseEvent* event) {
    const bool pan = event->button() == Qt::MiddleButton ||
                     (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (pan) {
        m_drag = Drag::Pan;
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::Orbit;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    m_lastMouse = event->position().toPoint();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (m_drag == Drag::Orbit) {
        m_camera.orbit(static_cast<float>(delta.x()), static_cast<float>(delta.y()));
    } else {
        m_camera.pan(static_cast<float>(delta.x()), static_cast<float>(delta.y()), static_cast<float>(height()));
    }
    emit cameraChanged();
    update();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    m_drag = Drag::None;
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    // 120 units per notch; touchpads send smaller deltas, which zoom proportionally.
    m_camera.zoom(static_cast<float>(event->angleDelta().y()) / 120.0f);
    emit cameraChanged();
    update();
    event->accept();
}

}  // namespace interplay
