// The metal spectra (see metal_spectra.h): tables, look-up and interpolation, and the reflectance
// integrated to linear sRGB. Sections: tables · look-up · reflectance.
//
// Which measurement for which metal. Real-Time Rendering, 4th ed. (Akenine-Möller et al., 2018),
// Table 9.2 lists F0 in linear sRGB integrated from spectral data. The same integration (D65,
// CIE 1931, reflectance_colour.h) of Johnson & Christy's 1972 noble-metal data misses it by 0.05
// in gold's green (0.730 against 0.782), 0.06 in silver's blue (0.978 against 0.915) and 0.026 in
// copper's red, while pbrt-v4's spectra (src/pbrt/util/spectrum.cpp, not CC0) reproduce its gold,
// silver, copper and aluminium within 0.001: the table rests on other measurements. Of the CC0 data sets in the
// refractiveindex.info database we take, per metal, one that agrees: gold McPeak 2015, silver and
// aluminium Rakić 1998, copper Hagemann 1975 (pbrt's copper in the visible), iron Querry 1985
// (Johnson & Christy 1974 is 0.084 off in blue), chromium Johnson & Christy 1974. Their F0 and
// distance from the table: tests/presets_test.cpp.
#include "metal_spectra.h"

#include <algorithm>

#include "brdf/fresnel.h"
#include "reflectance_colour.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

// --- tables ---------------------------------------------------------------------------------
// (λ [nm], n, κ) as tabulated, from the last point at or below 380 nm to the first at or above
// 780 nm. Each table's measurement and database file: kMetalSpectra below.
constexpr SpectralIndex kGold[] = {
    {370.0f, 1.689202065f, 1.922090949f}, {380.0f, 1.678059067f, 1.948381952f}, {390.0f, 1.672504217f, 1.966512231f},
    {400.0f, 1.665616091f, 1.973924254f}, {410.0f, 1.653911114f, 1.975227068f}, {420.0f, 1.63743714f, 1.970304643f},
    {430.0f, 1.612343317f, 1.959477219f}, {440.0f, 1.581523054f, 1.940313163f}, {450.0f, 1.538326354f, 1.910745397f},
    {460.0f, 1.475285274f, 1.872315849f}, {470.0f, 1.386263242f, 1.827683172f}, {480.0f, 1.252905499f, 1.782097694f},
    {490.0f, 1.064360219f, 1.76786953f}, {500.0f, 0.848474841f, 1.828280492f}, {510.0f, 0.661635502f, 1.964525779f},
    {520.0f, 0.52912664f, 2.129735899f}, {530.0f, 0.438041087f, 2.294990195f}, {540.0f, 0.372502061f, 2.451664289f},
    {550.0f, 0.323930966f, 2.597158307f}, {560.0f, 0.284960267f, 2.738978341f}, {570.0f, 0.254069233f, 2.871855006f},
    {580.0f, 0.228936734f, 2.999518633f}, {590.0f, 0.207122197f, 3.1213458f}, {600.0f, 0.188789629f, 3.241703491f},
    {610.0f, 0.172726107f, 3.356759495f}, {620.0f, 0.160071695f, 3.465634566f}, {630.0f, 0.14636792f, 3.577628204f},
    {640.0f, 0.135417727f, 3.685964997f}, {650.0f, 0.125499436f, 3.792327795f}, {660.0f, 0.117832095f, 3.896137113f},
    {670.0f, 0.111117685f, 3.999543366f}, {680.0f, 0.105744888f, 4.102704228f}, {690.0f, 0.101509306f, 4.205033191f},
    {700.0f, 0.098607898f, 4.305081128f}, {710.0f, 0.097790271f, 4.403812319f}, {720.0f, 0.098623269f, 4.499191766f},
    {730.0f, 0.096903666f, 4.59580138f}, {740.0f, 0.099463321f, 4.687205239f}, {750.0f, 0.098537395f, 4.78107829f},
    {760.0f, 0.099206649f, 4.872354868f}, {770.0f, 0.101706737f, 4.958865219f}, {780.0f, 0.101315225f, 5.051560628f},
    {790.0f, 0.103067755f, 5.148069829f},
};

