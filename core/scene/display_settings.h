// The display chain's settings (display/display_chain.h has the formulas). Plain data.
#pragma once

#include "scene/overlays.h"

namespace glint {

// Srgb: IEC 61966-2-1; Gamma: value^(1/γ); Linear: no encoding ("gamma off", the classroom's
// lesson on why encoding matters).
enum class Transfer { Srgb, Gamma, Linear };
// Ordered dither added before quantising to `levels` (display/quantisation.h has the matrices).
enum class Dither { None, Bayer2, Bayer4, Halftone };
// Tone mapping of exposed radiance before encoding (display_chain.h has the formulas).
enum class ToneMap { None, Reinhard, AcesFilmic, PbrNeutral };

// The display chain: exposure → tone map → clamp → sRGB, gamma or no encoding → quantisation to
// `levels` per channel (with an optional ordered dither) → 8 bits.
struct DisplaySettings {
    float exposureStops = 0.0f;  // radiance is multiplied by 2^exposureStops
    Transfer transfer = Transfer::Srgb;
    float gamma = 2.2f;  // used when transfer == Gamma
    ToneMap toneMap = ToneMap::None;  // None: values above 1 clip
    int levels = 256;  // intensity levels per channel, 2..256 (256: plain 8-bit output)
    Dither dither = Dither::None;
    bool levelsRamp = false;  // bottom eighth of the image: a grey radiance ramp 0..1 through the chain
    OverlaySettings overlays;  // wireframe / normals drawn over the displayed image (GL only)
};

}  // namespace glint
