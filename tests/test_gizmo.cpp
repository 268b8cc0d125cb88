// The transform gizmos' maths with no window: picking handles with rays through a camera's pixels,
// axis drags that move only along their axis by the distance the cursor's ray is carried along it,
// plane drags that stay in their plane, ring drags that turn about their axis by the angle the
// cursor sweeps round the centre, and snapping to 0.1 m and 15°.

#include "app/viewport/camera.h"
#include "app/viewport/gizmo.h"

#include <QTest>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace interplay;
using gizmo::Handle;

Q_DECLARE_METATYPE(gizmo::Handle)

namespace {

constexpr float kWidth = 960.0f, kHeight = 640.0f;
constexpr float kPi = 3.14159265358979f;

// The ray through a pixel, as the viewport casts it (x right, y down).
gizmo::Ray rayThrough(const Camera& camera, glm::vec2 pixel) {
    const glm::mat4 inverse = glm::inverse(camera.viewProjection(kWidth / kHeight));
    const float x = 2.0f * pixel.x / kWidth - 1.0f, y = 1.0f - 2.0f * pixel.y / kHeight;
    const glm::vec4 nearPoint = inverse * glm::vec4(x, y, -1.0f, 1.0f),
                    farPoint = inverse * glm::vec4(x, y, 1.0f, 1.0f);
    const glm::vec3 from = glm::vec3(nearPoint) / nearPoint.w, to = glm::vec3(farPoint) / farPoint.w;
    return {camera.isOrthographic() ? from : camera.eye(), glm::normalize(to - from)};
}

glm::vec2 pixelOf(const Camera& camera, const glm::vec3& world) {
    return glm::vec2(camera.project(world, kWidth, kHeight));
}

Camera defaultCamera(bool orthographic = false) {
    Camera camera;  // yaw 35°, pitch 22°: every axis, plane and ring seen at an angle
    camera.setTarget(glm::vec3(1.0f, 0.5f, -2.0f));
    camera.setDistance(10.0f);
    camera.setOrthographic(orthographic);
    return camera;
}

gizmo::Placement placeAt(const Camera& camera, const glm::vec3& center, const glm::mat3& axes = glm::mat3(1.0f)) {
    return gizmo::place(camera, kHeight, center, axes);
}

// A point on a handle's stroke, `fraction` of the way along its polyline's points.
glm::vec3 strokePoint(Handle handle, const gizmo::Placement& placement, float fraction) {
    const std::vector<glm::vec3> stroke = gizmo::handleStroke(handle, placement);
    const float at = fraction * static_cast<float>(stroke.size() - 1);
    const auto i = static_cast<std::size_t>(at);
    if (i + 1 >= stroke.size()) return stroke.back();
    return glm::mix(stroke[i], stroke[i + 1], at - static_cast<float>(i));
}

// The fraction of a ring's stroke nearest the viewer (its front), so that it is pickable.
float frontOfRing(Handle ring, const gizmo::Placement& placement) {
    const std::vector<glm::vec3> stroke = gizmo::handleStroke(ring, placement);
    std::size_t best = 0;
    for (std::size_t i = 0; i < stroke.size(); ++i) {
        if (glm::length(stroke[i] - placement.eye) < glm::length(stroke[best] - placement.eye)) best = i;
    }
    return static_cast<float>(best) / static_cast<float>(stroke.size() - 1);
}

}  // namespace

class TestGizmo : public QObject {
    Q_OBJECT

private slots:
    void placementKeepsAConstantScreenSize();
    void picksTheHandleUnderThePixel_data();
    void picksTheHandleUnderThePixel();
    void picksNothingAwayFromTheHandles();
    void ringsArePickedOnTheirNearHalfOnly();
    void axisDragMovesOnlyAlongTheAxis_data();
    void axisDragMovesOnlyAlongTheAxis();
    void planeDragStaysInThePlane_data();
    void planeDragStaysInThePlane();
    void ringDragTurnsByTheAngleSwept_data();
    void ringDragTurnsByTheAngleSwept();
    void ringDragSumsTurnsBeyondHalfARevolution();
    void snapsToTheGridAndAngleSteps();
    void raysAlongAnAxisOrGrazingAPlaneHoldTheDrag();
    void motionAppliesAboutThePivot();
};

