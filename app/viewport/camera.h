#pragma once
// Orbit camera: looks at a target from a distance, turned by yaw (about world Y) and pitch (above
// the horizon). Y is up, as in simcore scenes. Plain value type, no GL, so tests can project with it.

#include <glm/glm.hpp>

namespace interplay {

class Camera {
public:
    glm::vec3 target() const { return m_target; }
    float yawDegrees() const { return m_yaw; }
    float pitchDegrees() const { return m_pitch; }
    float distance() const { return m_distance; }
    float fovYDegrees() const { return m_fovY; }
    // Orthographic: parallel rays, the view as tall as the perspective one is at the target's
    // depth, so toggling keeps the framed scene the same size there.
    bool isOrthographic() const { return m_orthographic; }
    void setOrthographic(bool orthographic) { m_orthographic = orthographic; }

    void setTarget(const glm::vec3& target) { m_target = target; }
    void setYawDegrees(float yaw);
    void setPitchDegrees(float pitch);  // clamped short of the poles, where "up" is undefined
    void setDistance(float distance);   // clamped to a small positive minimum

    // Eye position, and the camera's right/up axes in world space.
    glm::vec3 eye() const;
    glm::vec3 forward() const;
    glm::vec3 right() const;
    glm::vec3 up() const;

    glm::mat4 viewMatrix() const;
    glm::mat4 projectionMatrix(float aspect) const;  // OpenGL clip space, depth in [-1, 1]
    glm::mat4 viewProjection(float aspect) const { return projectionMatrix(aspect) * viewMatrix(); }

    // Clip planes follow the distance, so the depth buffer keeps its precision when zoomed in and
    // the ground grid stays visible when zoomed out.
    float nearPlane() const;
    float farPlane() const;
    // The near plane the projection uses: orthographic views reach behind the eye, so zooming in
    // (which moves the eye towards the target) never cuts away what is in front of the target.
    float projectionNearPlane() const;
    // How far a ray from the near plane (rayThrough's origin) can reach before the far plane (m).
    float rayReach() const { return farPlane() - (m_orthographic ? projectionNearPlane() : 0.0f); }

    // Mouse gestures, in pixels of a viewport `viewportHeight` pixels tall.
    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels, float viewportHeight);  // the point under the cursor follows it
    void zoom(float wheelSteps);  // positive zooms in
    // First-person gestures (fly mode): turn the view about the eye, and move eye and target
    // together by `offset` given in the camera's (right, up, forward) axes (m).
    void lookAround(float dxPixels, float dyPixels);
    void fly(const glm::vec3& offset);

    // Points the camera at a sphere and backs off until it fits the view (keeps yaw and pitch).
    void frame(const glm::vec3& center, float radius, float aspect);
    // Points the camera at a box's centre and backs off until all eight corners are inside the
    // view, leaving `margin` (a fraction of the half-width/height) free at the edges. Tighter
    // than the bounding sphere for long, flat arrangements such as a row of bodies.
    // Frames a box's bounding sphere so that it fills `fill` of the narrower field of view: Frame
    // All's and an opened scene's framing.
    void frameBounds(const glm::vec3& min, const glm::vec3& max, float aspect, float fill = 0.8f);
    void frameBox(const glm::vec3& min, const glm::vec3& max, float aspect, float margin = 0.1f);

    // World point to widget pixels (x right, y down, origin top-left) and depth in [0, 1];
    // z > 1 or w <= 0 means behind the camera / beyond the far plane.
    glm::vec3 project(const glm::vec3& world, float widthPixels, float heightPixels) const;

private:
    glm::vec3 m_target{0.0f, 0.5f, 0.0f};
    float m_yaw = 35.0f;    // degrees, 0 looks along -Z
    float m_pitch = 22.0f;  // degrees above the horizon the eye sits
    float m_distance = 12.0f;
    float m_fovY = 45.0f;   // degrees
    bool m_orthographic = false;
};

}  // namespace interplay
