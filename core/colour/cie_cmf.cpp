// CIE 1931 colour matching functions (Wyman, Sloan & Shirley 2013, multi-lobe fit) and the
// XYZ → linear sRGB matrix (IEC 61966-2-1). See cie_cmf.h.
#include "colour/cie_cmf.h"

#include <cmath>

namespace glint {
namespace {

// Wyman et al. eq. 2: a Gaussian with different widths either side of its peak,
// g(λ; μ, σ₁, σ₂) = exp(−½ (λ−μ)²/σ²), σ = σ₁ for λ < μ, σ₂ otherwise.
float piecewiseGaussian(float wavelength, float peak, float widthBelow, float widthAbove) {
    const float scaled = (wavelength - peak) / (wavelength < peak ? widthBelow : widthAbove);
    return std::exp(-0.5f * scaled * scaled);
}

}  // namespace

glm::vec3 cieColourMatching(float wavelength) {
    // Lobe weights, peaks and widths [nm] from Wyman et al.'s multi-lobe fit (their eq. 2 table).
    const float x = 1.056f * piecewiseGaussian(wavelength, 599.8f, 37.9f, 31.0f) +
                    0.362f * piecewiseGaussian(wavelength, 442.0f, 16.0f, 26.7f) -
                    0.065f * piecewiseGaussian(wavelength, 501.1f, 20.4f, 26.2f);
    const float y = 0.821f * piecewiseGaussian(wavelength, 568.8f, 46.9f, 40.5f) +
                    0.286f * piecewiseGaussian(wavelength, 530.9f, 16.3f, 31.1f);
    const float z = 1.217f * piecewiseGaussian(wavelength, 437.0f, 11.8f, 36.0f) +
                    0.681f * piecewiseGaussian(wavelength, 459.0f, 26.0f, 13.8f);
    return {x, y, z};
}

glm::vec3 xyzToLinearSrgb(glm::vec3 xyz) {
    // IEC 61966-2-1:1999, the inverse of the sRGB primaries' matrix (rows: R, G, B).
    return {3.2406f * xyz.x - 1.5372f * xyz.y - 0.4986f * xyz.z,
            -0.9689f * xyz.x + 1.8758f * xyz.y + 0.0415f * xyz.z,
            0.0557f * xyz.x - 0.2040f * xyz.y + 1.0570f * xyz.z};
}

glm::vec2 chromaticity(glm::vec3 xyz) {
    const float sum = xyz.x + xyz.y + xyz.z;
    if (sum <= 0.0f) return {0.0f, 0.0f};
    return {xyz.x / sum, xyz.y / sum};
}

}  // namespace glint
