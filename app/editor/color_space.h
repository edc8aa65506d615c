// sRGB ↔ linear conversions for colour pickers: the picker shows sRGB-encoded values while the
// scene stores linear RGB (docs/architecture.md, units and conventions). Both curves live in
// core/display/display_chain.h (encodeSrgb, decodeSrgb), shared with texture decoding.
#pragma once

#include "display/display_chain.h"
