// Spectral mode: renders a scene one wavelength at a time with the CPU reference renderer
// (render/reference_renderer.h) and integrates the colour matching functions (cie_cmf.h) into
// CIE XYZ, then linear sRGB. Glass disperses by Cauchy's equation n(λ) = A + B/λ²; the emitters
// follow a flat (equal-energy) or narrow-band spectrum. It does not touch the GL renderer.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

enum class EmitterSpectrum {
    Flat,        // equal energy per nanometre over 380–780 nm (CIE illuminant E)
    NarrowBand,  // a Gaussian of the given centre and full width at half maximum
};

struct SpectralSettings {
    EmitterSpectrum spectrum = EmitterSpectrum::Flat;
    float bandCentreNanometres = 555.0f;  // NarrowBand: in [380, 780]
    float bandWidthNanometres = 10.0f;    // NarrowBand: FWHM > 0
    // Cauchy's B [µm²] of every glass material; A is chosen so that n(589.3 nm, sodium D) is the
    // material's own index. BK7 crown glass: about 0.0042; dense flint: about 0.016.
    float cauchyB = 0.0042f;
    int wavelengthSamples = 16;           // 1–256 wavelengths rendered
};

// Refuses NaN, a band outside the visible range, a non-positive width, a negative B, a sample
// count outside 1–256 (the message names the setting).
Status checkSpectralSettings(const SpectralSettings& settings);

// Cauchy's equation n(λ) = A + B/λ², λ in µm.
float cauchyIndex(float coefficientA, float coefficientBSquareMicrometres, float wavelengthNanometres);

// The wavelengths rendered and their quadrature weights: Σ weight·f(λ) ≈ ∫ S(λ) f(λ) dλ for the
// emitter spectrum S normalised to ∫ S dλ = 1 (a light's stated power is spread over the band).
struct WavelengthSample {
    float wavelengthNanometres;
    float weight;
};
std::vector<WavelengthSample> spectralSamples(const SpectralSettings& settings);

// XYZ of a unit-radiance emitter with spectrum S, relative to the equal-energy spectrum's Y
// (so a flat spectrum gives Y = 1; a 555 nm line gives Y = ȳ(555)/∫ȳ S_flat ≈ 3.7, the eye's
// greater sensitivity there).
glm::vec3 spectrumXyz(const std::vector<WavelengthSample>& samples);

// Linear sRGB of an XYZ, white-balanced so that the equal-energy spectrum (illuminant E) is
// neutral: M_sRGB·XYZ divided per channel by M_sRGB·XYZ_E (a von Kries-style diagonal scaling).
glm::vec3 spectralXyzToRgb(glm::vec3 xyz);

// Renders `scene` at width×height (its own size when zero): for each wavelength, every glass
// index becomes n(λ), the RGB reference render's channel mean is the radiance at λ (lights,
// background and material colours act as their grey mean), and the weighted sum against the
// matching functions gives XYZ (relative to equal-energy white, as spectrumXyz; with a flat
// spectrum each component is corrected for the N-sample quadrature, so grey stays grey).
// `progress` (when set) hears the fraction of wavelengths rendered after each one.
Result<RadianceImage> renderSpectralXyz(const Scene& scene, const SpectralSettings& settings, int width = 0, int height = 0,
                                        const std::function<void(float)>& progress = {});
// The XYZ image as linear sRGB radiance (spectralXyzToRgb per pixel).
RadianceImage spectralImageToRgb(const RadianceImage& xyzImage);

}  // namespace glint
