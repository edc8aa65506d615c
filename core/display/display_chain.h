// The display chain on the CPU: radiance → exposure (×2^EV) → tone map (none, Reinhard, ACES
// filmic) → clamp to [0,1] → sRGB, gamma or no encoding → quantisation to N levels with an
// optional ordered dither (quantisation.h) → 8 bits. Its GLSL twin is shaders/display.frag.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// Per-channel tone curves of the exposed value x ≥ 0.
// Reinhard: x/(1+x) (Reinhard et al., Photographic Tone Reproduction for Digital Images, 2002, eq. 3).
// ACES filmic: K. Narkowicz's fit of the ACES reference rendering transform (2015),
// x(2.51x+0.03) / (x(2.43x+0.59)+0.14).
inline float applyToneMap(float exposed, ToneMap toneMap) {
    switch (toneMap) {
        case ToneMap::None: return exposed;
        case ToneMap::Reinhard: return exposed / (1.0f + exposed);
        case ToneMap::AcesFilmic:
            return exposed * (2.51f * exposed + 0.03f) / (exposed * (2.43f * exposed + 0.59f) + 0.14f);
    }
    return exposed;
}

inline float encodeForDisplay(float radiance, const DisplaySettings& display) {
    const float toneMapped = applyToneMap(std::max(radiance * std::exp2(display.exposureStops), 0.0f), display.toneMap);
    const float exposed = std::clamp(toneMapped, 0.0f, 1.0f);
    switch (display.transfer) {
        case Transfer::Srgb: return encodeSrgb(exposed);
        case Transfer::Gamma: return std::pow(exposed, 1.0f / display.gamma);
        case Transfer::Linear: return exposed;
    }
    return exposed;
}

inline uint8_t quantize8(float encoded) {
    return static_cast<uint8_t>(std::floor(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

// Rows of the levels ramp (DisplaySettings::levelsRamp): the bottom eighth, at least one.
inline int levelsRampRows(int height) { return std::max(1, height / 8); }

// The radiance the ramp strip shows at column x: 0 at the left edge to 1 W/(sr·m²) at the right.
inline float levelsRampRadiance(int x, int width) { return (static_cast<float>(x) + 0.5f) / static_cast<float>(width); }

// The 8-bit value of one channel at pixel (x, yFromBottom) (the dither depends on the position).
inline uint8_t displayValue8(float radiance, const DisplaySettings& display, int x, int yFromBottom) {
    const float threshold = ditherThreshold(display.dither, x, yFromBottom);
    return quantize8(quantiseToLevels(encodeForDisplay(radiance, display), display.levels, threshold));
}

inline DisplayImage applyDisplayChain(const RadianceImage& image, const DisplaySettings& display) {
    DisplayImage out(image.width, image.height);
    const int rampRows = display.levelsRamp ? levelsRampRows(image.height) : 0;
    for (int y = 0; y < image.height; ++y) {
        const int yFromBottom = image.height - 1 - y;
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t i = (static_cast<size_t>(y) * image.width + x) * 3 + c;
                const float radiance = yFromBottom < rampRows ? levelsRampRadiance(x, image.width) : image.pixels[i];
                out.pixels[i] = displayValue8(radiance, display, x, yFromBottom);
            }
    }
    return out;
}

}  // namespace glint