void TestGizmo::placementKeepsAConstantScreenSize() {
    // An arrow's tip is kArrowPixels from the centre on screen, however far the camera is, as long
    // as the arrow lies across the view (here the camera's right axis).
    for (const float distance : {3.0f, 10.0f, 80.0f}) {
        for (const bool orthographic : {false, true}) {
            Camera camera = defaultCamera(orthographic);
            camera.setDistance(distance);
            const glm::mat3 axes(camera.right(), camera.up(), -camera.forward());
            const gizmo::Placement placement = placeAt(camera, camera.target(), axes);
            const glm::vec2 center = pixelOf(camera, placement.center);
            const glm::vec2 tip = pixelOf(camera, gizmo::handleStroke(Handle::AxisX, placement).back());
            QVERIFY2(std::abs(glm::length(tip - center) - gizmo::kArrowPixels) < 0.5f,
                     qPrintable(QStringLiteral("%1 px at %2 m").arg(glm::length(tip - center)).arg(distance)));
        }
    }
}

void TestGizmo::picksTheHandleUnderThePixel_data() {
    QTest::addColumn<int>("mode");
    QTest::addColumn<Handle>("handle");
    QTest::addColumn<bool>("orthographic");
    QTest::addColumn<bool>("localAxes");
    const std::pair<const char*, Handle> move[] = {{"x arrow", Handle::AxisX},    {"y arrow", Handle::AxisY},
                                                   {"z arrow", Handle::AxisZ},    {"yz plane", Handle::PlaneYZ},
                                                   {"xz plane", Handle::PlaneXZ}, {"xy plane", Handle::PlaneXY}};
    const std::pair<const char*, Handle> rotate[] = {{"x ring", Handle::RingX},
                                                     {"y ring", Handle::RingY},
                                                     {"z ring", Handle::RingZ},
                                                     {"view ring", Handle::RingView}};
    for (const bool orthographic : {false, true}) {
        for (const bool local : {false, true}) {
            const QString suffix =
                QStringLiteral(" %1 %2").arg(orthographic ? "ortho" : "persp", local ? "local" : "world");
            for (const auto& [name, handle] : move)
                QTest::newRow(qPrintable(name + suffix)) << int(gizmo::Mode::Move) << handle << orthographic << local;
            for (const auto& [name, handle] : rotate)
                QTest::newRow(qPrintable(name + suffix)) << int(gizmo::Mode::Rotate) << handle << orthographic << local;
        }
    }
}

