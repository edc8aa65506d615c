// The CIE 1931 2° standard observer's colour matching functions x̄(λ), ȳ(λ), z̄(λ), from the
// analytic multi-lobe fit of Wyman, Sloan & Shirley, "Simple Analytic Approximations to the CIE
// XYZ Color Matching Functions", JCGT 2(2), 2013 (eq. 2 and its table), and CIE XYZ → linear
// sRGB (IEC 61966-2-1, D65). It renders nothing; the spectral renderer is spectral_render.h.
#pragma once

#include <glm/glm.hpp>

namespace glint {

// Visible range the spectral tools sample [nm].
inline constexpr float kVisibleMinNanometres = 380.0f;
inline constexpr float kVisibleMaxNanometres = 780.0f;

// (x̄, ȳ, z̄) at wavelength λ [nm]; ȳ peaks at 1 near 555 nm (Wyman et al.'s fit; their reported
// error against the tabulated CIE 1931 functions is below about 0.03 absolute).
glm::vec3 cieColourMatching(float wavelengthNanometres);

// CIE XYZ → linear sRGB (Rec. 709 primaries, D65 white), IEC 61966-2-1 matrix. D65's white
// (0.9505, 1, 1.089) maps to (1, 1, 1); colours outside the gamut get negative components.
glm::vec3 xyzToLinearSrgb(glm::vec3 xyz);

// Chromaticity (x, y) = (X, Y) / (X + Y + Z); (0, 0) for black.
glm::vec2 chromaticity(glm::vec3 xyz);

}  // namespace glint
