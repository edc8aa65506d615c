// Per-channel complex indices for the RGB renderer, fitted to a metal's measured spectrum
// (metal_spectra.h): the (n, κ) whose exact conductor Fresnel reproduces the spectrally integrated
// reflectance. It computes the numbers of the metal presets; it does not hold them (core/brdf/presets.cpp).
#pragma once

#include <glm/glm.hpp>

#include "metal_spectra.h"

namespace glint {

struct ChannelIndices {
    glm::vec3 n;  // per linear sRGB channel
    glm::vec3 k;
};

// The angles the fit compares: θ = 0°, 1°, …, 89°.
inline constexpr int kIndexFitAngleCount = 90;

// Per channel c, with target R_c(θ) = metalReflectance(spectrum, cos θ)_c and F0 = R_c(0):
// - F0 < 1: among the (n, κ) with ((n−1)² + κ²)/((n+1)² + κ²) = F0 (so F0 is exact; n runs over
//   [(1−√F0)/(1+√F0), (1+√F0)/(1−√F0)] and κ² = ((n+1)² F0 − (n−1)²)/(1 − F0)), the one whose
//   unpolarised conductor Fresnel (brdf/fresnel.h) is closest in least squares to R_c at the
//   fit's angles: a scan over log n, then golden-section search around the best point, in
//   double precision (the error is smooth in n, so the result is reproducible to about 1e-6).
// - F0 = 1 after the clip (gold's red): a lossless conductor, n = kLosslessIndex → 0 (R = 1 at
//   every angle whatever κ), with κ the metal's own at the channel's most sensitive wavelength
//   (the largest srgbReflectanceWeight), so the number stays the metal's.
ChannelIndices fitMetalIndices(const MetalSpectrum& spectrum);

// n of a channel whose F0 clips at 1: small enough that F0 computes to 1 in float.
inline constexpr float kLosslessIndex = 1e-8f;

}  // namespace glint