void TestGizmo::picksTheHandleUnderThePixel() {
    QFETCH(int, mode);
    QFETCH(Handle, handle);
    QFETCH(bool, orthographic);
    QFETCH(bool, localAxes);
    const Camera camera = defaultCamera(orthographic);
    const glm::quat turn = glm::angleAxis(0.4f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    const gizmo::Placement placement =
        placeAt(camera, glm::vec3(1.5f, 0.8f, -1.0f), localAxes ? glm::mat3_cast(turn) : glm::mat3(1.0f));
    glm::vec3 target;
    if (handle == Handle::PlaneYZ || handle == Handle::PlaneXZ || handle == Handle::PlaneXY) {
        // The middle of the square: inside it, far from its outline.
        const std::vector<glm::vec3> square = gizmo::handleStroke(handle, placement);
        target = 0.5f * (square[0] + square[2]);
    } else if (mode == int(gizmo::Mode::Rotate)) {
        target = strokePoint(handle, placement, frontOfRing(handle, placement));
    } else {
        target = strokePoint(handle, placement, 0.7f);
    }
    // 3 px off the stroke still picks it (the reach is kPickPixels).
    const glm::vec2 pixel = pixelOf(camera, target) + glm::vec2(2.0f, -2.0f);
    QCOMPARE(gizmo::pick(gizmo::Mode(mode), placement, rayThrough(camera, pixel)), handle);
    // The other mode's gizmo has no such handle.
    QVERIFY(!gizmo::belongsTo(handle, mode == int(gizmo::Mode::Move) ? gizmo::Mode::Rotate : gizmo::Mode::Move));
}

void TestGizmo::picksNothingAwayFromTheHandles() {
    const Camera camera = defaultCamera();
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.0f, 0.5f, 0.0f));
    const glm::vec2 center = pixelOf(camera, placement.center);
    // The centre is left to body drags; far outside, nothing either.
    for (const glm::vec2 offset :
         {glm::vec2(0.0f), glm::vec2(3.0f, 4.0f), glm::vec2(300.0f, 200.0f), glm::vec2(-250.0f, 0.0f)}) {
        QCOMPARE(gizmo::pick(gizmo::Mode::Move, placement, rayThrough(camera, center + offset)), Handle::None);
        QCOMPARE(gizmo::pick(gizmo::Mode::Rotate, placement, rayThrough(camera, center + offset)), Handle::None);
    }
    // Just beyond the reach of the x arrow's tip, along the arrow.
    const glm::vec2 tip = pixelOf(camera, gizmo::handleStroke(Handle::AxisX, placement).back());
    const glm::vec2 along = glm::normalize(tip - center);
    QCOMPARE(gizmo::pick(gizmo::Mode::Move, placement, rayThrough(camera, tip + along * (gizmo::kPickPixels + 4.0f))),
             Handle::None);
}

void TestGizmo::ringsArePickedOnTheirNearHalfOnly() {
    const Camera camera = defaultCamera();
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.0f, 0.5f, 0.0f));
    const float front = frontOfRing(Handle::RingY, placement);
    const float back = std::fmod(front + 0.5f, 1.0f);
    const glm::vec3 backPoint = strokePoint(Handle::RingY, placement, back);
    QVERIFY(!gizmo::facesViewer(backPoint, placement));
    QVERIFY(gizmo::pick(gizmo::Mode::Rotate, placement, rayThrough(camera, pixelOf(camera, backPoint))) !=
            Handle::RingY);
}

void TestGizmo::axisDragMovesOnlyAlongTheAxis_data() {
    QTest::addColumn<Handle>("handle");
    QTest::addColumn<bool>("orthographic");
    for (const bool orthographic : {false, true}) {
        const char* view = orthographic ? " ortho" : " persp";
        QTest::newRow(qPrintable(QStringLiteral("x") + view)) << Handle::AxisX << orthographic;
        QTest::newRow(qPrintable(QStringLiteral("y") + view)) << Handle::AxisY << orthographic;
        QTest::newRow(qPrintable(QStringLiteral("z") + view)) << Handle::AxisZ << orthographic;
    }
}

void TestGizmo::axisDragMovesOnlyAlongTheAxis() {
    QFETCH(Handle, handle);
    QFETCH(bool, orthographic);
    const Camera camera = defaultCamera(orthographic);
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.3f, 0.7f, -0.4f));
    const glm::vec3 axis = gizmo::handleAxis(handle, placement);
    const glm::vec3 grabbed = strokePoint(handle, placement, 0.6f);
    auto drag = gizmo::Drag::begin(handle, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(drag);
    // Put the cursor where the grabbed point would be 1.25 m further along the axis, then push it
    // 30 px off the axis's line on screen: the motion is 1.25 m along the axis and nothing across.
    const float expected = 1.25f;
    const glm::vec2 onAxis = pixelOf(camera, grabbed + expected * axis);
    const glm::vec2 axisOnScreen = glm::normalize(onAxis - pixelOf(camera, grabbed));
    const glm::vec2 across(-axisOnScreen.y, axisOnScreen.x);
    const gizmo::Motion exact = drag->update(rayThrough(camera, onAxis), {});
    QVERIFY2(std::abs(glm::dot(exact.translation, axis) - expected) < 1e-3f,
             qPrintable(QString::number(glm::dot(exact.translation, axis))));
    const gizmo::Motion off = drag->update(rayThrough(camera, onAxis + 30.0f * across), {});
    const glm::vec3 sideways = off.translation - glm::dot(off.translation, axis) * axis;
    QCOMPARE(glm::length(sideways), 0.0f);  // world axes: the other coordinates are exactly zero
    QVERIFY(glm::length(off.translation) > 0.5f);
    QCOMPARE(off.angle, 0.0f);
}

