// The preset table (see presets.h). Metals: per-channel n + iκ fitted to measured spectra
// (tests/metal_index_fit.h; tests/metal_spectra_test.cpp recomputes them); dielectrics: κ = 0
// and n at 589 nm (the clear ones refract: the `glass` model); natural surfaces: broadband
// albedo as Lambert; layered materials: the OpenPBR model's coat, fuzz, thin film and transmission.
#include "brdf/presets.h"

#include "brdf/cook_torrance.h"
#include "interchange/material_values.h"

namespace glint {
namespace {

constexpr float kGgx = static_cast<float>(MicrofacetDistribution::Ggx);
constexpr float kSmith = static_cast<float>(MicrofacetGeometry::Smith);
constexpr float kExact = static_cast<float>(FresnelMode::Exact);

// A polished metal: GGX, height-correlated Smith, exact conductor Fresnel, no diffuse term.
constexpr Preset metal(const char* name, glm::vec3 ior, glm::vec3 extinction, const char* source) {
    return {name, "metal", BrdfModel::CookTorrance,
            {{"ior", ior}, {"extinction", extinction}, {"roughness", glm::vec3(0.08f)}, {"distribution", glm::vec3(kGgx)},
             {"geometry", glm::vec3(kSmith)}, {"fresnel", glm::vec3(kExact)}},
            source};
}

// A clear transparent dielectric: the refracting `glass` model (smooth, exact Fresnel, no
// absorption) with index n, so it reads as glass, water or diamond and not as a dark reflector.
constexpr Preset transparent(const char* name, float ior, const char* source) {
    return {name, "dielectric", BrdfModel::Glass, {{"ior", glm::vec3(ior)}}, source};
}

// A plastic: an opaque diffuse body under a white dielectric specular, κ = 0.
constexpr Preset plastic(const char* name, float ior, glm::vec3 diffuse, float roughness, const char* source) {
    return {name, "plastic", BrdfModel::CookTorrance,
            {{"ior", glm::vec3(ior)}, {"extinction", glm::vec3(0.0f)}, {"diffuse_albedo", diffuse},
             {"roughness", glm::vec3(roughness)}, {"distribution", glm::vec3(kGgx)}, {"fresnel", glm::vec3(kExact)}},
            source};
}

constexpr Preset lambertian(const char* name, float albedo, const char* source) {
    return {name, "natural", BrdfModel::Lambert, {{"albedo", glm::vec3(albedo)}}, source};
}

// What the metals' numbers are (the measurements' full references: tests/metal_spectra.cpp).
#define GLINT_FITTED_TO \
    "n, κ fitted per sRGB channel to the spectrally integrated Fresnel reflectance (D65, CIE 1931; F0 exact) of "
constexpr const char* kRakic1998 = GLINT_FITTED_TO
    "A. D. Rakić et al., Appl. Opt. 37, 5271 (1998), Lorentz-Drude model (refractiveindex.info)";
constexpr const char* kHechtIndex = "E. Hecht, Optics, 4th ed., Table 4.1: refractive index at 589 nm";
constexpr const char* kOkeAlbedo = "T. R. Oke, Boundary Layer Climates, 2nd ed. (1987), Table 1.1: broadband albedo";

constexpr Preset kPresets[] = {
    // Gold's red clips at F0 = 1 (1.05 before the clip): a lossless conductor, n → 0 (kLosslessIndex).
    metal("gold", {1e-8f, 0.377525151f, 1.6137383f}, {3.29923153f, 2.2643714f, 1.72846234f},
          GLINT_FITTED_TO "K. M. McPeak et al., ACS Photonics 2, 326 (2015) (refractiveindex.info); "
                          "red clipped at F0 = 1, n → 0"),
    metal("silver", {0.145585939f, 0.134493664f, 0.13750504f}, {3.91282725f, 3.17071915f, 2.26906776f}, kRakic1998),
    metal("copper", {0.177403733f, 0.968538821f, 1.21253431f}, {3.61480784f, 2.62657404f, 2.35925031f},
          GLINT_FITTED_TO "H.-J. Hagemann et al., J. Opt. Soc. Am. 65, 742 (1975) (refractiveindex.info)"),
    metal("aluminium", {1.39020634f, 0.937823951f, 0.561387777f}, {7.38514185f, 6.39095163f, 5.20355606f}, kRakic1998),
    metal("iron", {2.43629456f, 2.17564368f, 1.70583999f}, {3.32979465f, 3.16553521f, 2.87742519f},
          GLINT_FITTED_TO "M. R. Querry, Optical constants, CRDC-CR-85034 (1985) (refractiveindex.info)"),
    metal("chromium", {3.24471188f, 3.1157949f, 2.28574586f}, {3.28565097f, 3.33660555f, 3.11692643f},
          GLINT_FITTED_TO "P. B. Johnson, R. W. Christy, Phys. Rev. B 9, 5056 (1974) (refractiveindex.info)"),
    transparent("glass", 1.5f, "Crown glass, n ≈ 1.52 (Hecht, Optics, Table 4.1), rounded to 1.5"),
    transparent("water", 1.333f, kHechtIndex),
    transparent("diamond", 2.42f, kHechtIndex),
    transparent("ice", 1.31f, kHechtIndex),
    plastic("red_acrylic", 1.49f, {0.6f, 0.05f, 0.04f}, 0.1f,
            "PMMA n = 1.49 at 589 nm (Hecht, Optics, Table 4.1); diffuse colour illustrative"),
    plastic("white_polystyrene", 1.59f, glm::vec3(0.8f), 0.2f,
            "polystyrene n = 1.59 at 589 nm (Hecht, Optics, Table 4.1); diffuse colour illustrative"),
    lambertian("chalk", 0.85f, "white chalk/limestone, broadband reflectance ≈ 0.85 (approximate, no single measurement)"),
    lambertian("fresh_snow", 0.8f, kOkeAlbedo),
    lambertian("old_snow", 0.4f, kOkeAlbedo),
    lambertian("grass", 0.25f, kOkeAlbedo),
    lambertian("soil", 0.15f, kOkeAlbedo),
    // Layered (OpenPBR): illustrative artist materials, each showing one layer; indices sourced.
    {"car_paint", "layered", BrdfModel::OpenPbr,
     {{"base_color", {0.45f, 0.02f, 0.03f}}, {"base_metalness", glm::vec3(0.4f)}, {"specular_roughness", glm::vec3(0.4f)},
      {"coat_weight", glm::vec3(1.0f)}, {"coat_roughness", glm::vec3(0.05f)}, {"coat_ior", glm::vec3(1.5f)}},
     "metallic red base under a clear coat of n = 1.5 (acrylic/polyurethane clear coats); colours illustrative"},
    {"velvet", "layered", BrdfModel::OpenPbr,
     {{"base_color", {0.2f, 0.01f, 0.05f}}, {"specular_roughness", glm::vec3(0.8f)}, {"fuzz_weight", glm::vec3(1.0f)},
      {"fuzz_color", {0.9f, 0.35f, 0.55f}}, {"fuzz_roughness", glm::vec3(0.5f)}},
     "dark dyed base under a fuzz of fibres (Charlie sheen); colours illustrative"},
    {"soap_bubble", "layered", BrdfModel::OpenPbr,
     {{"base_color", glm::vec3(0.0f)}, {"specular_ior", glm::vec3(1.33f)}, {"specular_roughness", glm::vec3(0.0f)},
      {"transmission_weight", glm::vec3(1.0f)}, {"geometry_thin_walled", glm::vec3(1.0f)},
      {"thin_film_weight", glm::vec3(1.0f)}, {"thin_film_thickness", glm::vec3(0.4f)}, {"thin_film_ior", glm::vec3(1.33f)}},
     "a thin shell of soapy water: n = 1.33 (Hecht, Optics, Table 4.1), film about 0.4 µm thick"},
    {"frosted_glass", "layered", BrdfModel::OpenPbr,
     {{"specular_ior", glm::vec3(1.5f)}, {"specular_roughness", glm::vec3(0.35f)}, {"transmission_weight", glm::vec3(1.0f)},
      {"transmission_color", {0.85f, 0.95f, 0.93f}}, {"transmission_depth", glm::vec3(0.5f)}},
     "rough (etched) crown glass, n = 1.5 (Hecht, Optics, Table 4.1), faintly green over 0.5 m; roughness illustrative"},
    {"gold_f82", "layered", BrdfModel::OpenPbr,
     {{"base_color", {1.0f, 0.785f, 0.343f}}, {"base_metalness", glm::vec3(1.0f)}, {"specular_color", {1.0f, 1.0f, 0.964f}},
      {"specular_roughness", glm::vec3(0.25f)}},
     "gold as F0 and F82 tint, computed from the `gold` preset's fitted n + iκ (McPeak et al. 2015), tint clipped at 1"},
    {"rubber", "layered", BrdfModel::OpenPbr,
     {{"base_color", glm::vec3(0.04f)}, {"base_diffuse_roughness", glm::vec3(0.5f)}, {"specular_roughness", glm::vec3(0.6f)},
      {"specular_ior", glm::vec3(1.52f)}},
     "black natural rubber: n ≈ 1.52 (polyisoprene, Polymer Handbook); albedo and roughness illustrative"},
};
#undef GLINT_FITTED_TO

}  // namespace

Material Preset::material() const {
    Material result = Material::withDefaults(name, model);
    for (const PresetSetting& setting : settings) {
        if (!setting.param) break;
        setParam(result, setting.param, setting.value);  // checks that the model has the parameter
    }
    return result;
}

std::span<const Preset> allPresets() { return kPresets; }

const Preset* findPreset(std::string_view name) {
    for (const Preset& preset : kPresets)
        if (name == preset.name) return &preset;
    return nullptr;
}

}  // namespace glint
