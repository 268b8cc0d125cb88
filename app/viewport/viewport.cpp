#include "app/viewport/viewport.h"

#include "app/document/scene_document.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/color_space.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/shape_mesh.h"

#include "simcore/world/world.h"

#include <QKeyEvent>
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
    const auto channel = [](unsigned v) { return linearFromSrgb(static_cast<float>(v) / 255.0f); };
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
constexpr unsigned kSelectionColor = 0xFFB000;  // amber: reads against sky, floor and every palette colour
constexpr unsigned kSleepingTint = 0x6E7A8A;    // slate: sleeping bodies fade towards it
constexpr float kSleepingTintAmount = 0.55f;
constexpr float kOutlinePixels = 3.0f;
constexpr unsigned kAabbColor = 0x39D353;
constexpr unsigned kContactPointColor = 0xFF2E88;
constexpr unsigned kContactNormalColor = 0xFFE14D;
constexpr unsigned kGrabColor = 0xFFFFFF;
constexpr unsigned kJointColor = 0x30343A;  // near black: a rod or a hinge pin, drawn always
constexpr float kContactNormalLength = 0.3f;  // m
constexpr float kContactMarkSize = 0.05f;     // m, half-size of the cross marking a contact point
constexpr float kJointMarkSize = 0.12f;       // m, half-size of the cross marking a selected joint's anchor
constexpr float kJointAxisLength = 0.6f;      // m, either way along a selected hinge or slider axis
// How near a click must come to a joint's anchors to pick the joint, in widget pixels (device
// independent, as mouse positions are, so the reach is the same on a high-DPI screen).
constexpr float kJointPickPixels = 8.0f;

constexpr int kMaxCachedMeshes = 512;           // distinct shapes kept on the GPU between worlds

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

// The selection outline: one flat colour, no lighting.
const char* kFlatVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uViewProjection;
void main() { gl_Position = uViewProjection * uModel * vec4(aPosition, 1.0); }
)";

const char* kFlatFragmentShader = R"(#version 330 core
uniform vec3 uColor;
out vec4 fragColor;
void main() { fragColor = vec4(pow(uColor, vec3(1.0 / 2.2)), 1.0); }
)";

// Debug overlays: world-space lines with a colour per vertex.
const char* kLineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aColor;
uniform mat4 uViewProjection;
out vec3 vColor;
void main() {
    vColor = aColor;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* kLineFragmentShader = R"(#version 330 core
in vec3 vColor;
out vec4 fragColor;
void main() { fragColor = vec4(pow(vColor, vec3(1.0 / 2.2)), 1.0); }
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
    m_drawListDirty = true;
    if (m_simulation) {
        connect(m_simulation, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
        const auto markDirty = [this] {
            m_drawListDirty = true;
            update();
        };
        connect(m_simulation, &SimulationController::worldRebuilt, this, markDirty);
        connect(m_simulation, &SimulationController::bodySpawned, this, markDirty);
        connect(m_simulation, &SimulationController::bodiesEdited, this, markDirty);
        // A moved body is drawn from its live pose: the draw list still holds.
        connect(m_simulation, &SimulationController::posesEdited, this, qOverload<>(&QWidget::update));
    }
    update();
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
    if (m_debugDraw) {
        connect(m_debugDraw, &DebugDrawOptions::changed, this, qOverload<>(&QWidget::update));
    }
    update();
}

void Viewport::frameScene() {
    m_framePending = true;
    update();
}

void Viewport::frameSelection() {
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world || !m_document || m_document->selectedBodies().isEmpty()) {
        frameScene();
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
    m_camera.frameBox(box.min, box.max, static_cast<float>(width()) / static_cast<float>(std::max(height(), 1)), 0.3f);
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
    return {m_camera.eye(), glm::normalize(to - from)};
}

std::optional<simcore::WorldRayHit> Viewport::pick(const QPointF& pixel) const {
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world) return std::nullopt;
    const auto [origin, direction] = rayThrough(pixel);
    // Unit direction: the fraction is a distance, and the far plane bounds what can be seen.
    return world->castRay(origin, direction, m_camera.farPlane());
}

int Viewport::sceneBodyAt(const QPointF& pixel) const {
    const auto hit = pick(pixel);
    return hit ? m_simulation->sceneIndexOf(hit->body) : -1;
}

