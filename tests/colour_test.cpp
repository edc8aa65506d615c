// CIE 1931 colour matching functions (Wyman et al.'s fit) against tabulated CIE values, the
// XYZ → sRGB matrix, spectra (a 555 nm line, the flat spectrum) and the spectral renderer's
// dispersion through a glass sphere (core/colour/). Renders stay at 48×48 and 8 wavelengths.
#include <gtest/gtest.h>

#include <algorithm>

#include "colour/cie_cmf.h"
#include "colour/spectral_render.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

using test::dataPath;

struct ColourTestTabulated {
    float wavelength;
    glm::vec3 matching;
};

// CIE 1931 2° standard observer, from the CIE's 5 nm table (CIE 15:2004, table T.4).
constexpr ColourTestTabulated kColourTestCieTable[] = {
    {450.0f, {0.3362f, 0.0380f, 1.7721f}}, {500.0f, {0.0049f, 0.3230f, 0.2720f}},
    {550.0f, {0.4334f, 0.9950f, 0.0087f}}, {555.0f, {0.5121f, 1.0000f, 0.0057f}},
    {600.0f, {1.0622f, 0.6310f, 0.0008f}}, {650.0f, {0.2835f, 0.1070f, 0.0000f}},
    {700.0f, {0.0114f, 0.0041f, 0.0000f}},
};

TEST(Colour, MatchingFunctionsFollowTheCieTableWithinTheFitsError) {
    // Wyman et al. report the multi-lobe fit within about 0.01 of the table at these wavelengths.
    for (const ColourTestTabulated& row : kColourTestCieTable) {
        const glm::vec3 fitted = cieColourMatching(row.wavelength);
        for (int channel = 0; channel < 3; ++channel)
            EXPECT_NEAR(fitted[channel], row.matching[channel], 0.012f) << row.wavelength << " nm, channel " << channel;
    }
    // Nothing outside the visible range, and ȳ (the luminous efficiency V(λ)) peaks near 555 nm.
    EXPECT_LT(cieColourMatching(800.0f).y, 1e-3f);
    EXPECT_LT(cieColourMatching(360.0f).y, 1e-3f);
    EXPECT_GT(cieColourMatching(555.0f).y, cieColourMatching(530.0f).y);
    EXPECT_GT(cieColourMatching(555.0f).y, cieColourMatching(580.0f).y);
}

TEST(Colour, SrgbMatrixMapsD65WhiteToOneAndPrimariesToTheirChromaticities) {
    const glm::vec3 white = xyzToLinearSrgb({0.95047f, 1.0f, 1.08883f});
    EXPECT_NEAR(white.r, 1.0f, 2e-3f);
    EXPECT_NEAR(white.g, 1.0f, 2e-3f);
    EXPECT_NEAR(white.b, 1.0f, 2e-3f);
    // The sRGB red primary has chromaticity (0.64, 0.33): its XYZ maps to pure red.
    const glm::vec3 red = xyzToLinearSrgb({0.4124f, 0.2126f, 0.0193f});
    EXPECT_NEAR(red.r, 1.0f, 2e-3f);
    EXPECT_NEAR(red.g, 0.0f, 2e-3f);
    EXPECT_NEAR(red.b, 0.0f, 2e-3f);
}

TEST(Colour, A555NanometreLineHasTheSpectralLocusChromaticityAndFullLuminousEfficiency) {
    SpectralSettings line;
    line.spectrum = EmitterSpectrum::NarrowBand;
    line.bandCentreNanometres = 555.0f;
    line.bandWidthNanometres = 1.0f;
    line.wavelengthSamples = 9;
    ASSERT_TRUE(checkSpectralSettings(line).ok());
    const glm::vec3 xyz = spectrumXyz(spectralSamples(line));
    // CIE table at 555 nm: x = 0.5121/1.5178 = 0.3374, y = 1/1.5178 = 0.6589.
    const glm::vec2 xy = chromaticity(xyz);
    EXPECT_NEAR(xy.x, 0.3374f, 0.005f);
    EXPECT_NEAR(xy.y, 0.6589f, 0.005f);
    // Relative to the flat spectrum of equal radiance: ȳ(555) / (∫ȳ dλ / 400 nm) = 1 / 0.2673 ≈ 3.74.
    EXPECT_NEAR(xyz.y, 3.74f, 0.05f);
    // Outside the sRGB gamut: green dominates and red or blue goes negative.
    const glm::vec3 rgb = spectralXyzToRgb(xyz);
    EXPECT_GT(rgb.g, rgb.r);
    EXPECT_GT(rgb.g, rgb.b);
}

