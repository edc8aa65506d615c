// The display chain on the CPU: radiance → exposure (×2^EV) → clamp to [0,1] → sRGB or gamma
// encoding → 8-bit quantisation (round to nearest). Its GLSL twin is shaders/display.frag.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "image/image.h"
#include "scene/scene.h"

namespace glint {

// The sRGB opto-electronic transfer function (IEC 61966-2-1).
inline float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

inline float encodeForDisplay(float radiance, const DisplaySettings& display) {
    const float exposed = std::clamp(radiance * std::exp2(display.exposureStops), 0.0f, 1.0f);
    return display.transfer == Transfer::Srgb ? encodeSrgb(exposed) : std::pow(exposed, 1.0f / display.gamma);
}

inline uint8_t quantize8(float encoded) {
    return static_cast<uint8_t>(std::floor(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

inline DisplayImage applyDisplayChain(const RadianceImage& image, const DisplaySettings& display) {
    DisplayImage out(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) out.pixels[i] = quantize8(encodeForDisplay(image.pixels[i], display));
    return out;
}

}  // namespace glint