constexpr SpectralIndex kSilver[] = {
    {374.7f, 0.19062f, 1.5219f}, {382.14f, 0.17791f, 1.6176f}, {389.73f, 0.16796f, 1.7097f},
    {397.46f, 0.16007f, 1.799f}, {405.35f, 0.15377f, 1.886f}, {413.4f, 0.14871f, 1.9714f},
    {421.61f, 0.14463f, 2.0554f}, {429.98f, 0.14136f, 2.1384f}, {438.52f, 0.13874f, 2.2207f},
    {447.22f, 0.13667f, 2.3025f}, {456.1f, 0.13507f, 2.384f}, {465.15f, 0.13386f, 2.4654f},
    {474.39f, 0.133f, 2.5469f}, {483.81f, 0.13244f, 2.6285f}, {493.41f, 0.13214f, 2.7104f},
    {503.21f, 0.13208f, 2.7927f}, {513.2f, 0.13224f, 2.8754f}, {523.39f, 0.13259f, 2.9588f},
    {533.78f, 0.13311f, 3.0428f}, {544.37f, 0.13381f, 3.1276f}, {555.18f, 0.13465f, 3.2132f},
    {566.2f, 0.13565f, 3.2996f}, {577.44f, 0.13678f, 3.3871f}, {588.91f, 0.13804f, 3.4755f},
    {600.6f, 0.13943f, 3.565f}, {612.52f, 0.14094f, 3.6556f}, {624.68f, 0.14257f, 3.7474f},
    {637.09f, 0.14432f, 3.8404f}, {649.73f, 0.14619f, 3.9347f}, {662.63f, 0.14817f, 4.0303f},
    {675.79f, 0.15027f, 4.1273f}, {689.2f, 0.15249f, 4.2258f}, {702.89f, 0.15482f, 4.3257f},
    {716.84f, 0.15727f, 4.4272f}, {731.07f, 0.15984f, 4.5303f}, {745.59f, 0.16253f, 4.6349f},
    {760.39f, 0.16535f, 4.7413f}, {775.49f, 0.16829f, 4.8494f}, {790.88f, 0.17136f, 4.9593f},
};

constexpr SpectralIndex kCopper[] = {
    {364.7f, 1.27f, 1.95f}, {387.5f, 1.232f, 2.07f}, {413.3f, 1.184f, 2.21f}, {442.8f, 1.169f, 2.36f},
    {476.9f, 1.152f, 2.5f}, {516.6f, 1.121f, 2.6f}, {539.1f, 1.037f, 2.59f}, {563.6f, 0.826f, 2.6f},
    {590.4f, 0.468f, 2.81f}, {619.9f, 0.272f, 3.24f}, {652.5f, 0.214f, 3.67f}, {670.2f, 0.215f, 3.86f},
    {688.8f, 0.213f, 4.05f}, {708.5f, 0.214f, 4.24f}, {729.3f, 0.223f, 4.43f}, {826.6f, 0.26f, 5.26f},
};

