#version 330 core
in vec3 vWorldPos;
uniform vec3 uEye;
uniform vec2 uFadeRange;
out vec4 fragColor;

// Coverage of the lines at integer values of coord (about 1.2 pixels wide).
float lines(vec2 coord) {
    vec2 width = fwidth(coord);
    vec2 distance = abs(fract(coord - 0.5) - 0.5) / max(width * 1.2, vec2(1e-6));
    float coverage = 1.0 - min(min(distance.x, distance.y), 1.0);
    // Lines closer than a few pixels apart would alias; fade them out instead.
    return coverage * (1.0 - smoothstep(0.15, 0.4, max(width.x, width.y)));
}

float axisLine(float value) {
    float width = fwidth(value) * 1.6;
    return 1.0 - min(abs(value) / max(width, 1e-6), 1.0);
}

void main() {
    vec2 xz = vWorldPos.xz;
    float minor = lines(xz);         // 1 m
    float major = lines(xz / 10.0);  // 10 m
    vec3 color = vec3(0.16, 0.17, 0.19);
    float alpha = max(minor * 0.28, major * 0.55);
    // World axes: X in red along z = 0, Z in blue along x = 0.
    float ax = axisLine(xz.y), az = axisLine(xz.x);
    if (ax > 0.0 || az > 0.0) {
        color = ax >= az ? vec3(0.75, 0.12, 0.10) : vec3(0.10, 0.25, 0.80);
        alpha = max(alpha, max(ax, az) * 0.8);
    }
    alpha *= 1.0 - smoothstep(uFadeRange.x, uFadeRange.y, length(uEye - vWorldPos));
    if (alpha <= 0.002) discard;
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), alpha);
}
