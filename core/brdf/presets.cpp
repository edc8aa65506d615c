// The preset table (see presets.h). Metals: complex index n + iκ at about 650, 550 and 450 nm
// (R, G, B); dielectrics: κ = 0 and n at 589 nm; natural surfaces: broadband albedo as Lambert.
#include "brdf/presets.h"

#include "brdf/cook_torrance.h"
#include "util/diagnostic.h"

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

// A smooth dielectric reflector (the rasterizer shows no transmission): white specular, κ = 0.
constexpr Preset dielectric(const char* name, float ior, glm::vec3 diffuse, float roughness, const char* category,
                            const char* source) {
    return {name, category, BrdfModel::CookTorrance,
            {{"ior", glm::vec3(ior)}, {"extinction", glm::vec3(0.0f)}, {"diffuse_albedo", diffuse},
             {"roughness", glm::vec3(roughness)}, {"distribution", glm::vec3(kGgx)}, {"fresnel", glm::vec3(kExact)}},
            source};
}

constexpr Preset lambertian(const char* name, float albedo, const char* source) {
    return {name, "natural", BrdfModel::Lambert, {{"albedo", glm::vec3(albedo)}}, source};
}

constexpr const char* kJohnsonChristy1972 =
    "P. B. Johnson, R. W. Christy, Optical Constants of the Noble Metals, Phys. Rev. B 6, 4370 (1972): "
    "n, κ near 650/550/450 nm (refractiveindex.info)";
constexpr const char* kJohnsonChristy1974 =
    "P. B. Johnson, R. W. Christy, Optical constants of transition metals, Phys. Rev. B 9, 5056 (1974): "
    "n, κ near 650/550/450 nm (refractiveindex.info)";
constexpr const char* kRakic1998 =
    "A. D. Rakić et al., Optical properties of metallic films for vertical-cavity optoelectronic devices, "
    "Appl. Opt. 37, 5271 (1998): n, κ near 650/550/450 nm (refractiveindex.info)";
constexpr const char* kHechtIndex = "E. Hecht, Optics, 4th ed., Table 4.1: refractive index at 589 nm";
constexpr const char* kOkeAlbedo = "T. R. Oke, Boundary Layer Climates, 2nd ed. (1987), Table 1.1: broadband albedo";

constexpr Preset kPresets[] = {
    metal("gold", {0.18299f, 0.42108f, 1.3734f}, {3.4242f, 2.3459f, 1.7704f}, kJohnsonChristy1972),
    metal("silver", {0.15943f, 0.14512f, 0.13547f}, {3.9291f, 3.1900f, 2.3808f}, kJohnsonChristy1972),
    metal("copper", {0.27105f, 0.67693f, 1.31640f}, {3.60920f, 2.62480f, 2.29210f}, kJohnsonChristy1972),
    metal("aluminium", {1.3456f, 0.96521f, 0.61722f}, {7.4746f, 6.3995f, 5.3031f}, kRakic1998),
    metal("iron", {2.9114f, 2.9497f, 2.5845f}, {3.0893f, 2.9318f, 2.7670f}, kJohnsonChristy1974),
    metal("chromium", {3.1071f, 3.1812f, 2.3230f}, {3.3314f, 3.3291f, 3.1350f}, kJohnsonChristy1974),
    dielectric("glass", 1.5f, glm::vec3(0.0f), 0.01f, "dielectric", "Crown glass, n ≈ 1.52 (Hecht, Optics, Table 4.1), rounded to 1.5"),
    dielectric("water", 1.333f, glm::vec3(0.0f), 0.01f, "dielectric", kHechtIndex),
    dielectric("diamond", 2.42f, glm::vec3(0.0f), 0.005f, "dielectric", kHechtIndex),
    dielectric("ice", 1.31f, glm::vec3(0.0f), 0.05f, "dielectric", kHechtIndex),
    dielectric("red_acrylic", 1.49f, {0.6f, 0.05f, 0.04f}, 0.1f, "plastic",
               "PMMA n = 1.49 at 589 nm (Hecht, Optics, Table 4.1); diffuse colour illustrative"),
    dielectric("white_polystyrene", 1.59f, glm::vec3(0.8f), 0.2f, "plastic",
               "polystyrene n = 1.59 at 589 nm (Hecht, Optics, Table 4.1); diffuse colour illustrative"),
    lambertian("chalk", 0.85f, "white chalk/limestone, broadband reflectance ≈ 0.85 (approximate, no single measurement)"),
    lambertian("fresh_snow", 0.8f, kOkeAlbedo),
    lambertian("old_snow", 0.4f, kOkeAlbedo),
    lambertian("grass", 0.25f, kOkeAlbedo),
    lambertian("soil", 0.15f, kOkeAlbedo),
};

}  // namespace

Material Preset::material() const {
    Material result = Material::withDefaults(name, model);
    const auto table = modelInfo(model).params;
    for (const PresetSetting& setting : settings) {
        if (!setting.param) break;
        const int index = findParam(table, setting.param);
        GLINT_CHECK(index >= 0 && "preset names a parameter its model lacks");
        for (int c = 0; c < componentCount(table[index].kind); ++c)
            result.values[packedOffset(table, index) + c] = setting.value[c];
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
