#include "app/viewport/gizmo.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace interplay::gizmo {
namespace {

constexpr float kPi = 3.14159265358979f;
// Below this |cos| between a ray and a plane (a ray grazing it) a hit point runs off to the
// horizon for a pixel of cursor travel: the drag holds still instead.
constexpr float kGrazingCosine = 0.02f;

int axisIndex(Handle handle) {
    switch (handle) {
    case Handle::AxisX:
    case Handle::PlaneYZ:
    case Handle::RingX: return 0;
    case Handle::AxisY:
    case Handle::PlaneXZ:
    case Handle::RingY: return 1;
    case Handle::AxisZ:
    case Handle::PlaneXY:
    case Handle::RingZ: return 2;
    case Handle::None:
    case Handle::RingView: break;
    }
    return -1;
}

bool isAxis(Handle h) { return h == Handle::AxisX || h == Handle::AxisY || h == Handle::AxisZ; }
bool isPlane(Handle h) { return h == Handle::PlaneYZ || h == Handle::PlaneXZ || h == Handle::PlaneXY; }
bool isRing(Handle h) {
    return h == Handle::RingX || h == Handle::RingY || h == Handle::RingZ || h == Handle::RingView;
}

// The two gizmo axes spanning a plane handle's plane or a ring's circle (for the view ring, two
// directions across the view).
std::pair<glm::vec3, glm::vec3> spanningAxes(Handle handle, const Placement& placement) {
    if (handle == Handle::RingView) {
        const glm::vec3 n = placement.viewDirection;
        const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
        const glm::vec3 u = glm::normalize(glm::cross(helper, n));
        return {u, glm::cross(n, u)};
    }
    const int i = axisIndex(handle);
    return {placement.axes[(i + 1) % 3], placement.axes[(i + 2) % 3]};
}

struct RayDistance {
    float distance;  // m, between the ray and the nearest point of the segment
    float along;     // m, how far along the ray that is
};

// Closest approach of a ray (from its origin on) and the segment a-b.
RayDistance raySegment(const Ray& ray, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 u = b - a;
    const float uu = glm::dot(u, u);
    float t = 0.0f;
    const float du = glm::dot(ray.direction, u);
    const float denominator = uu - du * du;  // |d|² |u|² - (d·u)², d unit
    if (denominator > 1e-12f * std::max(uu, 1e-12f)) {
        const glm::vec3 w = ray.origin - a;
        t = (glm::dot(u, w) - du * glm::dot(ray.direction, w)) / denominator;
    }
    t = std::clamp(t, 0.0f, 1.0f);
    const float s = std::max(0.0f, glm::dot(a + t * u - ray.origin, ray.direction));
    if (uu > 0.0f) t = std::clamp(glm::dot(ray.origin + s * ray.direction - a, u) / uu, 0.0f, 1.0f);
    const glm::vec3 nearest = a + t * u;
    const float along = std::max(0.0f, glm::dot(nearest - ray.origin, ray.direction));
    return {glm::length(ray.origin + along * ray.direction - nearest), along};
}

std::optional<glm::vec3> rayPlane(const Ray& ray, const glm::vec3& point, const glm::vec3& normal) {
    const float cosine = glm::dot(ray.direction, normal);
    if (std::abs(cosine) < kGrazingCosine) return std::nullopt;
    const float t = glm::dot(point - ray.origin, normal) / cosine;
    if (t <= 0.0f) return std::nullopt;
    return ray.origin + t * ray.direction;
}

}  // namespace