constexpr SpectralIndex kAluminium[] = {
    {375.63f, 0.39743f, 4.4097f}, {378.77f, 0.4043f, 4.4478f}, {381.92f, 0.41133f, 4.4863f},
    {385.11f, 0.4185f, 4.525f}, {388.32f, 0.42583f, 4.5641f}, {391.56f, 0.43332f, 4.6035f},
    {394.82f, 0.44098f, 4.6432f}, {398.11f, 0.44881f, 4.6832f}, {401.43f, 0.45683f, 4.7236f},
    {404.78f, 0.46504f, 4.7643f}, {408.15f, 0.47345f, 4.8052f}, {411.56f, 0.48206f, 4.8465f},
    {414.99f, 0.49088f, 4.8882f}, {418.45f, 0.49993f, 4.9301f}, {421.93f, 0.5092f, 4.9724f},
    {425.45f, 0.51871f, 5.015f}, {429.0f, 0.52845f, 5.0578f}, {432.58f, 0.53845f, 5.1011f},
    {436.18f, 0.54871f, 5.1446f}, {439.82f, 0.55924f, 5.1884f}, {443.49f, 0.57004f, 5.2325f},
    {447.18f, 0.58112f, 5.2769f}, {450.91f, 0.5925f, 5.3216f}, {454.67f, 0.60417f, 5.3666f},
    {458.46f, 0.61615f, 5.4119f}, {462.28f, 0.62844f, 5.4574f}, {466.14f, 0.64104f, 5.5033f},
    {470.02f, 0.65398f, 5.5493f}, {473.94f, 0.66725f, 5.5957f}, {477.89f, 0.68086f, 5.6423f},
    {481.88f, 0.69481f, 5.6891f}, {485.89f, 0.70911f, 5.7361f}, {489.94f, 0.72377f, 5.7834f},
    {494.03f, 0.73878f, 5.8309f}, {498.15f, 0.75416f, 5.8785f}, {502.3f, 0.7699f, 5.9264f},
    {506.49f, 0.78601f, 5.9744f}, {510.71f, 0.80249f, 6.0226f}, {514.97f, 0.81933f, 6.0709f},
    {519.26f, 0.83655f, 6.1194f}, {523.59f, 0.85413f, 6.168f}, {527.96f, 0.87207f, 6.2167f},
    {532.36f, 0.89038f, 6.2655f}, {536.8f, 0.90904f, 6.3144f}, {541.27f, 0.92804f, 6.3634f},
    {545.78f, 0.9474f, 6.4125f}, {550.33f, 0.96708f, 6.4617f}, {554.92f, 0.9871f, 6.5109f},
    {559.55f, 1.0074f, 6.5601f}, {564.21f, 1.0281f, 6.6094f}, {568.92f, 1.049f, 6.6587f},
    {573.66f, 1.0702f, 6.7081f}, {578.44f, 1.0917f, 6.7576f}, {583.27f, 1.1134f, 6.8071f},
    {588.13f, 1.1354f, 6.8566f}, {593.03f, 1.1576f, 6.9063f}, {597.98f, 1.1801f, 6.956f},
    {602.96f, 1.2028f, 7.0058f}, {607.99f, 1.2257f, 7.0558f}, {613.06f, 1.2489f, 7.106f},
    {618.17f, 1.2723f, 7.1563f}, {623.32f, 1.2959f, 7.2069f}, {628.52f, 1.3198f, 7.2578f},
    {633.76f, 1.3441f, 7.3089f}, {639.04f, 1.3687f, 7.3605f}, {644.37f, 1.3937f, 7.4124f},
    {649.74f, 1.4192f, 7.4649f}, {655.16f, 1.4452f, 7.5178f}, {660.62f, 1.472f, 7.5713f},
    {666.13f, 1.4996f, 7.6254f}, {671.68f, 1.5283f, 7.6801f}, {677.28f, 1.5581f, 7.7354f},
    {682.93f, 1.5894f, 7.7913f}, {688.62f, 1.6223f, 7.8477f}, {694.36f, 1.6573f, 7.9046f},
    {700.15f, 1.6945f, 7.9618f}, {705.99f, 1.7345f, 8.0191f}, {711.87f, 1.7775f, 8.0761f},
    {717.81f, 1.8241f, 8.1324f}, {723.79f, 1.8745f, 8.1875f}, {729.83f, 1.9291f, 8.2405f},
    {735.91f, 1.9883f, 8.2905f}, {742.05f, 2.0521f, 8.3365f}, {748.23f, 2.1205f, 8.3769f},
    {754.47f, 2.193f, 8.4104f}, {760.76f, 2.2687f, 8.4352f}, {767.1f, 2.3463f, 8.4497f},
    {773.5f, 2.4237f, 8.4524f}, {779.95f, 2.4982f, 8.4424f}, {786.45f, 2.5667f, 8.4194f},
};

constexpr SpectralIndex kIron[] = {
    {370.0f, 1.339f, 2.454f}, {380.0f, 1.39f, 2.526f}, {390.0f, 1.442f, 2.588f},
    {400.0f, 1.492f, 2.644f}, {410.0f, 1.538f, 2.698f}, {420.0f, 1.583f, 2.753f},
    {430.0f, 1.631f, 2.806f}, {440.0f, 1.682f, 2.858f}, {450.0f, 1.736f, 2.906f},
    {460.0f, 1.79f, 2.949f}, {470.0f, 1.846f, 2.989f}, {480.0f, 1.903f, 3.019f},
    {490.0f, 1.952f, 3.043f}, {500.0f, 1.996f, 3.067f}, {510.0f, 2.039f, 3.091f},
    {520.0f, 2.08f, 3.113f}, {530.0f, 2.119f, 3.134f}, {540.0f, 2.156f, 3.153f},
    {550.0f, 2.189f, 3.171f}, {560.0f, 2.219f, 3.19f}, {570.0f, 2.252f, 3.21f},
    {580.0f, 2.281f, 3.223f}, {590.0f, 2.305f, 3.241f}, {600.0f, 2.328f, 3.259f},
    {610.0f, 2.35f, 3.277f}, {620.0f, 2.37f, 3.297f}, {630.0f, 2.391f, 3.317f},
    {640.0f, 2.408f, 3.336f}, {650.0f, 2.427f, 3.361f}, {660.0f, 2.448f, 3.383f},
    {670.0f, 2.468f, 3.404f}, {680.0f, 2.486f, 3.423f}, {690.0f, 2.503f, 3.443f},
    {700.0f, 2.519f, 3.463f}, {710.0f, 2.533f, 3.485f}, {720.0f, 2.549f, 3.507f},
    {730.0f, 2.564f, 3.527f}, {740.0f, 2.577f, 3.549f}, {750.0f, 2.587f, 3.569f},
    {760.0f, 2.597f, 3.595f}, {770.0f, 2.611f, 3.619f}, {780.0f, 2.623f, 3.642f},
    {790.0f, 2.633f, 3.669f},
};

