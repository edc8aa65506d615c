// The last step of the display chain, for the lecture on intensity levels: quantise an encoded
// value in [0,1] to N levels per channel, optionally with an ordered dither (Bayer 2×2, 4×4) or a
// clustered-dot halftone screen added before rounding. No encoding or tone mapping here
// (display_chain.h); its GLSL twin is shaders/common/display_quantise.glsl.
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace glint {

// Names of enum Dither in scene files and on the command line, in its order.
inline constexpr const char* kDitherIds[] = {"none", "bayer2", "bayer4", "halftone"};

// Threshold matrices of ordered dithering: cell (column, row) holds the rank k of that pixel in
// 0..n²−1; the threshold added before rounding down is (k + 0.5)/n², so that over one tile a
// constant value v·(N−1) + t rounds up on exactly frac(v·(N−1))·n² of the n² pixels, and the
// tile's average is the unquantised value (to 1/n² of a level).
// Bayer: B. E. Bayer, "An optimum method for two-level rendition of continuous-tone pictures",
// IEEE Int. Conf. on Communications, 1973 (dispersed dot: neighbours get far-apart ranks).
inline constexpr int kBayer2[2][2] = {{0, 2}, {3, 1}};
inline constexpr int kBayer4[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
// Clustered-dot halftone screen: ranks spiral out from the cell's centre, so that a darker or
// lighter level is one dot that grows, as on a printed page (R. Ulichney, Digital Halftoning,
// MIT Press 1987, ch. 5 on clustered-dot ordered dither; Foley, van Dam et al., Computer
// Graphics: Principles and Practice, 2nd ed., §13.1.2 "Halftone approximation").
inline constexpr int kHalftone4[4][4] = {{12, 5, 6, 13}, {4, 0, 1, 7}, {11, 3, 2, 8}, {15, 10, 9, 14}};

// The threshold in (0,1) added before rounding down at pixel (x, yFromBottom): counted from the
// image's lower-left corner, as gl_FragCoord is, so that CPU and GPU tile the same way.
// No dither: 0.5, i.e. rounding to the nearest level.
inline float ditherThreshold(Dither dither, int x, int yFromBottom) {
    const int column = x & 3, row = yFromBottom & 3;
    switch (dither) {
        case Dither::None: return 0.5f;
        case Dither::Bayer2: return (static_cast<float>(kBayer2[row & 1][column & 1]) + 0.5f) / 4.0f;
        case Dither::Bayer4: return (static_cast<float>(kBayer4[row][column]) + 0.5f) / 16.0f;
        case Dither::Halftone: return (static_cast<float>(kHalftone4[row][column]) + 0.5f) / 16.0f;
    }
    return 0.5f;
}

// An encoded value in [0,1] quantised to one of `levels` (2..256) equally spaced values
// k/(levels−1): k = ⌊value·(levels−1) + threshold⌋, clamped to 0..levels−1.
inline float quantiseToLevels(float encoded, int levels, float threshold) {
    const float steps = static_cast<float>(levels - 1);
    const float level = std::clamp(std::floor(std::clamp(encoded, 0.0f, 1.0f) * steps + threshold), 0.0f, steps);
    return level / steps;
}

}  // namespace glint
