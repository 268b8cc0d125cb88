#pragma once
// Real input for the editor suites: where a world point or a gizmo handle is on the viewport's
// screen, and the mouse gestures a hand makes there (drags with held modifiers, wheel turns, a
// slider's handle dragged along its groove), all as QTest and QMouseEvent events.

#include "app/viewport/gizmo.h"
#include "app/viewport/viewport.h"

#include <QApplication>
#include <QMouseEvent>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTest>
#include <QWheelEvent>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace test_support {

// A world point's widget pixel, as the viewport's camera projects it.
inline QPoint pixelOf(const interplay::Viewport& viewport, const glm::vec3& world) {
    const glm::vec3 p = viewport.camera().project(world, float(viewport.width()), float(viewport.height()));
    return {int(std::lround(p.x)), int(std::lround(p.y))};
}

// A point of a handle's stroke that the cursor can take: 70 % along an arrow, the middle of a
// plane square, the point of a ring nearest the eye.
inline glm::vec3 grabPoint(const interplay::Viewport& viewport, interplay::gizmo::Handle handle,
                           const interplay::gizmo::Placement& placement) {
    using interplay::gizmo::Handle;
    const std::vector<glm::vec3> stroke = interplay::gizmo::handleStroke(handle, placement);
    if (handle == Handle::AxisX || handle == Handle::AxisY || handle == Handle::AxisZ)
        return glm::mix(stroke[0], stroke[1], 0.7f);
    if (handle == Handle::PlaneYZ || handle == Handle::PlaneXZ || handle == Handle::PlaneXY)
        return 0.5f * (stroke[0] + stroke[2]);
    const glm::vec3 eye = viewport.camera().eye();
    glm::vec3 nearest = stroke.front();
    for (const glm::vec3& point : stroke) {
        if (glm::length(point - eye) < glm::length(nearest - eye)) nearest = point;
    }
    return nearest;
}

// A left drag through `path` (press on the first pixel, release on the last), the modifiers held
// throughout: QTest::mouseMove sends none, and the gizmo reads Ctrl from the moves.
inline void dragThrough(QWidget* widget, const std::vector<QPoint>& path, Qt::KeyboardModifiers modifiers = {}) {
    QTest::mousePress(widget, Qt::LeftButton, modifiers, path.front());
    for (std::size_t i = 1; i < path.size(); ++i) {
        QMouseEvent move(QEvent::MouseMove, path[i], widget->mapToGlobal(path[i]), Qt::NoButton, Qt::LeftButton,
                         modifiers);
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers, path.back());
}

// A straight left drag in ten moves, as a hand makes it.
inline void drag(QWidget* widget, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}) {
    std::vector<QPoint> path;
    for (int i = 0; i <= 10; ++i) path.push_back(from + (to - from) * i / 10);
    dragThrough(widget, path, modifiers);
}

// Turns the mouse wheel over `pixel` by `steps` notches (positive: away from the user, zoom in).
inline void turnWheel(QWidget* widget, QPoint pixel, int steps) {
    for (int i = 0; i < std::abs(steps); ++i) {
        QWheelEvent wheel(pixel, widget->mapToGlobal(pixel), QPoint(), QPoint(0, steps > 0 ? 120 : -120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(widget, &wheel);
    }
}

// Presses a horizontal slider's handle and drags it to where `value` sits on the groove.
inline void dragSliderTo(QSlider* slider, int value) {
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = Qt::Horizontal;
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    const QRect handle = slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider);
    const QRect groove = slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, slider);
    const int span = groove.width() - handle.width();
    const int x = groove.x() + handle.width() / 2 +
                  QStyle::sliderPositionFromValue(slider->minimum(), slider->maximum(), value, span);
    const QPoint from = handle.center();
    const QPoint to(x, from.y());
    QTest::mousePress(slider, Qt::LeftButton, {}, from);
    for (int i = 1; i <= 8; ++i) QTest::mouseMove(slider, from + (to - from) * i / 8);
    QTest::mouseRelease(slider, Qt::LeftButton, {}, to);
}

}  // namespace test_support
