// Cook-Torrance / Torrance-Sparrow microfacet BRDF f = D·G·F / (4 cos θ_i cos θ_o) plus an
// optional coloured Lambert diffuse term, with a choice of D, G and F (see microfacet.h).
// CPU reference; its GLSL twin is shaders/brdf/cook_torrance.glsl. Isotropic only.
#pragma once

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/model.h"
#include "brdf/microfacet.h"
#include "brdf/trait_forms.h"
#include "math/frame.h"

namespace glint {

enum class MicrofacetDistribution { Beckmann = 0, Ggx = 1 };
enum class MicrofacetGeometry { VCavity = 0, Smith = 1 };

inline constexpr EnumOption kDistributionOptions[] = {
    {"beckmann", "Beckmann"},
    {"ggx", "GGX (Trowbridge-Reitz)"},
};
inline constexpr EnumOption kGeometryOptions[] = {
    {"v_cavity", "V-cavity (Cook-Torrance 1982)"},
    {"smith", "Smith, height-correlated"},
};

struct CookTorranceParams {
    glm::vec3 diffuseAlbedo;  // ρ_d of the added Lambert term (0 for metals)
    glm::vec3 ior;            // n per channel, > 0
    glm::vec3 extinction;     // κ per channel, ≥ 0 (0: dielectric)
    float roughness;          // α: the distribution's width (linear roughness, α = perceptual²)
    MicrofacetDistribution distribution;
    MicrofacetGeometry geometry;
    FresnelMode fresnel;
};

inline constexpr ParamSpec kCookTorranceTable[] = {
    colorParam("diffuse_albedo", "Diffuse albedo ρ_d", {0.0f, 0.0f, 0.0f},
        "Added Lambert term ρ_d/π (0 for metals; a dielectric's body colour)"),
    {.name = "ior", .label = "IOR n", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0.01f, .sliderMax = 4, .validMin = 0, .validMax = kUnbounded, .defaultValue = {1.5f, 1.5f, 1.5f},
     .validMinExclusive = true, .help = "Real part of the complex index per RGB channel (> 0)"},
    {.name = "extinction", .label = "Extinction κ", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0, .sliderMax = 10, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0.0f, 0.0f, 0.0f},
     .help = "Imaginary part of the index per channel: 0 for dielectrics, a few for metals"},
    {.name = "roughness", .label = "Roughness α", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 0.001f, .sliderMax = 1, .validMin = 0.001f, .validMax = 1, .defaultValue = {0.2f, 0, 0},
     .scale = ParamScale::Log, .help = "Linear microfacet roughness α (perceptual roughness squared)"},
    {.name = "distribution", .label = "Distribution D", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1, 0, 0},
     .options = kDistributionOptions, .help = "Normal distribution of the microfacets"},
    {.name = "geometry", .label = "Geometry G", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1, 0, 0},
     .options = kGeometryOptions,
     .help = "Masking-shadowing: V-cavity, or height-correlated Smith for the chosen D (Beckmann in Walter's approximation)"},
    {.name = "fresnel", .label = "Fresnel F", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1, 0, 0},
     .options = kFresnelModeOptions, .help = "Schlick's approximation or the exact equations"},
};

// The masking-shadowing term G of the chosen geometry (and, for Smith, distribution).
inline float cookTorranceGeometry(const CookTorranceParams& p, float cosHalf, float cosIn, float cosOut, float cosDifference) {
    if (p.geometry == MicrofacetGeometry::VCavity) return maskingVCavity(cosHalf, cosIn, cosOut, cosDifference);
    if (p.distribution == MicrofacetDistribution::Ggx)
        return smithHeightCorrelated(lambdaGgx(cosIn, p.roughness), lambdaGgx(cosOut, p.roughness));
    return smithHeightCorrelated(lambdaBeckmann(cosIn, p.roughness), lambdaBeckmann(cosOut, p.roughness));
}

// D·G / (4 cos θ_i cos θ_o) without Fresnel: the specular term of a perfect (F = 1) reflector.
inline float cookTorranceSpecular(const CookTorranceParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi), cosOut = frame.cosTheta(wo);
    const glm::vec3 halfway = glm::normalize(wi + wo);
    const float cosHalf = frame.cosTheta(halfway);
    const float sin2Half = sinSquared(frame.normal, halfway);
    const float distribution = p.distribution == MicrofacetDistribution::Ggx ? distributionGgx(cosHalf, sin2Half, p.roughness)
                                                                             : distributionBeckmann(cosHalf, sin2Half, p.roughness);
    return distribution * cookTorranceGeometry(p, cosHalf, cosIn, cosOut, glm::dot(wo, halfway)) / (4.0f * cosIn * cosOut);
}

