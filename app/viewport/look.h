#pragma once
// The viewport's look: colours and sizes shared by the renderer, the body batches and the debug
// overlay. Colours are written in sRGB (as a designer picks them) and converted to linear for
// lighting; the shaders convert back to sRGB on output.

#include "app/viewport/color_space.h"

#include <glm/glm.hpp>

#include <array>

namespace interplay::look {

inline glm::vec3 srgb(unsigned rgb) {
    const auto channel = [](unsigned v) { return linearFromSrgb(static_cast<float>(v) / 255.0f); };
    return {channel((rgb >> 16) & 0xFF), channel((rgb >> 8) & 0xFF), channel(rgb & 0xFF)};
}

inline constexpr std::array<unsigned, 8> kPalette = {
    0xE4572E,  // vermilion
    0x2E86AB,  // blue
    0xF3A712,  // amber
    0x4C9F70,  // green
    0xA23B72,  // magenta
    0x17BEBB,  // teal
    0x7D5BA6,  // violet
    0x9BC53D,  // lime
};
inline constexpr unsigned kStaticColor = 0xA7ABB0;  // neutral grey: the floor should not compete with the bodies

inline constexpr unsigned kSkyZenith = 0x6F9BD1;
inline constexpr unsigned kSkyHorizon = 0xD9E3EC;
inline constexpr unsigned kBelowHorizon = 0xC3C9D0;  // close to a lit floor, so a floor's edge does not stand out

inline constexpr unsigned kSelectionColor = 0xFFB000;  // amber: reads against sky, floor and every palette colour
inline constexpr unsigned kSleepingTint = 0x6E7A8A;    // slate: sleeping bodies fade towards it
inline constexpr float kSleepingTintAmount = 0.55f;
inline constexpr float kOutlinePixels = 3.0f;
inline constexpr unsigned kAabbColor = 0x39D353;
inline constexpr unsigned kContactPointColor = 0xFF2E88;
inline constexpr unsigned kContactNormalColor = 0xFFE14D;
inline constexpr unsigned kGrabColor = 0xFFFFFF;
inline constexpr unsigned kJointColor = 0x30343A;  // near black: a rod or a hinge pin, drawn always
inline constexpr float kContactNormalLength = 0.3f;  // m
inline constexpr float kContactMarkSize = 0.05f;     // m, half-size of the cross marking a contact point
inline constexpr float kJointMarkSize = 0.12f;       // m, half-size of the cross marking a selected joint's anchor
inline constexpr float kJointAxisLength = 0.6f;      // m, either way along a selected hinge or slider axis

// Towards the light (world space): high and from the front left of the default camera, so the faces
// turned to the viewer are lit and shadows fall behind the bodies, to the right.
inline const glm::vec3 kLightDirection = glm::normalize(glm::vec3(-0.35f, 1.0f, 0.55f));

}  // namespace interplay::look
