#pragma once
// The transform gizmo's gesture, which the selection tool hands presses on a handle: a drag of an
// arrow, plane handle or ring moves or turns the whole selection (gizmo.h has the maths) through
// the same MoveBodies command as a body drag, merged into one history entry per gesture, with the
// joints riding on the bodies. It works while playing too: a move shifts the live bodies by as much
// as the authored ones (SimulationController's in-place edits). A drag snaps to the grid and angle
// steps of the settings while snapping is on or Ctrl is held (Ctrl held with snapping on turns it
// off, as in Blender); a cancel (Escape, right click) puts everything back and leaves no entry.

#include "app/document/scene_document.h"
#include "app/viewport/gizmo.h"

#include "simcore/io/scene.h"

#include <QList>
#include <QObject>
#include <QPointF>

#include <optional>
#include <vector>

namespace interplay {

class SimulationController;
class Viewport;

// QSettings keys of the snapping steps, and their defaults (read at each press, so a change in
// the Preferences applies to the next drag).
inline constexpr char kGizmoGridStepKey[] = "viewport/gizmoGridStep";    // m
inline constexpr char kGizmoAngleStepKey[] = "viewport/gizmoAngleStep";  // degrees
inline constexpr double kDefaultGizmoGridStep = 0.1;
inline constexpr double kDefaultGizmoAngleStep = 15.0;
// The step stored under `key`, or `fallback` where the stored value is missing, not a number or
// not positive (a zero step would divide by zero when snapping).
double preferredGizmoStep(const char* key, double fallback);

class GizmoTool : public QObject {
    Q_OBJECT

public:
    // Casts rays and reads the camera through `viewport`, which outlives the tool.
    explicit GizmoTool(Viewport& viewport) : m_viewport(viewport) {}

    void setSimulation(SimulationController* simulation) { m_simulation = simulation; }
    void setDocument(SceneDocument* document);

    // The gizmo shown on the selection: a mode, or none; world or local axes.
    void setMode(std::optional<gizmo::Mode> mode);
    std::optional<gizmo::Mode> mode() const { return m_mode; }
    void setSpace(gizmo::Space space);
    gizmo::Space space() const { return m_space; }
    // Snapping without Ctrl (the toolbar's Snap); Ctrl then drags freely.
    void setSnapping(bool snapping) { m_snapping = snapping; }
    bool snapping() const { return m_snapping; }
    // Where the gizmo is in the current view: at the selected bodies' live centre, on the world's
    // axes or on those of the active (last selected) body; none when no gizmo is shown or nothing
    // is selected.
    std::optional<gizmo::Placement> placement() const;
    // The handle under the cursor, or the one being dragged.
    gizmo::Handle highlighted() const { return m_highlighted; }

    // A press on a handle starts a drag and returns true; any other press is the caller's.
    bool press(const QPointF& position);
    void drag(const QPointF& position, Qt::KeyboardModifiers modifiers);
    void release();
    void cancel();
    bool isDragging() const { return m_drag.has_value(); }
    // With no drag: lights up the handle under the cursor.
    void hover(const QPointF& position);
    // The cursor left the view: no handle is lit.
    void clearHover();

signals:
    void repaintNeeded();

private:
    void push(std::vector<simcore::SceneBody> after);
    // Ends a drag whose bodies changed places or went (a delete mid-drag, a new scene): what it
    // pushed stays one finished entry, and the rest of the gesture moves nothing.
    void abandon();

    Viewport& m_viewport;
    SimulationController* m_simulation = nullptr;
    SceneDocument* m_document = nullptr;

    std::optional<gizmo::Mode> m_mode = gizmo::Mode::Move;
    gizmo::Space m_space = gizmo::Space::World;
    gizmo::Handle m_highlighted = gizmo::Handle::None;
    bool m_snapping = false;

    std::optional<gizmo::Drag> m_drag;
    gizmo::Snap m_snapSteps;                        // the settings' steps, read at the press
    BodyField m_field = BodyField::Position;        // what the drag's commands change
    QList<int> m_indices;                           // the bodies dragged
    std::vector<simcore::SceneBody> m_startBodies;  // as they were at the press
    bool m_pushed = false;                          // the drag has pushed its first command
};

}  // namespace interplay
