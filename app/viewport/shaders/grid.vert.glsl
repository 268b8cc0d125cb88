#version 330 core
// A square on y = 0 around the camera target; lines are computed per pixel (anti-aliased with
// fwidth, grid.frag) so they stay one pixel wide at any distance and fade before they turn into moire.
uniform mat4 uViewProjection;
uniform vec2 uCenter;
uniform float uExtent;
out vec3 vWorldPos;
void main() {
    vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
    vWorldPos = vec3(uCenter.x + corner.x * uExtent, 0.0, uCenter.y + corner.y * uExtent);
    gl_Position = uViewProjection * vec4(vWorldPos, 1.0);
}
