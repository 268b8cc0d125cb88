#include "app/viewport/gizmo_overlay.h"

#include "app/viewport/look.h"

#include <algorithm>
#include <array>
#include <optional>
#include <span>

namespace interplay {
namespace {

using gizmo::Handle;

// The axis colours every 3D editor uses (x red, y green, z blue), light enough to read on the
// dark outline and saturated enough to tell apart on the sky.
constexpr unsigned kAxisColors[] = {0xF0524F, 0x7BC545, 0x4A90F0};
constexpr unsigned kViewRingColor = 0xE4E7EB;
constexpr unsigned kHighlightColor = 0xFFF07A;  // pale yellow: unlike any axis colour and the amber selection
constexpr unsigned kOutlineColor = 0x16181B;
constexpr float kStrokePixels = 3.0f;
constexpr float kOutlinePixels = 2.0f;     // each side of a stroke
constexpr float kBackStrokePixels = 1.5f;  // a ring's far half
constexpr float kBackDimming = 0.45f;      // towards grey, for a ring's far half
constexpr float kArrowHeadLength = 16.0f;
constexpr float kArrowHeadHalfWidth = 6.5f;
constexpr float kCenterDotPixels = 3.0f;  // half-size of the square marking the centre

class Triangles {
public:
    explicit Triangles(std::vector<OverlayVertex>& out) : m_out(out) {}

    void triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, const glm::vec3& color) {
        for (const glm::vec2& p : {a, b, c}) m_out.push_back({glm::vec3(p, 0.0f), color});
    }
    void quad(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, const glm::vec3& color) {
        triangle(a, b, c, color);
        triangle(a, c, d, color);
    }
    // A segment `width` pixels wide with square caps (so that polylines close without gaps).
    void segment(glm::vec2 a, glm::vec2 b, float width, const glm::vec3& color) {
        const glm::vec2 along = b - a;
        const float length = glm::length(along);
        if (length < 1e-4f) return;
        const glm::vec2 d = along / length * (0.5f * width), n(-d.y, d.x);
        quad(a - d - n, b + d - n, b + d + n, a - d + n, color);
    }

private:
    std::vector<OverlayVertex>& m_out;
};

struct Projector {
    const Camera& camera;
    float width, height;
    // Widget pixels, or none behind the eye or beyond the far plane.
    std::optional<glm::vec2> operator()(const glm::vec3& world) const {
        const glm::vec3 p = camera.project(world, width, height);
        if (p.z > 1.0f) return std::nullopt;
        return glm::vec2(p);
    }
};

glm::vec3 handleColor(Handle handle, Handle highlighted) {
    if (handle == highlighted) return look::srgb(kHighlightColor);
    if (handle == Handle::RingView) return look::srgb(kViewRingColor);
    static constexpr Handle kByAxis[][3] = {{Handle::AxisX, Handle::PlaneYZ, Handle::RingX},
                                            {Handle::AxisY, Handle::PlaneXZ, Handle::RingY},
                                            {Handle::AxisZ, Handle::PlaneXY, Handle::RingZ}};
    for (int axis = 0; axis < 3; ++axis) {
        if (std::find(std::begin(kByAxis[axis]), std::end(kByAxis[axis]), handle) != std::end(kByAxis[axis]))
            return look::srgb(kAxisColors[axis]);
    }
    return look::srgb(kViewRingColor);
}

void drawPolyline(Triangles& out, const std::vector<std::optional<glm::vec2>>& points, float width,
                  const glm::vec3& color) {
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i - 1] && points[i]) out.segment(*points[i - 1], *points[i], width, color);
    }
}

void drawArrow(Triangles& out, const Projector& project, const gizmo::Placement& placement, Handle handle,
               const glm::vec3& color) {
    const std::vector<glm::vec3> stroke = gizmo::handleStroke(handle, placement);
    const auto from = project(stroke.front()), tip = project(stroke.back());
    if (!from || !tip) return;
    const glm::vec3 outline = look::srgb(kOutlineColor);
    const float length = glm::length(*tip - *from);
    // An arrow pointing at the viewer is a dot on screen: no direction for a head.
    if (length < 2.0f) return;
    const glm::vec2 d = (*tip - *from) / length, n(-d.y, d.x);
    // The head ends at the stroke's tip, so all of what is drawn can be picked; the shaft runs
    // into it (the head is shorter than an arrow seen very obliquely: then it is the whole arrow).
    const float headLength = std::min(kArrowHeadLength, length);
    const glm::vec2 base = *tip - d * headLength;
    const auto head = [&](float grow, const glm::vec3& c) {
        out.triangle(base - d * grow + n * (kArrowHeadHalfWidth + grow),
                     base - d * grow - n * (kArrowHeadHalfWidth + grow), *tip + d * (1.5f * grow), c);
    };
    out.segment(*from, base, kStrokePixels + 2.0f * kOutlinePixels, outline);
    head(kOutlinePixels, outline);
    out.segment(*from, base, kStrokePixels, color);
    head(0.0f, color);
}

