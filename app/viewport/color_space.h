#pragma once
// sRGB <-> linear RGB for one channel in [0, 1]. Body colours are stored linear (they are lit);
// people pick colours, and the palette is written, in sRGB.

#include <cmath>

namespace interplay {

inline float linearFromSrgb(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float srgbFromLinear(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace interplay