std::optional<Viewport::JointPick> Viewport::pickJoint(const QPointF& pixel) const {
    if (!m_simulation || !m_simulation->world()) return std::nullopt;
    const float w = static_cast<float>(width()), h = static_cast<float>(height());
    const glm::vec2 cursor(static_cast<float>(pixel.x()), static_cast<float>(pixel.y()));
    std::optional<JointPick> nearest;
    float nearestPixels = kJointPickPixels;
    const std::size_t jointCount = m_simulation->authoredScene().joints.size();
    for (std::size_t j = 0; j < jointCount; ++j) {
        const auto anchors = jointAnchors(j);
        if (!anchors) continue;
        // Perspective keeps a segment straight on screen, so its projection is where it is drawn;
        // one reaching behind the eye (or beyond the far plane) is not drawn and is skipped.
        const glm::vec3 a = m_camera.project(anchors->onA, w, h), b = m_camera.project(anchors->onB, w, h);
        if (a.z > 1.0f || b.z > 1.0f) continue;
        const glm::vec2 from(a), along = glm::vec2(b) - from;
        const float lengthSquared = glm::dot(along, along);  // zero where the anchors meet
        const float t =
            lengthSquared > 0.0f ? std::clamp(glm::dot(cursor - from, along) / lengthSquared, 0.0f, 1.0f) : 0.0f;
        const float pixels = glm::length(cursor - (from + t * along));
        if (pixels <= nearestPixels) {
            const glm::vec3 point = glm::mix(anchors->onA, anchors->onB, t);  // near enough under perspective
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
    m_flatProgram = makeProgram(this, kFlatVertexShader, kFlatFragmentShader);
    m_lineProgram = makeProgram(this, kLineVertexShader, kLineFragmentShader);
    glGenVertexArrays(1, &m_emptyVao);

    glGenVertexArrays(1, &m_overlayVao);
    glGenBuffers(1, &m_overlayVbo);
    glBindVertexArray(m_overlayVao);
    glBindBuffer(GL_ARRAY_BUFFER, m_overlayVbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          reinterpret_cast<const void*>(offsetof(OverlayVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          reinterpret_cast<const void*>(offsetof(OverlayVertex, color)));
    glBindVertexArray(0);
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
    delete m_flatProgram;
    delete m_lineProgram;
    m_bodyProgram = m_shadowProgram = m_skyProgram = m_gridProgram = m_flatProgram = m_lineProgram = nullptr;
    glDeleteVertexArrays(1, &m_emptyVao);
    glDeleteVertexArrays(1, &m_overlayVao);
    glDeleteBuffers(1, &m_overlayVbo);
    m_overlayVao = m_overlayVbo = 0;
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
    gpu.hull = shape.hull;
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
    // Meshes outlive a world (an edit rebuilds it with mostly the same shapes); the cache is only
    // dropped when edits of sizes have filled it with shapes no longer in use.
    if (m_meshes.size() > static_cast<std::size_t>(kMaxCachedMeshes)) releaseMeshes();
    m_draws.clear();
    m_drawListDirty = false;
    const simcore::World* world = m_simulation ? m_simulation->world() : nullptr;
    if (!world) return;
    const auto& ids = m_simulation->bodyIds();
    const auto& colors = m_simulation->authoredColors();
    const int authored = static_cast<int>(m_simulation->authoredScene().bodies.size());
    m_draws.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!world->contains(ids[i])) continue;
        const simcore::Shape& shape = world->shape(ids[i]);
        const std::optional<glm::vec3> authoredColor = i < colors.size() ? colors[i] : std::nullopt;
        const simcore::Aabb bounds = simcore::localBounds(shape);
        BodyDraw draw;
        draw.id = ids[i];
        draw.sceneIndex = static_cast<int>(i) < authored ? static_cast<int>(i) : -1;
        draw.mesh = meshFor(shape);
        draw.color = displayColor(i, authoredColor, world->motionType(ids[i]));
        draw.localCenter = bounds.center();
        draw.localHalfSize = glm::max(0.5f * (bounds.max - bounds.min), glm::vec3(1e-4f));
        m_draws.push_back(draw);
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
    const bool tintSleeping = !shadowPass && (!m_debugDraw || m_debugDraw->sleepingTint());
    for (const BodyDraw& draw : m_draws) {
        const int dense = bodies.denseIndex(draw.id);
        if (dense < 0 || draw.mesh < 0) continue;
        const auto i = static_cast<std::size_t>(dense);
        setUniform(program, "uModel", modelMatrix(bodies.transform(i)));
        if (!shadowPass) {
            const bool asleep = bodies.motion[i] == simcore::MotionType::Dynamic && !bodies.awake[i];
            const glm::vec3 color =
                tintSleeping && asleep ? glm::mix(draw.color, srgb(kSleepingTint), kSleepingTintAmount) : draw.color;
            setUniform(program, "uColor", color);
        }
        const GpuMesh& mesh = m_meshes[static_cast<std::size_t>(draw.mesh)];
        glBindVertexArray(mesh.vao);
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

void Viewport::drawSelectionOutline(const glm::mat4& viewProjection) {
    if (!m_document || m_document->selectedBodies().isEmpty()) return;
    const simcore::BodyStorage& bodies = m_simulation->world()->bodies();
    std::vector<std::pair<const BodyDraw*, simcore::Transform>> selected;
    for (const BodyDraw& draw : m_draws) {
        const int dense = bodies.denseIndex(draw.id);
        if (dense < 0 || draw.mesh < 0 || !m_document->selectedBodies().contains(draw.sceneIndex)) continue;
        selected.emplace_back(&draw, bodies.transform(static_cast<std::size_t>(dense)));
    }
    if (selected.empty()) return;

    // Stencil outline: mark the bodies' silhouettes, then draw them grown by a few pixels where
    // the mark is not. Both passes ignore depth, so a selected body stays findable behind others.
    const float pixelsToMetres = 2.0f * std::tan(0.5f * glm::radians(m_camera.fovYDegrees())) /
                                 static_cast<float>(std::max(height(), 1));
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xFF);
    m_flatProgram->bind();
    setUniform(*m_flatProgram, "uViewProjection", viewProjection);
    setUniform(*m_flatProgram, "uColor", srgb(kSelectionColor));
    for (int pass = 0; pass < 2; ++pass) {
        const bool markPass = pass == 0;
        glColorMask(!markPass, !markPass, !markPass, !markPass);
        glStencilFunc(markPass ? GL_ALWAYS : GL_NOTEQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, markPass ? GL_REPLACE : GL_KEEP);
        for (const auto& [draw, transform] : selected) {
            glm::mat4 model = modelMatrix(transform);
            if (!markPass) {
                // Grow the shape about its bounds' centre by the outline width on every side.
                const float depth = std::max(glm::length(transform.position - m_camera.eye()), m_camera.nearPlane());
                const glm::vec3 grow = glm::vec3(kOutlinePixels * pixelsToMetres * depth);
                model = model * glm::translate(glm::mat4(1.0f), draw->localCenter) *
                        glm::scale(glm::mat4(1.0f), (draw->localHalfSize + grow) / draw->localHalfSize) *
                        glm::translate(glm::mat4(1.0f), -draw->localCenter);
            }
            setUniform(*m_flatProgram, "uModel", model);
            const GpuMesh& mesh = m_meshes[static_cast<std::size_t>(draw->mesh)];
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

std::vector<Viewport::OverlayVertex> Viewport::overlayLines() const {
    std::vector<OverlayVertex> lines;
    const simcore::World* world = m_simulation->world();
    const auto addLine = [&lines](const glm::vec3& a, const glm::vec3& b, const glm::vec3& color) {
        lines.push_back({a, color});
        lines.push_back({b, color});
    };
    // Three axis-aligned strokes through `point`, each 2 * halfSize long.
    const auto addCross = [&addLine](const glm::vec3& point, float halfSize, const glm::vec3& color) {
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 d(0.0f);
            d[axis] = halfSize;
            addLine(point - d, point + d, color);
        }
    };
    if (m_debugDraw && m_debugDraw->aabbs()) {
        const glm::vec3 color = srgb(kAabbColor);
        const simcore::BodyStorage& bodies = world->bodies();
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            const simcore::Aabb box = simcore::worldBounds(bodies.shape[i], bodies.transform(i));
            const auto corner = [&box](int c) {
                return glm::vec3((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                 (c & 4) ? box.max.z : box.min.z);
            };
            // The 12 edges: corners differing in exactly one bit.
            for (int c = 0; c < 8; ++c) {
                for (int bit = 1; bit < 8; bit <<= 1) {
                    if (!(c & bit)) addLine(corner(c), corner(c | bit), color);
                }
            }
        }
    }
    const bool points = m_debugDraw && m_debugDraw->contactPoints();
    const bool normals = m_debugDraw && m_debugDraw->contactNormals();
    if (points || normals) {
        const glm::vec3 pointColor = srgb(kContactPointColor), normalColor = srgb(kContactNormalColor);
        for (const simcore::Contact& contact : world->contacts()) {
            const simcore::ContactManifold& manifold = contact.manifold;
            for (int k = 0; k < manifold.pointCount; ++k) {
                const simcore::ContactPoint& p = manifold.points[static_cast<std::size_t>(k)];
                const glm::vec3 mid = 0.5f * (p.pointA + p.pointB);
                if (points) addCross(mid, kContactMarkSize, pointColor);
                if (normals) addLine(mid, mid + manifold.normal * kContactNormalLength, normalColor);
            }
        }
    }
    // Joints: from each body's centre to the joint's point in the world (the anchor, or a distance
    // joint's second point, fixed for a joint to the world: a pendulum shows its rod), or between
    // the two bodies' centres, with a small cross at the live anchor, where a click picks the joint.
    // Selected joints are drawn in the selection colour, with both live anchor points marked large
    // and their hinge or slider axis drawn through the anchor.
    const auto& ids = m_simulation->bodyIds();
    const auto centreOf = [&](std::size_t sceneIndex) -> std::optional<glm::vec3> {
        if (sceneIndex >= ids.size() || !world->contains(ids[sceneIndex])) return std::nullopt;
        return world->centerOfMass(ids[sceneIndex]);
    };
    const auto& joints = m_simulation->authoredScene().joints;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const simcore::SceneJoint& joint = joints[j];
        const bool selected = m_document && m_document->selectedJoints().contains(static_cast<int>(j));
        const glm::vec3 color = srgb(selected ? kSelectionColor : kJointColor);
        const auto a = centreOf(joint.bodyA);
        const glm::vec3 fixedPoint =
            joint.joint.type == simcore::JointType::Distance ? joint.joint.anchorB : joint.joint.anchor;
        const auto b = joint.bodyB ? centreOf(*joint.bodyB) : std::optional<glm::vec3>(fixedPoint);
        if (a && b) addLine(*a, *b, color);
        const auto anchors = jointAnchors(j);
        if (!anchors) continue;
        const bool distance = joint.joint.type == simcore::JointType::Distance;
        const float mark = selected ? kJointMarkSize : 0.5f * kJointMarkSize;
        addCross(anchors->onA, mark, color);
        if (selected || distance) addCross(anchors->onB, mark, color);
        if (!selected) continue;
        if (joint.joint.type == simcore::JointType::Hinge || joint.joint.type == simcore::JointType::Slider) {
            addLine(anchors->onA - anchors->axis * kJointAxisLength, anchors->onA + anchors->axis * kJointAxisLength,
                    color);
        }
    }
    if (const auto grab = m_simulation->grabLine()) addLine(grab->first, grab->second, srgb(kGrabColor));
    return lines;
}

std::optional<Viewport::JointAnchors> Viewport::jointAnchors(std::size_t sceneIndex) const {
    const simcore::World* world = m_simulation->world();
    const auto& jointIds = m_simulation->jointIds();
    if (sceneIndex >= jointIds.size() || !world->contains(jointIds[sceneIndex])) return std::nullopt;
    const simcore::JointStorage& storage = world->joints();
    const simcore::Joint& live = storage.joints[static_cast<std::size_t>(storage.denseIndex(jointIds[sceneIndex]))];
    const simcore::JointGeometry geometry = simcore::jointGeometry(live, storage.poseOf(live.bodyA, world->bodies()),
                                                                   storage.poseOf(live.bodyB, world->bodies()));
    const glm::vec3 onA = world->centerOfMass(live.bodyA) + geometry.armA;
    return JointAnchors{onA, onA + geometry.separation, geometry.axisA};
}

void Viewport::drawOverlays(const glm::mat4& viewProjection) {
    const std::vector<OverlayVertex> lines = overlayLines();
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
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
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

    // 5. Selection and debug overlays, over everything.
    if (haveBodies) {
        drawSelectionOutline(viewProjection);
        drawOverlays(viewProjection);
    }

    const qint64 now = m_frameClock.elapsed();
    m_frameTimes.push_back(now);
    while (!m_frameTimes.empty() && m_frameTimes.front() <= now - 1000) m_frameTimes.pop_front();
}

// ---- Mouse and keys: the selection tool's ------------------------------------------------------

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

void Viewport::focusOutEvent(QFocusEvent* event) {
    m_tool.focusOut();
    QOpenGLWidget::focusOutEvent(event);
}

}  // namespace interplay
