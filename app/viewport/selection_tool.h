#pragma once
// The viewport's mouse and keys: selecting, moving and turning bodies, grabbing them while the
// simulation plays, and driving the camera. One gesture at a time, from press to release:
//   left click            select the joint whose anchor (or distance rod) is within a few
//                         pixels, else the body under the cursor; a joint of that body hidden
//                         inside it takes a click on the body once the body alone is selected;
//                         Ctrl/Shift-click adds or removes it; a click on nothing clears
//   left drag on a body   paused: move the selection on a horizontal plane (one undo entry), and
//                         the anchors of joints riding on it; with R held (or Alt, which many
//                         Linux window managers take for moving windows): turn it about the
//                         vertical; playing: pull it with a spring
//   left drag on nothing  box select: the bodies whose centres the rectangle holds on screen
//                         (live centres while running); Shift adds them, Ctrl toggles them
//   left drag from a joint, or Ctrl/Shift-drag from a body: orbit
//   middle drag           orbit;  Shift + middle drag: pan;  wheel: zoom
//   right drag + WASDQE   fly (Shift: faster)
//   left drag on a gizmo  the gizmo's (gizmo_tool.h): presses on its handles go there first

#include "app/viewport/gizmo_tool.h"

#include "simcore/io/scene.h"
#include "simcore/world/world.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPoint>
#include <QRect>
#include <QSet>
#include <QTimer>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

class QFocusEvent;
class QKeyEvent;
class QMouseEvent;
class QWheelEvent;

namespace interplay {

class SceneDocument;
class SimulationController;
class Viewport;

class SelectionTool : public QObject {
    Q_OBJECT

public:
    // Picks and moves the camera through `viewport`, which outlives the tool.
    explicit SelectionTool(Viewport& viewport);

    void setSimulation(SimulationController* simulation) {
        m_simulation = simulation;
        m_gizmo.setSimulation(simulation);
    }
    void setDocument(SceneDocument* document) {
        m_document = document;
        m_gizmo.setDocument(document);
    }
    GizmoTool& gizmo() { return m_gizmo; }
    const GizmoTool& gizmo() const { return m_gizmo; }

    // Each returns whether the tool used the event (the widget passes on the others).
    bool mousePress(QMouseEvent* event);
    bool mouseMove(QMouseEvent* event);
    bool mouseRelease(QMouseEvent* event);
    void wheel(QWheelEvent* event);
    bool keyPress(QKeyEvent* event);
    bool keyRelease(QKeyEvent* event);
    void focusOut();
    // Whether the tool takes this key ahead of the window's shortcuts (fly keys while flying,
    // Escape during a gizmo drag).
    bool wantsKey(const QKeyEvent* event) const;

    // The box-select rectangle while one is being dragged (widget pixels), for the view to draw.
    std::optional<QRect> rubberBand() const;

signals:
    void cameraChanged();
    void repaintNeeded();

private:
    enum class Gesture { None, Orbit, Pan, Fly, MoveBodies, RotateBodies, Grab, BoxSelect, Gizmo };

    void pressOnBody(QMouseEvent* event, const simcore::WorldRayHit& hit, int sceneIndex);
    void dragBodies(const QPointF& position);
    std::optional<glm::vec3> dragPlanePoint(const QPointF& pixel) const;
    void clickSelect(Qt::MouseButton button);
    void boxSelect(const QRect& box);
    void flyTick();

    Viewport& m_viewport;
    SimulationController* m_simulation = nullptr;
    SceneDocument* m_document = nullptr;

    Gesture m_gesture = Gesture::None;
    QPoint m_lastMouse;
    QPoint m_pressMouse;
    bool m_dragMoved = false;           // the mouse travelled since the press (not a click)
    int m_clickedBody = -1;             // scene body under the press, for click-to-select on release
    int m_clickedJoint = -1;            // scene joint under the press (takes the click from bodies)
    int m_jointInPressedBody = -1;      // a joint under the press whose point the pressed body hides
    bool m_pressedBodyWasSelected = false;
    Qt::KeyboardModifiers m_pressModifiers;
    float m_dragPlaneHeight = 0.0f;     // y of the horizontal plane bodies move on (m)
    glm::vec3 m_dragStart{0.0f};        // where the drag plane was first hit (m)
    std::vector<simcore::SceneBody> m_dragStartBodies;  // the selection as it was at the press
    QList<int> m_dragIndices;
    bool m_dragPushed = false;          // the drag has pushed its first command (the rest merge)
    float m_grabDepth = 0.0f;           // grab: distance along the view ray kept while dragging (m)

    bool m_rotateKeyHeld = false;       // R is down: a drag on a body turns the selection
    QSet<int> m_flyKeys;
    QTimer m_flyTimer;
    QElapsedTimer m_flyClock;
    GizmoTool m_gizmo;
};

}  // namespace interplay
