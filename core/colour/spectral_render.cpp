// Spectral rendering (spectral_render.h): wavelength sampling, Cauchy dispersion, per-wavelength
// reference renders and their integration into XYZ and white-balanced linear sRGB.
// Sections: settings · sampling · colour · rendering.
#include "colour/spectral_render.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "brdf/model_registry.h"
#include "colour/cie_cmf.h"
#include "interchange/material_values.h"
#include "render/reference_renderer.h"
#include "util/text.h"

namespace glint {
namespace {

constexpr float kSodiumDNanometres = 589.3f;  // where A is matched to the material's own index
constexpr float kFwhmToSigma = 0.42466090f;  // σ = FWHM / (2√(2 ln 2))

// ∫ x̄, ȳ, z̄ against the flat spectrum (unit integral over 380–780 nm), by 1 nm midpoints.
glm::vec3 equalEnergyXyz() {
    static const glm::vec3 integral = [] {
        glm::vec3 sum{0.0f};
        const int steps = static_cast<int>(kVisibleMaxNanometres - kVisibleMinNanometres);
        for (int step = 0; step < steps; ++step) sum += cieColourMatching(kVisibleMinNanometres + step + 0.5f);
        return sum / static_cast<float>(steps);
    }();
    return integral;
}

}  // namespace

// --- settings -------------------------------------------------------------------------------

Status checkSpectralSettings(const SpectralSettings& settings) {
    if (settings.spectrum == EmitterSpectrum::NarrowBand) {
        if (!(settings.bandCentreNanometres >= kVisibleMinNanometres && settings.bandCentreNanometres <= kVisibleMaxNanometres))
            return makeError("spectral band centre " + std::to_string(settings.bandCentreNanometres) +
                             " nm is outside the visible range 380–780 nm");
        if (!(settings.bandWidthNanometres > 0.0f && settings.bandWidthNanometres <= 400.0f))
            return makeError("spectral band width " + std::to_string(settings.bandWidthNanometres) +
                             " nm must be above 0 and at most 400 nm");
    }
    if (!(settings.cauchyB >= 0.0f && settings.cauchyB <= 1.0f))
        return makeError("Cauchy B " + std::to_string(settings.cauchyB) + " µm² must be in [0, 1]");
    if (settings.wavelengthSamples < 1 || settings.wavelengthSamples > 256)
        return makeError("wavelength samples " + std::to_string(settings.wavelengthSamples) + " must be 1–256");
    return success();
}

float cauchyIndex(float coefficientA, float coefficientB, float wavelengthNanometres) {
    const float micrometres = wavelengthNanometres * 1e-3f;
    return coefficientA + coefficientB / (micrometres * micrometres);
}

// --- sampling -------------------------------------------------------------------------------

std::vector<WavelengthSample> spectralSamples(const SpectralSettings& settings) {
    const int count = settings.wavelengthSamples;
    std::vector<WavelengthSample> samples;
    if (settings.spectrum == EmitterSpectrum::Flat) {
        // Midpoints of equal bins, each carrying 1/count of the power.
        const float binWidth = (kVisibleMaxNanometres - kVisibleMinNanometres) / count;
        for (int index = 0; index < count; ++index)
            samples.push_back({kVisibleMinNanometres + (index + 0.5f) * binWidth, 1.0f / count});
        return samples;
    }
    // Narrow band: midpoints over centre ± 3σ (inside the visible range), Gaussian weights
    // normalised to 1 so the band carries the light's whole power.
    const float sigma = settings.bandWidthNanometres * kFwhmToSigma;
    const float low = std::max(kVisibleMinNanometres, settings.bandCentreNanometres - 3.0f * sigma);
    const float high = std::min(kVisibleMaxNanometres, settings.bandCentreNanometres + 3.0f * sigma);
    if (count == 1) return {{settings.bandCentreNanometres, 1.0f}};
    const float step = (high - low) / count;
    float total = 0.0f;
    for (int index = 0; index < count; ++index) {
        const float wavelength = low + (index + 0.5f) * step;
        const float offset = (wavelength - settings.bandCentreNanometres) / sigma;
        samples.push_back({wavelength, std::exp(-0.5f * offset * offset)});
        total += samples.back().weight;
    }
    for (WavelengthSample& sample : samples) sample.weight /= total;
    return samples;
}

// --- colour ---------------------------------------------------------------------------------

glm::vec3 spectrumXyz(const std::vector<WavelengthSample>& samples) {
    glm::vec3 xyz{0.0f};
    for (const WavelengthSample& sample : samples) xyz += sample.weight * cieColourMatching(sample.wavelengthNanometres);
    return xyz / equalEnergyXyz().y;
}

glm::vec3 spectralXyzToRgb(glm::vec3 xyz) {
    static const glm::vec3 equalEnergyRgb = xyzToLinearSrgb(equalEnergyXyz() / equalEnergyXyz().y);
    return xyzToLinearSrgb(xyz) / equalEnergyRgb;
}

RadianceImage spectralImageToRgb(const RadianceImage& xyzImage) {
    RadianceImage rgb(xyzImage.width, xyzImage.height);
    for (int y = 0; y < xyzImage.height; ++y)
        for (int x = 0; x < xyzImage.width; ++x) rgb.set(x, y, spectralXyzToRgb(xyzImage.at(x, y)));
    return rgb;
}

// --- rendering ------------------------------------------------------------------------------

Result<RadianceImage> renderSpectralXyz(const Scene& scene, const SpectralSettings& settings, int width, int height,
                                        const std::function<void(float)>& progress) {
    if (Status valid = checkSpectralSettings(settings); !valid) return valid.error();
    const int outputWidth = width > 0 ? width : scene.width;
    const int outputHeight = height > 0 ? height : scene.height;
    // XYZ relative to the equal-energy white's Y. With a flat spectrum each component is also
    // corrected by the exact equal-energy integral over its N-sample estimate, so that a grey
    // scene stays exactly grey at any N (the quadrature error of a few bins would tint it).
    glm::vec3 normalisation(1.0f / equalEnergyXyz().y);
    if (settings.spectrum == EmitterSpectrum::Flat) {
        glm::vec3 sampledFlat{0.0f};
        for (const WavelengthSample& sample : spectralSamples(settings))
            sampledFlat += sample.weight * cieColourMatching(sample.wavelengthNanometres);
        normalisation *= equalEnergyXyz() / sampledFlat;
    }
    Scene atWavelength = scene;
    RadianceImage xyzImage(outputWidth, outputHeight);
    const std::vector<WavelengthSample> samples = spectralSamples(settings);
    for (size_t rendered = 0; rendered < samples.size(); ++rendered) {
        if (progress) progress(static_cast<float>(rendered) / samples.size());
        const WavelengthSample& sample = samples[rendered];
        for (size_t index = 0; index < scene.materials.size(); ++index) {
            const Material& material = scene.materials[index];
            const char* dispersed = material.analytic() ? modelInfo(material.analytic()->model).dispersiveIndex : nullptr;
            if (!dispersed) continue;
            const float indexAtSodiumD = paramScalar(material, dispersed);
            const float coefficientA = indexAtSodiumD - cauchyIndex(0.0f, settings.cauchyB, kSodiumDNanometres);
            const float dispersedIndex = cauchyIndex(coefficientA, settings.cauchyB, sample.wavelengthNanometres);
            // Too strong a B must be refused, not clamped into the table's valid range.
            const auto table = paramTable(material);
            const ParamSpec& spec = table[findParam(table, dispersed)];
            if (!spec.accepts(dispersedIndex))
                return makeError("material '" + material.name + "': Cauchy B " + std::to_string(settings.cauchyB) +
                                 " µm² gives n = " + std::to_string(dispersedIndex) + " at " +
                                 std::to_string(sample.wavelengthNanometres) + " nm, outside " + dispersed + "'s valid [" +
                                 formatNumber(spec.validMin) + ", " + formatNumber(spec.validMax) + "]");
            setParam(atWavelength.materials[index], dispersed, dispersedIndex);
        }
        const RadianceImage rgb = renderReference(atWavelength, outputWidth, outputHeight);
        const glm::vec3 weightedMatching = sample.weight * normalisation * cieColourMatching(sample.wavelengthNanometres);
        for (int y = 0; y < outputHeight; ++y)
            for (int x = 0; x < outputWidth; ++x) {
                const glm::vec3 channels = rgb.at(x, y);
                const float radianceAtWavelength = (channels.r + channels.g + channels.b) / 3.0f;
                xyzImage.set(x, y, xyzImage.at(x, y) + radianceAtWavelength * weightedMatching);
            }
    }
    if (progress) progress(1.0f);
    return xyzImage;
}

}  // namespace glint
