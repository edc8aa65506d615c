// The display chain on the CPU: radiance → exposure (×2^EV) → tone map (none, Reinhard, ACES
// filmic, PBR Neutral) → clamp to [0,1] → sRGB, gamma or no encoding → quantisation to N levels with an
// optional ordered dither (quantisation.h) → 8 bits. Its GLSL twin is shaders/display.frag.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "display/quantisation.h"
#include "image/image.h"
#include "scene/scene.h"

namespace glint {

// The sRGB opto-electronic transfer function (IEC 61966-2-1).
inline float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Its inverse, the electro-optical transfer: encoded value in [0,1] → linear.
inline float decodeSrgb(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// Tone curves of the exposed colour x ≥ 0 (each channel ≥ 0).
// Reinhard: x/(1+x) per channel (Reinhard et al., Photographic Tone Reproduction for Digital Images, 2002, eq. 3).
// ACES filmic: K. Narkowicz's fit of the ACES reference rendering transform (2015), per channel,
// x(2.51x+0.03) / (x(2.43x+0.59)+0.14).
// PBR Neutral: the Khronos PBR Neutral tone mapper (Khronos Group, 2024, the reference GLSL of
// github.com/KhronosGroup/ToneMapping): on the whole colour, so that hues and saturation survive
// until the brightest channel nears 1; below 0.76 it only lifts blacks by an offset ≤ 0.04.
inline glm::vec3 pbrNeutralToneMap(glm::vec3 color) {
    constexpr float kStartCompression = 0.8f - 0.04f;
    constexpr float kDesaturation = 0.15f;
    const float x = std::min(color.r, std::min(color.g, color.b));
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color -= offset;
    const float peak = std::max(color.r, std::max(color.g, color.b));
    if (peak < kStartCompression) return color;
    constexpr float d = 1.0f - kStartCompression;
    const float newPeak = 1.0f - d * d / (peak + d - kStartCompression);
    color *= newPeak / peak;
    const float g = 1.0f - 1.0f / (kDesaturation * (peak - newPeak) + 1.0f);
    return glm::mix(color, glm::vec3(newPeak), g);
}

inline glm::vec3 applyToneMap(glm::vec3 exposed, ToneMap toneMap) {
    switch (toneMap) {
        case ToneMap::None: return exposed;
        case ToneMap::Reinhard: return exposed / (1.0f + exposed);
        case ToneMap::AcesFilmic:
            return exposed * (2.51f * exposed + 0.03f) / (exposed * (2.43f * exposed + 0.59f) + 0.14f);
        case ToneMap::PbrNeutral: return pbrNeutralToneMap(exposed);
    }
    return exposed;
}

// A grey (all channels equal).
inline float applyToneMap(float exposed, ToneMap toneMap) { return applyToneMap(glm::vec3(exposed), toneMap).r; }

inline glm::vec3 encodeForDisplay(glm::vec3 radiance, const DisplaySettings& display) {
    const glm::vec3 toneMapped = applyToneMap(glm::max(radiance * std::exp2(display.exposureStops), 0.0f), display.toneMap);
    const glm::vec3 exposed = glm::clamp(toneMapped, 0.0f, 1.0f);
    switch (display.transfer) {
        case Transfer::Srgb: return {encodeSrgb(exposed.r), encodeSrgb(exposed.g), encodeSrgb(exposed.b)};
        case Transfer::Gamma: return glm::pow(exposed, glm::vec3(1.0f / display.gamma));
        case Transfer::Linear: return exposed;
    }
    return exposed;
}

// A grey (all channels equal).
inline float encodeForDisplay(float radiance, const DisplaySettings& display) {
    return encodeForDisplay(glm::vec3(radiance), display).r;
}

inline uint8_t quantize8(float encoded) {
    return static_cast<uint8_t>(std::floor(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

// Rows of the levels ramp (DisplaySettings::levelsRamp): the bottom eighth, at least one.
inline int levelsRampRows(int height) { return std::max(1, height / 8); }

// The radiance the ramp strip shows at column x: 0 at the left edge to 1 W/(sr·m²) at the right.
inline float levelsRampRadiance(int x, int width) { return (static_cast<float>(x) + 0.5f) / static_cast<float>(width); }

// The 8-bit value of one channel of the encoded colour at pixel (x, yFromBottom) (the dither depends on the position).
inline uint8_t displayValue8(float encoded, const DisplaySettings& display, int x, int yFromBottom) {
    const float threshold = ditherThreshold(display.dither, x, yFromBottom);
    return quantize8(quantiseToLevels(encoded, display.levels, threshold));
}

inline DisplayImage applyDisplayChain(const RadianceImage& image, const DisplaySettings& display) {
    DisplayImage out(image.width, image.height);
    const int rampRows = display.levelsRamp ? levelsRampRows(image.height) : 0;
    for (int y = 0; y < image.height; ++y) {
        const int yFromBottom = image.height - 1 - y;
        for (int x = 0; x < image.width; ++x) {
            const size_t i = (static_cast<size_t>(y) * image.width + x) * 3;
            const glm::vec3 radiance = yFromBottom < rampRows ? glm::vec3(levelsRampRadiance(x, image.width))
                                                              : glm::vec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
            const glm::vec3 encoded = encodeForDisplay(radiance, display);
            for (int c = 0; c < 3; ++c) out.pixels[i + c] = displayValue8(encoded[c], display, x, yFromBottom);
        }
    }
    return out;
}

}  // namespace glint
