// Golden-image comparison with the tolerance of docs/architecture.md (after Filament's renderdiff and
// Blender's render tests): a pixel fails when any channel differs by more than
// `channelTolerance` (default 5/255); the comparison fails when more than `failingFraction`
// (default 0.1%) of pixels fail. Optionally a pixel may match any golden pixel in its 3×3
// neighbourhood (a one-pixel shift of anti-aliased edges). Also builds the ×16 difference image.
#pragma once

#include <string>

#include "image/image.h"

namespace glint {

struct CompareTolerance {
    int channelTolerance = 5;        // in 8-bit steps
    double failingFraction = 0.001;  // of all pixels
    bool allowOnePixelShift = false; // a pixel passes if any golden pixel in its 3×3 neighbourhood matches
};

struct CompareResult {
    bool sizesMatch = true;
    long failingPixels = 0;
    long totalPixels = 0;
    int maxChannelDifference = 0;  // in 8-bit steps (after the shift allowance, when on)
    bool passed = false;

    double failingFraction() const { return totalPixels ? static_cast<double>(failingPixels) / totalPixels : 1.0; }
    std::string summary() const;
};

CompareResult compareImages(const DisplayImage& actual, const DisplayImage& expected, CompareTolerance tolerance = {});

// |actual − expected| × 16 per channel, clamped; images of different sizes give an empty image.
DisplayImage differenceImage(const DisplayImage& actual, const DisplayImage& expected, int gain = 16);

}  // namespace glint
