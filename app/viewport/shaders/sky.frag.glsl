#version 330 core
in vec2 vNdc;
uniform mat4 uInverseViewProjection;
uniform vec3 uZenith;
uniform vec3 uHorizon;
uniform vec3 uBelow;
out vec4 fragColor;
void main() {
    vec4 nearPoint = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    vec3 color = dir.y >= 0.0 ? mix(uHorizon, uZenith, pow(dir.y, 0.6))
                              : mix(uHorizon, uBelow, clamp(-dir.y * 6.0, 0.0, 1.0));
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