TEST(Colour, FlatSpectrumIsNeutralWithUnitLuminance) {
    SpectralSettings flat;
    flat.wavelengthSamples = 16;
    const glm::vec3 xyz = spectrumXyz(spectralSamples(flat));
    EXPECT_NEAR(xyz.y, 1.0f, 0.01f);
    // Illuminant E's chromaticity is (1/3, 1/3).
    EXPECT_NEAR(chromaticity(xyz).x, 1.0f / 3.0f, 0.01f);
    EXPECT_NEAR(chromaticity(xyz).y, 1.0f / 3.0f, 0.01f);
    const glm::vec3 rgb = spectralXyzToRgb(xyz);
    EXPECT_NEAR(rgb.r, rgb.g, 0.02f);
    EXPECT_NEAR(rgb.b, rgb.g, 0.02f);
    EXPECT_NEAR(rgb.g, 1.0f, 0.02f);
}

TEST(Colour, CauchyIndexFallsWithWavelengthAndBadSettingsAreRefused) {
    EXPECT_NEAR(cauchyIndex(1.5046f, 0.0042f, 500.0f), 1.5046f + 0.0042f / 0.25f, 1e-6f);
    EXPECT_GT(cauchyIndex(1.5f, 0.01f, 450.0f), cauchyIndex(1.5f, 0.01f, 650.0f));
    SpectralSettings bad;
    bad.spectrum = EmitterSpectrum::NarrowBand;
    bad.bandCentreNanometres = 900.0f;
    EXPECT_FALSE(checkSpectralSettings(bad).ok());
    bad = {};
    bad.cauchyB = -0.1f;
    EXPECT_FALSE(checkSpectralSettings(bad).ok());
    bad = {};
    bad.wavelengthSamples = 0;
    EXPECT_FALSE(checkSpectralSettings(bad).ok());
}

TEST(Colour, LambertSunUnderAFlatSpectrumRendersTheSameGreyAsRgb) {
    auto scene = loadScene(dataPath("scenes/lambert_sun.json"));
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    SpectralSettings flat;
    flat.wavelengthSamples = 8;
    auto xyz = renderSpectralXyz(*scene, flat, 33, 33);
    ASSERT_TRUE(xyz.ok()) << xyz.error().format();
    // The centre pixel is 0.5 W/(sr·m²) in the RGB render (docs/scene-format.md): neutral 0.5 here too.
    const glm::vec3 centre = spectralXyzToRgb(xyz->at(16, 16));
    EXPECT_NEAR(centre.r, 0.5f, 0.01f);
    EXPECT_NEAR(centre.g, 0.5f, 0.01f);
    EXPECT_NEAR(centre.b, 0.5f, 0.01f);
}

// Mean linear red and blue over the lower half of the ball's image, inside 0.8 of its radius
// (48×48 pixels, orthographic, radius 20 pixels).
glm::vec2 colourTestLowerHalfRedBlue(const RadianceImage& rgb) {
    glm::dvec2 sum{0.0};
    int count = 0;
    for (int y = 24; y < rgb.height; ++y)
        for (int x = 0; x < rgb.width; ++x) {
            const float dx = x + 0.5f - 24.0f, dy = y + 0.5f - 24.0f;
            if (dx * dx + dy * dy > 16.0f * 16.0f) continue;
            sum += glm::dvec2(rgb.at(x, y).r, rgb.at(x, y).b);
            ++count;
        }
    return glm::vec2(sum / static_cast<double>(std::max(count, 1)));
}

TEST(Colour, GlassSphereDispersesBlueFurtherThanRed) {
    // The ball is a lens that shows the sky upside down: its lower half looks up into the sky,
    // whose radiance grows with elevation (examples/spectral/dispersion.json). Blue, with the larger
    // n(λ) of Cauchy's equation, is bent further, looks higher up the gradient and comes out brighter
    // than red there; without dispersion (B = 0) the same region is grey.
    auto scene = loadScene(dataPath("../examples/spectral/dispersion.json"));
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    SpectralSettings settings;
    settings.wavelengthSamples = 8;
    settings.cauchyB = 0.0f;
    auto plain = renderSpectralXyz(*scene, settings, 48, 48);
    settings.cauchyB = 0.03f;
    auto dispersed = renderSpectralXyz(*scene, settings, 48, 48);
    ASSERT_TRUE(plain.ok() && dispersed.ok());
    const glm::vec2 grey = colourTestLowerHalfRedBlue(spectralImageToRgb(*plain));
    const glm::vec2 split = colourTestLowerHalfRedBlue(spectralImageToRgb(*dispersed));
    ASSERT_GT(grey.x, 0.1f);
    EXPECT_NEAR(grey.y / grey.x, 1.0f, 0.01f);
    EXPECT_GT(split.y / split.x, 1.03f) << "red " << split.x << ", blue " << split.y;
}

}  // namespace
}  // namespace glint