void TestGizmo::planeDragStaysInThePlane_data() {
    QTest::addColumn<Handle>("handle");
    QTest::addColumn<bool>("localAxes");
    for (const bool local : {false, true}) {
        const char* space = local ? " local" : " world";
        QTest::newRow(qPrintable(QStringLiteral("yz") + space)) << Handle::PlaneYZ << local;
        QTest::newRow(qPrintable(QStringLiteral("xz") + space)) << Handle::PlaneXZ << local;
        QTest::newRow(qPrintable(QStringLiteral("xy") + space)) << Handle::PlaneXY << local;
    }
}

void TestGizmo::planeDragStaysInThePlane() {
    QFETCH(Handle, handle);
    QFETCH(bool, localAxes);
    const Camera camera = defaultCamera();
    const glm::mat3 axes =
        localAxes ? glm::mat3_cast(glm::angleAxis(0.7f, glm::normalize(glm::vec3(0.2f, 1.0f, 0.4f)))) : glm::mat3(1.0f);
    const gizmo::Placement placement = placeAt(camera, glm::vec3(-0.5f, 1.0f, 0.5f), axes);
    const glm::vec3 normal = gizmo::handleAxis(handle, placement);
    const std::vector<glm::vec3> square = gizmo::handleStroke(handle, placement);
    const glm::vec3 grabbed = 0.5f * (square[0] + square[2]);
    auto drag = gizmo::Drag::begin(handle, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(drag);
    // A target point in the plane: the cursor over it carries the grabbed point exactly there.
    const glm::vec3 inPlane = placement.axes[(handle == Handle::PlaneYZ ? 1 : 0)] * 0.8f +
                              placement.axes[(handle == Handle::PlaneXY ? 1 : 2)] * -0.6f;
    const gizmo::Motion motion = drag->update(rayThrough(camera, pixelOf(camera, grabbed + inPlane)), {});
    QVERIFY2(glm::length(motion.translation - inPlane) < 1e-3f,
             qPrintable(QString::number(glm::length(motion.translation - inPlane))));
    QVERIFY(std::abs(glm::dot(motion.translation, normal)) < 1e-6f);
    // Wherever the cursor goes, nothing along the normal.
    for (const glm::vec2 pixel : {glm::vec2(100.0f, 50.0f), glm::vec2(700.0f, 600.0f), glm::vec2(480.0f, 330.0f)}) {
        const gizmo::Motion anywhere = drag->update(rayThrough(camera, pixel), {});
        QVERIFY(std::abs(glm::dot(anywhere.translation, normal)) <
                1e-6f * std::max(1.0f, glm::length(anywhere.translation)));
    }
}

void TestGizmo::ringDragTurnsByTheAngleSwept_data() {
    QTest::addColumn<Handle>("handle");
    QTest::addColumn<float>("degrees");
    for (const float degrees : {30.0f, -50.0f, 120.0f}) {
        for (const auto& [name, handle] : {std::pair{"x", Handle::RingX}, std::pair{"y", Handle::RingY},
                                           std::pair{"z", Handle::RingZ}, std::pair{"view", Handle::RingView}}) {
            QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(name).arg(degrees))) << handle << degrees;
        }
    }
}

