// The display chain in GLSL: radiance → exposure → tone map → clamp → sRGB, gamma or none →
// quantisation to N levels, optionally dithered (display_quantise.glsl); twin of core/display/display_chain.h (same formulas and citations there). Used by
// the display pass (display.frag) and, fused, by the passes that write radiance
// (display_output.glsl). It does not read or write any image itself.

#include "common/display_quantise.glsl"

uniform float exposureScale;  // 2^EV
uniform float gamma;
// The choices are compile-time constants in a specialised program (gl/shader_specialisation.h).
#ifdef GLINT_DISPLAY_TRANSFER
const int transfer = GLINT_DISPLAY_TRANSFER;
const int toneMap = GLINT_DISPLAY_TONE_MAP;
#else
uniform int transfer;         // 0: sRGB, 1: gamma, 2: linear (no encoding)
uniform int toneMap;          // 0: none (clip), 1: Reinhard x/(1+x), 2: ACES filmic (Narkowicz 2015), 3: Khronos PBR Neutral
#endif

float encodeSrgb(float linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

vec3 pbrNeutralToneMap(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

vec3 applyToneMap(vec3 exposed) {
    if (toneMap == 3) return pbrNeutralToneMap(exposed);
    if (toneMap == 1) return exposed / (1.0 + exposed);
    if (toneMap == 2) return exposed * (2.51 * exposed + 0.03) / (exposed * (2.43 * exposed + 0.59) + 0.14);
    return exposed;
}

// The display-encoded value of a radiance at a pixel (counted from the lower-left corner, for the
// dither), quantised to the 8-bit level it will be stored as.
vec3 displayEncode(vec3 value, ivec2 pixel) {
    vec3 exposed = clamp(applyToneMap(max(value * exposureScale, 0.0)), 0.0, 1.0);
    vec3 encoded = transfer == 0 ? vec3(encodeSrgb(exposed.r), encodeSrgb(exposed.g), encodeSrgb(exposed.b))
                 : transfer == 1 ? pow(exposed, vec3(1.0 / gamma))
                                 : exposed;
    return quantiseToLevels(encoded, pixel);
}
