#include "app/viewport/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace interplay {
namespace {
constexpr float kMinDistance = 0.05f;   // m
constexpr float kMaxDistance = 5000.0f; // m
constexpr float kMaxPitch = 89.0f;      // degrees
constexpr float kOrbitDegreesPerPixel = 0.3f;
}  // namespace

void Camera::setYawDegrees(float yaw) {
    m_yaw = std::fmod(yaw, 360.0f);
}

void Camera::setPitchDegrees(float pitch) {
    m_pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
}

void Camera::setDistance(float distance) {
    m_distance = std::clamp(distance, kMinDistance, kMaxDistance);
}

glm::vec3 Camera::forward() const {
    const float yaw = glm::radians(m_yaw), pitch = glm::radians(m_pitch);
    // At yaw 0 the eye sits on +Z looking towards -Z; positive pitch raises the eye.
    return glm::vec3(-std::sin(yaw) * std::cos(pitch), -std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

glm::vec3 Camera::eye() const {
    return m_target - forward() * m_distance;
}

glm::vec3 Camera::right() const {
    return glm::normalize(glm::cross(forward(), glm::vec3(0.0f, 1.0f, 0.0f)));
}

glm::vec3 Camera::up() const {
    return glm::cross(right(), forward());
}

glm::mat4 Camera::viewMatrix() const {
    return glm::lookAt(eye(), m_target, glm::vec3(0.0f, 1.0f, 0.0f));
}

float Camera::nearPlane() const {
    return std::max(0.01f, 0.02f * m_distance);
}

float Camera::farPlane() const {
    return std::max(200.0f, 50.0f * m_distance);
}

float Camera::projectionNearPlane() const {
    return m_orthographic ? -farPlane() : nearPlane();
}

glm::mat4 Camera::projectionMatrix(float aspect) const {
    aspect = std::max(aspect, 1e-3f);
    if (!m_orthographic) return glm::perspective(glm::radians(m_fovY), aspect, nearPlane(), farPlane());
    const float halfHeight = m_distance * std::tan(0.5f * glm::radians(m_fovY));
    const float halfWidth = halfHeight * aspect;
    return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, projectionNearPlane(), farPlane());
}

void Camera::orbit(float dxPixels, float dyPixels) {
    // Dragging right swings the eye to the left around the target, as if turning the scene with the hand.
    setYawDegrees(m_yaw - dxPixels * kOrbitDegreesPerPixel);
    setPitchDegrees(m_pitch + dyPixels * kOrbitDegreesPerPixel);
}

void Camera::pan(float dxPixels, float dyPixels, float viewportHeight) {
    // World size of one pixel at the target's depth.
    const float metresPerPixel =
        2.0f * m_distance * std::tan(0.5f * glm::radians(m_fovY)) / std::max(viewportHeight, 1.0f);
    m_target += (-dxPixels * right() + dyPixels * up()) * metresPerPixel;
}

void Camera::zoom(float wheelSteps) {
    setDistance(m_distance * std::pow(0.85f, wheelSteps));
}

void Camera::lookAround(float dxPixels, float dyPixels) {
    // Same angles as orbit (dragging right turns the view right), but the eye stays put.
    const glm::vec3 eyeBefore = eye();
    orbit(dxPixels, dyPixels);
    m_target = eyeBefore + forward() * m_distance;
}

void Camera::fly(const glm::vec3& offset) {
    m_target += offset.x * right() + offset.y * up() + offset.z * forward();
}

void Camera::frame(const glm::vec3& center, float radius, float aspect) {
    m_target = center;
    // The sphere fits when it fits the narrower of the two fields of view.
    const float halfFovY = 0.5f * glm::radians(m_fovY);
    const float halfFovX = std::atan(std::tan(halfFovY) * std::max(aspect, 1e-3f));
    const float halfFov = std::min(halfFovY, halfFovX);
    setDistance(std::max(radius, 0.1f) / std::sin(halfFov));
}

void Camera::frameBounds(const glm::vec3& min, const glm::vec3& max, float aspect, float fill) {
    frame(0.5f * (min + max), 0.5f * glm::length(max - min) / std::clamp(fill, 0.1f, 1.0f), aspect);
}

void Camera::frameBox(const glm::vec3& min, const glm::vec3& max, float aspect, float margin) {
    m_target = 0.5f * (min + max);
    const float tanY = std::tan(0.5f * glm::radians(m_fovY)) * (1.0f - margin);
    const float tanX = tanY * std::max(aspect, 1e-3f);
    const glm::vec3 r = right(), u = up(), f = forward();
    // A corner at offset c from the target, seen from the eye at target - f * d, lies at depth
    // d + c.f with lateral offsets c.r and c.u; it is inside the view when both offsets are within
    // tan(half field of view) * depth. Solve each for d and take the largest.
    float distance = kMinDistance;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y, (corner & 4) ? max.z : min.z);
        const glm::vec3 c = p - m_target;
        const float depthOffset = glm::dot(c, f);
        distance = std::max(distance, std::abs(glm::dot(c, r)) / tanX - depthOffset);
        distance = std::max(distance, std::abs(glm::dot(c, u)) / tanY - depthOffset);
    }
    // Never so close that the near plane cuts into the box.
    distance = std::max(distance, glm::length(max - min) * 0.5f + 0.1f);
    setDistance(distance);
}

glm::vec3 Camera::project(const glm::vec3& world, float widthPixels, float heightPixels) const {
    const glm::vec4 clip = viewProjection(widthPixels / std::max(heightPixels, 1.0f)) * glm::vec4(world, 1.0f);
    if (clip.w <= 0.0f) return glm::vec3(-1.0f, -1.0f, 2.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return glm::vec3((ndc.x * 0.5f + 0.5f) * widthPixels, (0.5f - ndc.y * 0.5f) * heightPixels, ndc.z * 0.5f + 0.5f);
}

}  // namespace interplay