void TestGizmo::ringDragTurnsByTheAngleSwept() {
    QFETCH(Handle, handle);
    QFETCH(float, degrees);
    const Camera camera = defaultCamera();
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.2f, 0.6f, 0.1f));
    const glm::vec3 axis = gizmo::handleAxis(handle, placement);
    const glm::vec3 grabbed = strokePoint(handle, placement, frontOfRing(handle, placement));
    auto drag = gizmo::Drag::begin(handle, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(drag);
    // The cursor follows the grabbed point turned about the axis in 10 steps: the motion turns
    // by the angle swept, about the axis, and moves nothing.
    const glm::vec3 arm = grabbed - placement.center;
    gizmo::Motion motion;
    for (int step = 1; step <= 10; ++step) {
        const glm::quat turn = glm::angleAxis(glm::radians(degrees) * static_cast<float>(step) / 10.0f, axis);
        motion = drag->update(rayThrough(camera, pixelOf(camera, placement.center + turn * arm)), {});
    }
    QVERIFY2(std::abs(motion.angle - glm::radians(degrees)) < glm::radians(0.2f),
             qPrintable(QString::number(glm::degrees(motion.angle))));
    const glm::vec3 turnedArm = motion.rotation * arm;
    QVERIFY(glm::length(turnedArm - glm::angleAxis(glm::radians(degrees), axis) * arm) < 2e-3f * glm::length(arm));
    QCOMPARE(motion.translation, glm::vec3(0.0f));
    QCOMPARE(motion.pivot, placement.center);
}

void TestGizmo::ringDragSumsTurnsBeyondHalfARevolution() {
    const Camera camera = defaultCamera();
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.0f));
    const glm::vec3 axis = gizmo::handleAxis(Handle::RingView, placement);
    const glm::vec3 grabbed = strokePoint(Handle::RingView, placement, 0.0f);
    auto drag = gizmo::Drag::begin(Handle::RingView, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(drag);
    gizmo::Motion motion;
    for (int step = 1; step <= 40; ++step) {  // 400°, 10° a step
        const glm::quat turn = glm::angleAxis(glm::radians(10.0f * static_cast<float>(step)), axis);
        motion = drag->update(rayThrough(camera, pixelOf(camera, turn * grabbed)), {});
    }
    QVERIFY2(std::abs(glm::degrees(motion.angle) - 400.0f) < 0.5f,
             qPrintable(QString::number(glm::degrees(motion.angle))));
}