Placement place(const Camera& camera, float heightPixels, const glm::vec3& center, const glm::mat3& axes) {
    Placement placement;
    placement.center = center;
    placement.axes = axes;
    placement.viewDirection = camera.forward();
    placement.orthographic = camera.isOrthographic();
    placement.eye = camera.eye();
    // The view's height in metres at the centre's depth (the orthographic view is as tall as the
    // perspective one at the target's), over its height in pixels.
    const float depth = camera.isOrthographic() ? camera.distance()
                                                : std::max(glm::dot(center - camera.eye(), camera.forward()), 1e-3f);
    placement.metresPerPixel =
        2.0f * depth * std::tan(0.5f * glm::radians(camera.fovYDegrees())) / std::max(heightPixels, 1.0f);
    return placement;
}

bool belongsTo(Handle handle, Mode mode) {
    if (handle == Handle::None) return false;
    return mode == Mode::Rotate ? isRing(handle) : !isRing(handle);
}

glm::vec3 handleAxis(Handle handle, const Placement& placement) {
    if (handle == Handle::RingView) return -placement.viewDirection;  // towards the viewer
    const int i = axisIndex(handle);
    return i < 0 ? glm::vec3(0.0f) : placement.axes[i];
}

std::vector<glm::vec3> handleStroke(Handle handle, const Placement& placement) {
    const float scale = placement.metresPerPixel;
    const glm::vec3& c = placement.center;
    if (isAxis(handle)) {
        const glm::vec3 axis = handleAxis(handle, placement);
        return {c + axis * (kArrowStartPixels * scale), c + axis * (kArrowPixels * scale)};
    }
    const auto [u, v] = spanningAxes(handle, placement);
    if (isPlane(handle)) {
        const float a = kPlaneNearPixels * scale, b = kPlaneFarPixels * scale;
        return {c + a * u + a * v, c + b * u + a * v, c + b * u + b * v, c + a * u + b * v, c + a * u + a * v};
    }
    if (!isRing(handle)) return {};
    const float radius = (handle == Handle::RingView ? kViewRingPixels : kRingPixels) * scale;
    std::vector<glm::vec3> circle;
    circle.reserve(kRingSegments + 1);
    for (int i = 0; i <= kRingSegments; ++i) {
        const float angle = 2.0f * kPi * static_cast<float>(i % kRingSegments) / static_cast<float>(kRingSegments);
        circle.push_back(c + radius * (std::cos(angle) * u + std::sin(angle) * v));
    }
    return circle;
}

bool facesViewer(const glm::vec3& point, const Placement& placement) {
    const glm::vec3 towardsViewer =
        placement.orthographic ? -placement.viewDirection : glm::normalize(placement.eye - placement.center);
    // A little past the silhouette, so the ring's ends where it turns away stay pickable.
    return glm::dot(point - placement.center, towardsViewer) >= -0.05f * glm::length(point - placement.center);
}

Handle pick(Mode mode, const Placement& placement, const Ray& ray) {
    static constexpr Handle kMoveHandles[] = {Handle::AxisX,   Handle::AxisY,   Handle::AxisZ,
                                              Handle::PlaneYZ, Handle::PlaneXZ, Handle::PlaneXY};
    static constexpr Handle kRotateHandles[] = {Handle::RingX, Handle::RingY, Handle::RingZ, Handle::RingView};
    const float reach = kPickPixels * placement.metresPerPixel;
    Handle best = Handle::None;
    float bestDistance = std::numeric_limits<float>::infinity();
    const auto consider = [&](Handle handle, float distance) {
        if (distance <= reach && distance < bestDistance) {
            best = handle;
            bestDistance = distance;
        }
    };
    if (mode == Mode::Move) {
        for (Handle handle : kMoveHandles) {
            const std::vector<glm::vec3> stroke = handleStroke(handle, placement);
            if (isPlane(handle)) {
                // Inside the square counts as on it.
                if (const auto hit = rayPlane(ray, placement.center, handleAxis(handle, placement))) {
                    const auto [u, v] = spanningAxes(handle, placement);
                    const glm::vec3 offset = (*hit - placement.center) / placement.metresPerPixel;
                    const float a = glm::dot(offset, u), b = glm::dot(offset, v);
                    if (a >= kPlaneNearPixels && a <= kPlaneFarPixels && b >= kPlaneNearPixels &&
                        b <= kPlaneFarPixels) {
                        consider(handle, 0.0f);
                        continue;
                    }
                }
            }
            for (std::size_t i = 1; i < stroke.size(); ++i)
                consider(handle, raySegment(ray, stroke[i - 1], stroke[i]).distance);
        }
        return best;
    }
    for (Handle handle : kRotateHandles) {
        const std::vector<glm::vec3> stroke = handleStroke(handle, placement);
        for (std::size_t i = 1; i < stroke.size(); ++i) {
            if (handle != Handle::RingView && !facesViewer(0.5f * (stroke[i - 1] + stroke[i]), placement)) continue;
            consider(handle, raySegment(ray, stroke[i - 1], stroke[i]).distance);
        }
    }
    return best;
}

