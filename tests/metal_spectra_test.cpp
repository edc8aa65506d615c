// Metal spectra (metal_spectra.h), the D65 colorimetry they are integrated with
// (reflectance_colour.h) and the per-channel indices fitted to them (metal_index_fit.h): the metal
// presets' numbers must be exactly what the fit computes from the spectra.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdf/cook_torrance.h"
#include "brdf/presets.h"
#include "math/constants.h"
#include "metal_index_fit.h"
#include "metal_spectra.h"
#include "reflectance_colour.h"

namespace glint {
namespace {

TEST(MetalSpectra, AConstantReflectanceIsAGreyOfTheSameValue) {
    // White-balanced to D65: the perfect reflector is (1, 1, 1), and R(λ) = c gives (c, c, c).
    for (const float constant : {0.0f, 0.3f, 1.0f}) {
        const glm::vec3 rgb = reflectanceToLinearSrgb([&](float) { return constant; });
        for (int channel = 0; channel < 3; ++channel) EXPECT_NEAR(rgb[channel], constant, 1e-6f) << constant;
    }
    // Reflecting only beyond 600 nm looks red, only below 480 nm blue.
    const glm::vec3 red = reflectanceToLinearSrgb([](float wavelength) { return wavelength > 600.0f ? 1.0f : 0.0f; });
    EXPECT_GT(red.r, 5.0f * std::max(red.g, red.b));
    const glm::vec3 blue = reflectanceToLinearSrgb([](float wavelength) { return wavelength < 480.0f ? 1.0f : 0.0f; });
    EXPECT_GT(blue.b, 5.0f * std::max(blue.r, blue.g));
    EXPECT_EQ(colorimetryWavelength(0), 380.0f);
    EXPECT_EQ(colorimetryWavelength(kColorimetryWavelengthCount - 1), 780.0f);
}

TEST(MetalSpectra, TablesCoverTheVisibleRangeAndInterpolationHitsTheirPoints) {
    ASSERT_EQ(metalSpectra().size(), 6u);
    for (const MetalSpectrum& spectrum : metalSpectra()) {
        SCOPED_TRACE(spectrum.name);
        EXPECT_EQ(findMetalSpectrum(spectrum.name), &spectrum);
        EXPECT_NE(std::string(spectrum.source).find("refractiveindex.info"), std::string::npos);
        const auto table = spectrum.table;
        EXPECT_LE(table.front().wavelengthNanometres, 380.0f);
        EXPECT_GE(table.back().wavelengthNanometres, 780.0f);
        for (size_t i = 0; i < table.size(); ++i) {
            // At a tabulated wavelength, exactly the tabulated values.
            const glm::vec2 index = complexIndexAt(spectrum, table[i].wavelengthNanometres);
            EXPECT_EQ(index.x, table[i].n) << table[i].wavelengthNanometres << " nm";
            EXPECT_EQ(index.y, table[i].k) << table[i].wavelengthNanometres << " nm";
            if (i + 1 == table.size()) continue;
            EXPECT_LT(table[i].wavelengthNanometres, table[i + 1].wavelengthNanometres);
            // Halfway, halfway between.
            const glm::vec2 middle =
                complexIndexAt(spectrum, 0.5f * (table[i].wavelengthNanometres + table[i + 1].wavelengthNanometres));
            EXPECT_NEAR(middle.x, 0.5f * (table[i].n + table[i + 1].n), 1e-5f);
            EXPECT_NEAR(middle.y, 0.5f * (table[i].k + table[i + 1].k), 1e-5f);
        }
    }
    EXPECT_EQ(findMetalSpectrum("unobtainium"), nullptr);
}

TEST(MetalSpectra, GoldsRedLeavesTheSrgbGamutAndIsClipped) {
    const MetalSpectrum& gold = *findMetalSpectrum("gold");
    const glm::vec3 unclipped = reflectanceToLinearSrgb([&](float wavelength) {
        const glm::vec2 index = complexIndexAt(gold, wavelength);
        return fresnelF0(glm::vec3(index.x), glm::vec3(index.y)).x;
    });
    EXPECT_GT(unclipped.r, 1.04f);  // 1.05: no sRGB colour is as saturated as gold
    EXPECT_EQ(metalReflectance(gold, 1.0f).r, 1.0f);
    EXPECT_NEAR(metalReflectance(gold, 1.0f).g, unclipped.g, 1e-6f);
}

// The preset's (n, κ), or nullptr where it sets none.
const glm::vec3* presetSetting(const Preset& preset, std::string_view param) {
    for (const PresetSetting& setting : preset.settings) {
        if (!setting.param) break;
        if (param == setting.param) return &setting.value;
    }
    return nullptr;
}

TEST(MetalSpectra, MetalPresetsHoldTheIndicesFittedToTheirSpectra) {
    // The generator: on a mismatch (after changing a table or the fit) the line to paste into
    // core/brdf/presets.cpp is printed. Agreement to 1e-5 relative: builds that contract a·b + c
    // into one FMA (-march=native) move the fit's last digits by up to 2e-6.
    for (const MetalSpectrum& spectrum : metalSpectra()) {
        SCOPED_TRACE(spectrum.name);
        const Preset* preset = findPreset(spectrum.name);
        ASSERT_NE(preset, nullptr);
        const ChannelIndices fitted = fitMetalIndices(spectrum);
        const glm::vec3 n = *presetSetting(*preset, "ior"), k = *presetSetting(*preset, "extinction");
        bool same = true;
        for (int c = 0; c < 3; ++c) {
            same &= std::abs(n[c] - fitted.n[c]) <= 1e-5f * std::max(1.0f, fitted.n[c]);
            same &= std::abs(k[c] - fitted.k[c]) <= 1e-5f * std::max(1.0f, fitted.k[c]);
        }
        char line[256];
        std::snprintf(line, sizeof line, "metal(\"%s\", {%.9gf, %.9gf, %.9gf}, {%.9gf, %.9gf, %.9gf}, ...)", spectrum.name,
                      fitted.n.r, fitted.n.g, fitted.n.b, fitted.k.r, fitted.k.g, fitted.k.b);
        EXPECT_TRUE(same) << "the fit now gives " << line;
        // F0 of the preset is the integrated F0, to float precision.
        const glm::vec3 presetF0 = fresnelF0(n, k), spectralF0 = metalReflectance(spectrum, 1.0f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(presetF0[c], spectralF0[c], 1e-6f) << "channel " << c;
    }
}

TEST(MetalSpectra, FittedIndicesFollowTheIntegratedReflectanceToGrazing) {
    // The constant-F0 family has one free parameter; it matches the integrated curve to 0.005 at
    // every angle (measured: at most 0.0044, copper's red near 80°; gold's red, clipped to 1, is a
    // lossless conductor, 0.003 above the integrated 0.997 at 85°).
    for (const MetalSpectrum& spectrum : metalSpectra()) {
        const Preset& preset = *findPreset(spectrum.name);
        const CookTorranceParams params = unpack<CookTorrance>(preset.material().analytic()->values.data());
        float worst = 0.0f;
        for (const float degrees : {0.0f, 30.0f, 60.0f, 75.0f, 80.0f, 85.0f, 89.0f}) {
            const float cosIncident = std::cos(degrees * kPi / 180.0f);
            const glm::vec3 fitted = fresnelConductor(cosIncident, params.ior, params.extinction);
            const glm::vec3 integrated = metalReflectance(spectrum, cosIncident);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(fitted[c], integrated[c], 0.005f) << spectrum.name << " at " << degrees << "°, channel " << c;
                worst = std::max(worst, std::abs(fitted[c] - integrated[c]));
            }
        }
        std::printf("%-10s fitted Fresnel within %.4f of the integrated curve\n", spectrum.name, worst);
    }
}

}  // namespace
}  // namespace glint
