#version 330 core
in vec3 vColor;
out vec4 fragColor;
void main() { fragColor = vec4(pow(vColor, vec3(1.0 / 2.2)), 1.0); }
