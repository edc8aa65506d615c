// sRGB ↔ linear conversions for colour pickers: the picker shows sRGB-encoded values while the
// scene stores linear RGB (DESIGN.md, units and conventions).
#pragma once

#include <cmath>

#include "display/display_chain.h"

namespace glint {

inline float decodeSrgb(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace glint