void drawPlane(Triangles& out, const Projector& project, const gizmo::Placement& placement, Handle handle,
               const glm::vec3& color) {
    std::vector<std::optional<glm::vec2>> corners;
    for (const glm::vec3& p : gizmo::handleStroke(handle, placement)) corners.push_back(project(p));
    if (std::any_of(corners.begin(), corners.end(), [](const auto& c) { return !c; })) return;
    out.quad(*corners[0], *corners[1], *corners[2], *corners[3], color);
    drawPolyline(out, corners, 2.0f * kOutlinePixels, look::srgb(kOutlineColor));
}

// A ring's near half (or the whole view ring) as a bright stroke over an outline; `farHalf` draws
// the other half, thin and dim.
void drawRing(Triangles& out, const Projector& project, const gizmo::Placement& placement, Handle handle,
              const glm::vec3& color, bool farHalf) {
    const std::vector<glm::vec3> stroke = gizmo::handleStroke(handle, placement);
    const glm::vec3 outline = look::srgb(kOutlineColor);
    const glm::vec3 dim = glm::mix(color, look::srgb(look::kStaticColor), kBackDimming);
    for (std::size_t i = 1; i < stroke.size(); ++i) {
        const bool near =
            handle == Handle::RingView || gizmo::facesViewer(0.5f * (stroke[i - 1] + stroke[i]), placement);
        if (near == farHalf) continue;
        const auto a = project(stroke[i - 1]), b = project(stroke[i]);
        if (!a || !b) continue;
        if (farHalf) {
            out.segment(*a, *b, kBackStrokePixels, dim);
        } else {
            out.segment(*a, *b, kStrokePixels + 2.0f * kOutlinePixels, outline);
        }
    }
    if (farHalf) return;
    // The bright stroke after the whole outline, so that segments' outlines never cut it.
    for (std::size_t i = 1; i < stroke.size(); ++i) {
        if (handle != Handle::RingView && !gizmo::facesViewer(0.5f * (stroke[i - 1] + stroke[i]), placement)) continue;
        const auto a = project(stroke[i - 1]), b = project(stroke[i]);
        if (a && b) out.segment(*a, *b, kStrokePixels, color);
    }
}

}  // namespace

std::vector<OverlayVertex> gizmoTriangles(const gizmo::Placement& placement, gizmo::Mode mode, Handle highlighted,
                                          const Camera& camera, float widthPixels, float heightPixels) {
    std::vector<OverlayVertex> vertices;
    Triangles out(vertices);
    const Projector project{camera, widthPixels, heightPixels};
    const auto draw = [&](Handle handle, bool farHalf) {
        const glm::vec3 color = handleColor(handle, highlighted);
        switch (handle) {
        case Handle::AxisX:
        case Handle::AxisY:
        case Handle::AxisZ: drawArrow(out, project, placement, handle, color); break;
        case Handle::PlaneYZ:
        case Handle::PlaneXZ:
        case Handle::PlaneXY: drawPlane(out, project, placement, handle, color); break;
        case Handle::RingX:
        case Handle::RingY:
        case Handle::RingZ:
        case Handle::RingView: drawRing(out, project, placement, handle, color, farHalf); break;
        case Handle::None: break;
        }
    };
    static constexpr std::array<Handle, 6> kMoveOrder = {Handle::PlaneYZ, Handle::PlaneXZ, Handle::PlaneXY,
                                                         Handle::AxisX,   Handle::AxisY,   Handle::AxisZ};
    static constexpr std::array<Handle, 4> kRotateOrder = {Handle::RingView, Handle::RingX, Handle::RingY,
                                                           Handle::RingZ};
    if (mode == gizmo::Mode::Rotate) {
        for (Handle handle : kRotateOrder) draw(handle, true);  // the far halves, under everything
    }
    const std::span<const Handle> order =
        mode == gizmo::Mode::Rotate ? std::span<const Handle>(kRotateOrder) : std::span<const Handle>(kMoveOrder);
    for (Handle handle : order) {
        if (handle != highlighted) draw(handle, false);
    }
    if (gizmo::belongsTo(highlighted, mode)) draw(highlighted, false);
    if (const auto center = project(placement.center)) {
        const glm::vec2 o(kCenterDotPixels + kOutlinePixels), i(kCenterDotPixels);
        out.quad(*center - o, *center + glm::vec2(o.x, -o.y), *center + o, *center + glm::vec2(-o.x, o.y),
                 look::srgb(kOutlineColor));
        out.quad(*center - i, *center + glm::vec2(i.x, -i.y), *center + i, *center + glm::vec2(-i.x, i.y),
                 look::srgb(kViewRingColor));
    }
    return vertices;
}

}  // namespace interplay
