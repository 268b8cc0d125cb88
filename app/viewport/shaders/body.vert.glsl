#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
// Per instance: one body of the mesh (see Renderer::drawInstances).
layout(location = 2) in mat4 aModel;  // locations 2 to 5
layout(location = 6) in vec3 aColor;  // linear RGB
uniform mat4 uViewProjection;
uniform mat4 uLightViewProjection;
out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vLightClip;
flat out vec3 vColor;
void main() {
    vec4 world = aModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(aModel) * aNormal;  // rigid transform: no inverse-transpose needed
    vLightClip = uLightViewProjection * world;
    vColor = aColor;
    gl_Position = uViewProjection * world;
}
