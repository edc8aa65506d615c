// The linear sRGB colour of a surface's spectral reflectance R(λ) seen under CIE standard
// illuminant D65 (CIE 015 colorimetry: a 5 nm sum of S·R·x̄ȳz̄ over 380–780 nm), using the matching
// functions and matrix of cie_cmf.h. It knows no materials; metal spectra are metal_spectra.h.
#pragma once

#include <functional>

#include <glm/glm.hpp>

namespace glint {

// The colorimetric wavelengths 380, 385, …, 780 nm: the spacing of CIE 015's tables.
inline constexpr int kColorimetryWavelengthCount = 81;
float colorimetryWavelength(int index);  // nm, index in [0, kColorimetryWavelengthCount)

// How much reflectance at the index-th wavelength adds to each linear sRGB channel under D65:
// D65(λ)·M_sRGB·(x̄, ȳ, z̄)(λ), divided per channel by its sum over all wavelengths, so the weights
// of a channel add up to 1 and a perfect reflector is exactly white (1, 1, 1). Some are negative:
// the sRGB primaries' matching functions have negative lobes (red between about 440 and 540 nm).
glm::vec3 srgbReflectanceWeight(int index);

// Σ weight(λ)·R(λ) over the colorimetric wavelengths: linear sRGB, white-balanced to D65 (the
// balance only removes the fitted matching functions' and the 4-digit matrix's white error, below
// 0.0005). Not clipped: a saturated colour (gold's red, 1.05) leaves [0, 1].
glm::vec3 reflectanceToLinearSrgb(const std::function<float(float wavelengthNanometres)>& reflectance);

}  // namespace glint
