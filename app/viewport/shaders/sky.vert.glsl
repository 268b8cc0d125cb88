#version 330 core
// Full-screen triangle; the fragment shader turns each pixel into a view ray.
out vec2 vNdc;
void main() {
    vNdc = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    gl_Position = vec4(vNdc, 0.0, 1.0);
}
