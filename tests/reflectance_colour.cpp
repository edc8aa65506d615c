// Reflectance spectrum → linear sRGB under D65 (see reflectance_colour.h).
#include "reflectance_colour.h"

#include <array>

#include "colour/cie_cmf.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

constexpr float kColorimetryStepNanometres = 5.0f;

// CIE standard illuminant D65, relative spectral power (100 at 560 nm), 380–780 nm in 5 nm steps:
// CIE 015:2004 Colorimetry, Table T.1 (also ISO 11664-2); read from the CIE_Illum_D6500 table of
// pbrt-v4, src/pbrt/util/spectrum.cpp.
constexpr float kIlluminantD65[kColorimetryWavelengthCount] = {
    49.9755f, 52.3118f, 54.6482f, 68.7015f, 82.7549f, 87.1204f, 91.4860f, 92.4589f, 93.4318f, 90.0570f,
    86.6823f, 95.7736f, 104.865f, 110.936f, 117.008f, 117.410f, 117.812f, 116.336f, 114.861f, 115.392f,
    115.923f, 112.367f, 108.811f, 109.082f, 109.354f, 108.578f, 107.802f, 106.296f, 104.790f, 106.239f,
    107.689f, 106.047f, 104.405f, 104.225f, 104.046f, 102.023f, 100.000f, 98.1671f, 96.3342f, 96.0611f,
    95.7880f, 92.2368f, 88.6856f, 89.3459f, 90.0062f, 89.8026f, 89.5991f, 88.6489f, 87.6987f, 85.4936f,
    83.2886f, 83.4939f, 83.6992f, 81.8630f, 80.0268f, 80.1207f, 80.2146f, 81.2462f, 82.2778f, 80.2810f,
    78.2842f, 74.0027f, 69.7213f, 70.6652f, 71.6091f, 72.9790f, 74.3490f, 67.9765f, 61.6040f, 65.7448f,
    69.8856f, 72.4863f, 75.0870f, 69.3398f, 63.5927f, 55.0054f, 46.4182f, 56.6118f, 66.8054f, 65.0941f,
    63.3828f,
};

// D65(λ)·M_sRGB·(x̄, ȳ, z̄)(λ) per wavelength, each channel normalised to sum 1 (CIE 015's
// normalisation k = 1/Σ S ȳ, followed by the white balance, in one step).
const std::array<glm::dvec3, kColorimetryWavelengthCount>& reflectanceWeights() {
    static const std::array<glm::dvec3, kColorimetryWavelengthCount> weights = [] {
        std::array<glm::dvec3, kColorimetryWavelengthCount> weight;
        glm::dvec3 white(0.0);
        for (int index = 0; index < kColorimetryWavelengthCount; ++index) {
            const glm::vec3 xyz = kIlluminantD65[index] * cieColourMatching(colorimetryWavelength(index));
            weight[index] = glm::dvec3(xyzToLinearSrgb(xyz));
            white += weight[index];
        }
        for (glm::dvec3& channelWeights : weight) channelWeights /= white;
        return weight;
    }();
    return weights;
}

}  // namespace

float colorimetryWavelength(int index) {
    GLINT_CHECK(index >= 0 && index < kColorimetryWavelengthCount);
    return kVisibleMinNanometres + kColorimetryStepNanometres * static_cast<float>(index);
}

glm::vec3 srgbReflectanceWeight(int index) {
    GLINT_CHECK(index >= 0 && index < kColorimetryWavelengthCount);
    return glm::vec3(reflectanceWeights()[index]);
}

glm::vec3 reflectanceToLinearSrgb(const std::function<float(float wavelengthNanometres)>& reflectance) {
    glm::dvec3 rgb(0.0);
    for (int index = 0; index < kColorimetryWavelengthCount; ++index)
        rgb += reflectanceWeights()[index] * static_cast<double>(reflectance(colorimetryWavelength(index)));
    return glm::vec3(rgb);
}

}  // namespace glint
