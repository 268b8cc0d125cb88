#version 330 core
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vLightClip;
flat in vec3 vColor;
uniform vec3 uEye;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
uniform vec3 uFogColor;
uniform vec2 uFogRange;
uniform float uShadowTexel;
uniform sampler2DShadow uShadowMap;
out vec4 fragColor;

float lightVisibility(vec3 n) {
    vec3 p = vLightClip.xyz / vLightClip.w * 0.5 + 0.5;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    // Slope-scaled bias against acne on faces lit at grazing angles.
    float cosTheta = clamp(dot(n, uLightDir), 0.0, 1.0);
    p.z -= uShadowTexel * (1.5 + 3.0 * sqrt(1.0 - cosTheta * cosTheta) / max(cosTheta, 0.2));
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            sum += texture(uShadowMap, vec3(p.xy + vec2(x, y) * uShadowTexel, p.z));
    return sum / 9.0;
}

void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uEye - vWorldPos);
    float diffuse = max(dot(n, uLightDir), 0.0);
    float visible = diffuse > 0.0 ? lightVisibility(n) : 0.0;
    // Hemispheric ambient: sky from above, bounce from the floor below.
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
    // A weak fill from the opposite side keeps shadowed faces from going flat.
    float fill = 0.18 * max(dot(n, normalize(vec3(-uLightDir.x, 0.3, -uLightDir.z))), 0.0);
    vec3 h = normalize(uLightDir + v);
    float specular = diffuse > 0.0 ? 0.25 * pow(max(dot(n, h), 0.0), 48.0) : 0.0;
    vec3 color = vColor * (ambient + fill + uLightColor * diffuse * visible) + uLightColor * specular * visible;
    float fog = smoothstep(uFogRange.x, uFogRange.y, length(uEye - vWorldPos));
    color = mix(color, uFogColor, fog);
    fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