float snapTo(float value, float step) {
    if (!(step > 0.0f)) return value;
    return std::round(value / step) * step;
}

std::optional<Drag> Drag::begin(Handle handle, const Placement& placement, const Ray& ray) {
    if (handle == Handle::None) return std::nullopt;
    Drag drag(handle, placement);
    const auto start = drag.constrainedPoint(ray);
    if (!start) return std::nullopt;
    drag.m_startPoint = drag.m_lastPoint = *start;
    return drag;
}

std::optional<glm::vec3> Drag::constrainedPoint(const Ray& ray) const {
    const glm::vec3 axis = handleAxis(m_handle, m_placement);
    if (!isAxis(m_handle)) return rayPlane(ray, m_placement.center, axis);
    // The point of the axis line nearest the ray: with w from the eye to the centre and b the
    // cosine between ray and axis, t = (b (w·d) - w·a) / (1 - b²) along the axis.
    const glm::vec3 w = m_placement.center - ray.origin;
    const float b = glm::dot(axis, ray.direction);
    const float denominator = 1.0f - b * b;
    if (denominator < kGrazingCosine * kGrazingCosine) return std::nullopt;  // looking along the axis
    const float t = (b * glm::dot(w, ray.direction) - glm::dot(w, axis)) / denominator;
    if (glm::dot(w, ray.direction) + t * b <= 0.0f) return std::nullopt;  // behind the eye
    return m_placement.center + t * axis;
}

Motion Drag::update(const Ray& ray, const Snap& snap) {
    Motion motion;
    motion.pivot = m_placement.center;
    const glm::vec3 axis = handleAxis(m_handle, m_placement);
    const auto point = constrainedPoint(ray);
    if (isRing(m_handle)) {
        if (point) {
            const glm::vec3 from = m_lastPoint - m_placement.center, to = *point - m_placement.center;
            // Over the centre the angle is undefined: wait for the cursor to leave it.
            if (glm::length(to) > 1e-3f * m_placement.metresPerPixel * kRingPixels) {
                // Summed step by step, so a drag round and round turns by more than 180°.
                m_swept += std::atan2(glm::dot(glm::cross(from, to), axis), glm::dot(from, to));
                m_lastPoint = *point;
            }
        }
        motion.angle = snapTo(m_swept, snap.angleStep);
        motion.rotation = glm::angleAxis(motion.angle, axis);
        return motion;
    }
    if (point) m_freeTranslation = *point - m_startPoint;
    if (isAxis(m_handle)) {
        motion.translation = snapTo(glm::dot(m_freeTranslation, axis), snap.gridStep) * axis;
    } else {
        // Rebuilt from its two in-plane parts, so it has nothing along the normal.
        const auto [u, v] = spanningAxes(m_handle, m_placement);
        motion.translation = snapTo(glm::dot(m_freeTranslation, u), snap.gridStep) * u +
                             snapTo(glm::dot(m_freeTranslation, v), snap.gridStep) * v;
    }
    return motion;
}

}  // namespace interplay::gizmo
