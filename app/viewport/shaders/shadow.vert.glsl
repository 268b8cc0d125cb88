#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 2) in mat4 aModel;  // per instance, as in body.vert
uniform mat4 uLightViewProjection;
void main() { gl_Position = uLightViewProjection * aModel * vec4(aPosition, 1.0); }
