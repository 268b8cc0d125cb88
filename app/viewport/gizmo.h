#pragma once
// Transform gizmos: the geometry, picking and drag maths of the move gizmo (three axis arrows and
// three plane handles) and the rotate gizmo (three axis rings and a view-axis ring), as pure
// functions of a camera and rays, with no window and no GL, so tests drive them directly. The
// gizmo keeps a constant size on screen: its handles are laid out in pixels and turned into metres
// by the view's scale at the gizmo's centre. The selection tool routes presses on a handle here;
// gizmo_overlay draws the handles.

#include "app/viewport/camera.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <vector>

namespace interplay::gizmo {

enum class Mode { Move, Rotate };
// World: the gizmo's axes are the world's; Local: the active body's.
enum class Space { World, Local };

enum class Handle {
    None,
    // Move along one axis.
    AxisX,
    AxisY,
    AxisZ,
    // Move in the plane of two axes (named by the axes it keeps).
    PlaneYZ,
    PlaneXZ,
    PlaneXY,
    // Turn about one axis, or about the view direction.
    RingX,
    RingY,
    RingZ,
    RingView,
};

// The gizmo's layout, in pixels from its centre (constant on screen whatever the zoom).
inline constexpr float kArrowPixels = 100.0f;      // an axis arrow's tip
inline constexpr float kArrowStartPixels = 22.0f;  // where its shaft begins: the centre stays free for body drags
inline constexpr float kPlaneNearPixels = 28.0f;   // a plane handle's square spans these two offsets
inline constexpr float kPlaneFarPixels = 48.0f;
inline constexpr float kRingPixels = 85.0f;       // axis ring radius
inline constexpr float kViewRingPixels = 100.0f;  // view ring radius, outside the axis rings
inline constexpr float kPickPixels = 8.0f;        // how near the cursor must pass a handle's stroke
inline constexpr int kRingSegments = 64;

// The gizmo as seen in one view: where it is, its axes and the view's scale there.
struct Placement {
    glm::vec3 center{0.0f};
    glm::mat3 axes{1.0f};                        // columns: the gizmo's x, y and z, unit length, world space
    float metresPerPixel = 0.01f;                // at the centre's depth
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};  // the camera's forward (unit)
    bool orthographic = false;
    glm::vec3 eye{0.0f};  // where the camera is (perspective rays start there)
};

// Places a gizmo at `center` with `axes` for `camera` in a viewport `heightPixels` tall.
Placement place(const Camera& camera, float heightPixels, const glm::vec3& center, const glm::mat3& axes);

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit
};

// Whether the handle belongs to the mode's gizmo.
bool belongsTo(Handle handle, Mode mode);
// The handle's axis (unit, world space): the arrow's direction, the plane's normal, the ring's axis.
glm::vec3 handleAxis(Handle handle, const Placement& placement);
// The polyline the handle is drawn and picked along (world space): an arrow's shaft, a plane
// square's closed outline, a ring's closed circle.
std::vector<glm::vec3> handleStroke(Handle handle, const Placement& placement);
// Whether a point of a ring lies on its half facing the viewer (only that half is picked, and drawn
// bright, as in Blender: the far half would be grabbed through the near one).
bool facesViewer(const glm::vec3& point, const Placement& placement);

// The mode's handle whose stroke passes within kPickPixels of the ray (or, for a plane handle, whose
// square the ray goes through), the nearest if several do; None if none.
Handle pick(Mode mode, const Placement& placement, const Ray& ray);

// Grid and angle snapping. A step of 0 leaves that motion free.
struct Snap {
    float gridStep = 0.0f;   // m: a move's offset along each gizmo axis is a whole number of these
    float angleStep = 0.0f;  // rad: a turn is a whole number of these
};

// A rigid motion: turn by `rotation` about `pivot`, then move by `translation`.
struct Motion {
    glm::vec3 pivot{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    float angle = 0.0f;  // rad, the turn about the handle's axis (rotate drags)
    glm::vec3 translation{0.0f};
    glm::vec3 apply(const glm::vec3& point) const { return pivot + rotation * (point - pivot) + translation; }
};

// One drag of a handle, from the press: it keeps the placement it started with, so the constraint
// stays put while the bodies move under it.
class Drag {
public:
    // Starts dragging `handle` with the cursor's ray; none if the ray cannot hold the handle
    // (parallel to its axis or plane).
    static std::optional<Drag> begin(Handle handle, const Placement& placement, const Ray& ray);

    // The motion from the press to the cursor's ray now, snapped by `snap`. A ray that cannot
    // hold the handle (it grazes the plane, or misses it) keeps the last motion.
    Motion update(const Ray& ray, const Snap& snap);

    Handle handle() const { return m_handle; }
    const Placement& placement() const { return m_placement; }

private:
    Drag(Handle handle, const Placement& placement) : m_handle(handle), m_placement(placement) {}
    std::optional<glm::vec3> constrainedPoint(const Ray& ray) const;

    Handle m_handle;
    Placement m_placement;
    glm::vec3 m_startPoint{0.0f};       // the constrained point under the press
    glm::vec3 m_lastPoint{0.0f};        // rings: the last point, from which the sweep goes on
    float m_swept = 0.0f;               // rings: the angle swept so far (rad), beyond ±180° too
    glm::vec3 m_freeTranslation{0.0f};  // the last unsnapped move
};

// `value` to the nearest whole number of `step` (unchanged for a step of 0 or less).
float snapTo(float value, float step);

}  // namespace interplay::gizmo