void TestGizmo::snapsToTheGridAndAngleSteps() {
    const Camera camera = defaultCamera();
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.0f, 0.5f, 0.0f));
    const gizmo::Snap snap{0.1f, glm::radians(15.0f)};
    // Along x: 0.37 m of cursor motion snaps to 0.4 m, 0.33 m to 0.3 m.
    const glm::vec3 grabbed = strokePoint(Handle::AxisX, placement, 0.5f);
    auto move = gizmo::Drag::begin(Handle::AxisX, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(move);
    for (const auto& [free, snapped] : {std::pair{0.37f, 0.4f}, std::pair{0.33f, 0.3f}, std::pair{-0.26f, -0.3f}}) {
        const gizmo::Motion m =
            move->update(rayThrough(camera, pixelOf(camera, grabbed + glm::vec3(free, 0.0f, 0.0f))), snap);
        QVERIFY2(std::abs(m.translation.x - snapped) < 1e-5f, qPrintable(QString::number(m.translation.x)));
        QCOMPARE(m.translation.y, 0.0f);
        QCOMPARE(m.translation.z, 0.0f);
        // Unsnapped, the same cursor gives the free value.
        QVERIFY(std::abs(move->update(rayThrough(camera, pixelOf(camera, grabbed + glm::vec3(free, 0.0f, 0.0f))), {})
                             .translation.x -
                         free) < 1e-3f);
    }
    // A plane drag snaps both of its axes.
    const std::vector<glm::vec3> square = gizmo::handleStroke(Handle::PlaneXZ, placement);
    const glm::vec3 inSquare = 0.5f * (square[0] + square[2]);
    auto plane = gizmo::Drag::begin(Handle::PlaneXZ, placement, rayThrough(camera, pixelOf(camera, inSquare)));
    QVERIFY(plane);
    const gizmo::Motion p =
        plane->update(rayThrough(camera, pixelOf(camera, inSquare + glm::vec3(0.44f, 0.0f, -0.18f))), snap);
    QVERIFY(std::abs(p.translation.x - 0.4f) < 1e-5f && std::abs(p.translation.z + 0.2f) < 1e-5f);
    QCOMPARE(p.translation.y, 0.0f);
    // About y: 37° swept snaps to 30°, 38° to 45°.
    const glm::vec3 front = strokePoint(Handle::RingY, placement, frontOfRing(Handle::RingY, placement));
    for (const auto& [free, snapped] : {std::pair{37.0f, 30.0f}, std::pair{38.0f, 45.0f}, std::pair{-8.0f, -15.0f}}) {
        auto ring = gizmo::Drag::begin(Handle::RingY, placement, rayThrough(camera, pixelOf(camera, front)));
        QVERIFY(ring);
        gizmo::Motion m;
        for (int step = 1; step <= 4; ++step) {
            const glm::quat turn =
                glm::angleAxis(glm::radians(free * static_cast<float>(step) / 4.0f), glm::vec3(0.0f, 1.0f, 0.0f));
            m = ring->update(rayThrough(camera, pixelOf(camera, placement.center + turn * (front - placement.center))),
                             snap);
        }
        QVERIFY2(std::abs(glm::degrees(m.angle) - snapped) < 1e-3f, qPrintable(QString::number(glm::degrees(m.angle))));
    }
    QCOMPARE(gizmo::snapTo(0.25f, 0.0f), 0.25f);  // a step of 0 snaps nothing
}

void TestGizmo::raysAlongAnAxisOrGrazingAPlaneHoldTheDrag() {
    // Looking straight down y: the y arrow points at the eye, and a y drag cannot start.
    Camera camera;
    camera.setPitchDegrees(90.0f);  // clamped just short of the pole
    camera.setTarget(glm::vec3(0.0f));
    camera.setOrthographic(true);
    const gizmo::Placement placement = placeAt(camera, glm::vec3(0.0f));
    QVERIFY(!gizmo::Drag::begin(Handle::AxisY, placement, rayThrough(camera, pixelOf(camera, placement.center))));
    // An x drag that then sees a ray that cannot hold it keeps its last motion (finite).
    const glm::vec3 grabbed = strokePoint(Handle::AxisX, placement, 0.5f);
    auto drag = gizmo::Drag::begin(Handle::AxisX, placement, rayThrough(camera, pixelOf(camera, grabbed)));
    QVERIFY(drag);
    const gizmo::Motion before =
        drag->update(rayThrough(camera, pixelOf(camera, grabbed + glm::vec3(0.5f, 0.0f, 0.0f))), {});
    const gizmo::Motion held = drag->update({glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)}, {});
    QCOMPARE(held.translation, before.translation);
    QVERIFY(std::isfinite(held.translation.x));
}

void TestGizmo::motionAppliesAboutThePivot() {
    gizmo::Motion motion;
    motion.pivot = glm::vec3(1.0f, 0.0f, 0.0f);
    motion.rotation = glm::angleAxis(0.5f * kPi, glm::vec3(0.0f, 1.0f, 0.0f));
    motion.translation = glm::vec3(0.0f, 2.0f, 0.0f);
    // (2, 0, 0) is 1 m along x from the pivot; a quarter turn about y takes it to -z.
    const glm::vec3 moved = motion.apply(glm::vec3(2.0f, 0.0f, 0.0f));
    QVERIFY(glm::length(moved - glm::vec3(1.0f, 2.0f, -1.0f)) < 1e-6f);
    QCOMPARE(motion.apply(motion.pivot), motion.pivot + motion.translation);
}

QTEST_GUILESS_MAIN(TestGizmo)
#include "test_gizmo.moc"