// f_r = ρ_d/π + D·G·F(ω_i·h) / (4 cos θ_i cos θ_o) (Cook & Torrance 1982; Walter et al. 2007, eq. 20).
inline glm::vec3 evalCookTorrance(const CookTorranceParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    if (frame.cosTheta(wi) <= 0.0f || frame.cosTheta(wo) <= 0.0f) return glm::vec3(0.0f);
    const float cosDifference = glm::dot(wi, glm::normalize(wi + wo));
    const glm::vec3 fresnel = microfacetFresnel(p.fresnel, cosDifference, p.ior, p.extinction);
    return p.diffuseAlbedo * kInvPi + fresnel * cookTorranceSpecular(p, wi, wo, frame);
}

// Ambient reflectance k_a: the diffuse albedo ρ_d, exact for the added Lambert term. The
// microfacet lobe's albedo has no closed form (it needs a fitted table or a sampled integral,
// which the two twins could not share exactly), so it is left out, as in the lecture's k_a = k_d.
inline glm::vec3 ambientReflectanceCookTorrance(const CookTorranceParams& p, glm::vec3 /*wo*/,
                                                const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo;
}

struct CookTorrance {
    static constexpr const char *id = "cook_torrance", *label = "Cook-Torrance (microfacet)";
    static constexpr const char* citation =
        "R. L. Cook, K. E. Torrance, A Reflectance Model for Computer Graphics, ACM TOG 1(1), 1982; "
        "B. Walter et al., Microfacet Models for Refraction through Rough Surfaces, EGSR 2007; "
        "E. Heitz, Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs, JCGT 3(2), 2014";
    // Not energy-conserving as a whole: the Lambert term is added, not coupled, to the specular one.
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kCookTorranceTable;
    using Params = CookTorranceParams;
    static constexpr auto eval = evalCookTorrance;
    static constexpr auto ambientReflectance = ambientReflectanceCookTorrance;
    static constexpr const char* environmentResponse = "ρ_d·E(n)/π + prefiltered radiance × (F0·A + B − a·C), split-sum tables of the chosen D and G";
    static const char* environmentApproximation(const Params& p) {
        if (p.distribution == MicrofacetDistribution::Ggx && p.geometry == MicrofacetGeometry::Smith) return nullptr;  // the split sum
        return "split sum of the lobe's own D and G, prefiltered through its GGX stand-in with the lobe's mean "
               "cosine, along its mean direction (narrowed across the plane of incidence)";
    }
    static std::optional<TextbookForm> textbookForm(const Params& p) {
        if (p.distribution != MicrofacetDistribution::Ggx || p.geometry != MicrofacetGeometry::Smith || p.fresnel != FresnelMode::Schlick)
            return std::nullopt;
        return TextbookForm{p.diffuseAlbedo, TextbookForm::Ggx{fresnelF0(p.ior, p.extinction), p.roughness}};
    }
    static MtlForm mtlForm(const Params& p) { return mtlMicrofacet(p.diffuseAlbedo, p.ior, p.extinction, p.roughness); }
    static GltfForm gltfForm(const Params& p) {
        GltfForm form = gltfMicrofacet(p.diffuseAlbedo, p.ior, p.extinction, p.roughness);
        if (p.distribution != MicrofacetDistribution::Ggx || p.geometry != MicrofacetGeometry::Smith)
            form.lost.push_back("glTF's BRDF is GGX with Smith masking; other viewers render it so");
        if (p.fresnel != FresnelMode::Schlick) form.lost.push_back("glTF's BRDF uses Schlick's Fresnel; other viewers render it so");
        return form;
    }
    static Appearance appearance(const Params& p) {
        return {.diffuse = {p.diffuseAlbedo, {"diffuse_albedo"}}, .alpha = {glm::vec2(p.roughness), {"roughness"}},
                .ior = {p.ior, {"ior"}}, .extinction = {p.extinction, {"extinction"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        to.diffuseTo("diffuse_albedo");
        to.indexTo("ior", "extinction");
        to.alphaTo("roughness", to.isotropicAlpha(), " (α = √(α_x α_y))");
    }
};

}  // namespace glint