constexpr SpectralIndex kChromium[] = {
    {368.0f, 1.87f, 2.69f}, {381.0f, 1.92f, 2.74f}, {397.0f, 2.0f, 2.83f}, {413.0f, 2.08f, 2.93f},
    {431.0f, 2.19f, 3.04f}, {451.0f, 2.33f, 3.14f}, {471.0f, 2.51f, 3.24f}, {496.0f, 2.75f, 3.3f},
    {521.0f, 2.94f, 3.33f}, {549.0f, 3.18f, 3.33f}, {582.0f, 3.22f, 3.3f}, {617.0f, 3.17f, 3.3f},
    {659.0f, 3.09f, 3.34f}, {704.0f, 3.05f, 3.39f}, {756.0f, 3.08f, 3.42f}, {821.0f, 3.2f, 3.48f},
};

constexpr MetalSpectrum kMetalSpectra[] = {
    {"gold", kGold,
     "K. M. McPeak et al., Plasmonic films can easily be better: rules and recipes, ACS Photonics 2, 326 (2015). "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Au/McPeak.yml (commit 5f69b91)"},
    {"silver", kSilver,
     "A. D. Rakić et al., Optical properties of metallic films for vertical-cavity optoelectronic devices, "
     "Appl. Opt. 37, 5271 (1998), Lorentz-Drude model. "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Ag/Rakic-LD.yml (commit 5f69b91)"},
    {"copper", kCopper,
     "H.-J. Hagemann, W. Gudat, C. Kunz, Optical constants from the far infrared to the x-ray region, "
     "J. Opt. Soc. Am. 65, 742 (1975). "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Cu/Hagemann.yml (commit 5f69b91)"},
    {"aluminium", kAluminium,
     "A. D. Rakić et al., Optical properties of metallic films for vertical-cavity optoelectronic devices, "
     "Appl. Opt. 37, 5271 (1998), Lorentz-Drude model. "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Al/Rakic-LD.yml (commit 96dcbbe)"},
    {"iron", kIron,
     "M. R. Querry, Optical constants, Contractor Report CRDC-CR-85034 (1985). "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Fe/Querry.yml (commit 96dcbbe)"},
    {"chromium", kChromium,
     "P. B. Johnson, R. W. Christy, Optical constants of transition metals, Phys. Rev. B 9, 5056 (1974). "
     "Read from refractiveindex.info (CC0): database/data-nk/main/Cr/Johnson.yml (commit 96dcbbe)"},
};

}  // namespace

// --- look-up --------------------------------------------------------------------------------

std::span<const MetalSpectrum> metalSpectra() { return kMetalSpectra; }

const MetalSpectrum* findMetalSpectrum(std::string_view name) {
    for (const MetalSpectrum& spectrum : kMetalSpectra)
        if (name == spectrum.name) return &spectrum;
    return nullptr;
}

glm::vec2 complexIndexAt(const MetalSpectrum& spectrum, float wavelengthNanometres) {
    const auto table = spectrum.table;
    GLINT_CHECK(wavelengthNanometres >= table.front().wavelengthNanometres &&
                wavelengthNanometres <= table.back().wavelengthNanometres);
    // The first point above λ (the last point when λ is the table's end) and the one before it.
    const auto above = std::upper_bound(table.begin(), table.end() - 1, wavelengthNanometres,
                                        [](float wavelength, const SpectralIndex& point) { return wavelength < point.wavelengthNanometres; });
    const SpectralIndex& low = *(above - 1);
    const SpectralIndex& high = *above;
    const float t = (wavelengthNanometres - low.wavelengthNanometres) / (high.wavelengthNanometres - low.wavelengthNanometres);
    return {(1.0f - t) * low.n + t * high.n, (1.0f - t) * low.k + t * high.k};  // exact at t = 0 and t = 1
}

// --- reflectance ----------------------------------------------------------------------------

glm::vec3 metalReflectance(const MetalSpectrum& spectrum, float cosIncident) {
    const glm::vec3 rgb = reflectanceToLinearSrgb([&](float wavelength) {
        const glm::vec2 index = complexIndexAt(spectrum, wavelength);
        return fresnelConductorPolarised(cosIncident, index.x, index.y).unpolarised();
    });
    return glm::clamp(rgb, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace glint
