#version 330 core
uniform vec3 uColor;
out vec4 fragColor;
void main() { fragColor = vec4(pow(uColor, vec3(1.0 / 2.2)), 1.0); }
