// Anisotropic GGX microfacet BRDF (α_x along the surface tangent, α_y along the bitangent) with
// height-correlated Smith masking, Fresnel from a complex index, and Lambert diffuse: brushed
// metal. CPU reference; GLSL twin: shaders/brdf/ggx_anisotropic.glsl. Needs a real tangent.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/model.h"
#include "brdf/microfacet.h"
#include "math/frame.h"

namespace glint {

struct GgxAnisotropicParams {
    glm::vec3 diffuseAlbedo;  // ρ_d of the added Lambert term
    glm::vec3 ior;            // n per channel, > 0
    glm::vec3 extinction;     // κ per channel, ≥ 0
    float roughnessX;         // α_x along the tangent (direction of increasing u)
    float roughnessY;         // α_y along the bitangent
    FresnelMode fresnel;
};

inline constexpr ParamSpec kGgxAnisotropicTable[] = {
    colorParam("diffuse_albedo", "Diffuse albedo ρ_d", {0.0f, 0.0f, 0.0f}, "Added Lambert term ρ_d/π (0 for metals)"),
    {.name = "ior", .label = "IOR n", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0.01f, .sliderMax = 4, .validMin = 0, .validMax = kUnbounded,
     .defaultValue = {1.3456f, 0.96521f, 0.61722f}, .validMinExclusive = true,
     .help = "Real part of the complex index per RGB channel (> 0); default: aluminium"},
    {.name = "extinction", .label = "Extinction κ", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0, .sliderMax = 10, .validMin = 0, .validMax = kUnbounded,
     .defaultValue = {7.4746f, 6.3995f, 5.3031f}, .help = "Imaginary part of the index per channel"},
    {.name = "roughness_x", .label = "Roughness α_x", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 0.001f, .sliderMax = 1, .validMin = 0.001f, .validMax = 1, .defaultValue = {0.05f, 0, 0},
     .scale = ParamScale::Log, .help = "Linear GGX roughness along the tangent (around a sphere's pole axis)"},
    {.name = "roughness_y", .label = "Roughness α_y", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 0.001f, .sliderMax = 1, .validMin = 0.001f, .validMax = 1, .defaultValue = {0.4f, 0, 0},
     .scale = ParamScale::Log, .help = "Linear GGX roughness along the bitangent"},
    {.name = "fresnel", .label = "Fresnel F", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1, 0, 0},
     .options = kFresnelModeOptions, .help = "Schlick's approximation or the exact equations"},
};

// D·G / (4 cos θ_i cos θ_o) with anisotropic GGX D and height-correlated Smith G (Heitz 2014,
// eqs. 85, 86, 99); F = 1.
inline float ggxAnisotropicSpecular(const GgxAnisotropicParams& p, glm::vec3 wi, glm::vec3 wo,
                                    const ShadingFrame& frame) {
    const glm::vec3 in = frame.toLocal(wi), out = frame.toLocal(wo);
    const glm::vec3 halfLocal = glm::normalize(in + out);
    const float distribution = distributionGgxAnisotropic(halfLocal, p.roughnessX, p.roughnessY);
    const float geometry = smithHeightCorrelated(lambdaGgxAnisotropic(in, p.roughnessX, p.roughnessY),
                                                 lambdaGgxAnisotropic(out, p.roughnessX, p.roughnessY));
    return distribution * geometry / (4.0f * in.z * out.z);
}

// f_r = ρ_d/π + D·G·F / (4 cos θ_i cos θ_o).
inline glm::vec3 evalGgxAnisotropic(const GgxAnisotropicParams& p, glm::vec3 wi, glm::vec3 wo,
                                    const ShadingFrame& frame) {
    if (frame.cosTheta(wi) <= 0.0f || frame.cosTheta(wo) <= 0.0f) return glm::vec3(0.0f);
    const float cosDifference = glm::dot(wi, glm::normalize(wi + wo));
    const glm::vec3 fresnel = microfacetFresnel(p.fresnel, cosDifference, p.ior, p.extinction);
    return p.diffuseAlbedo * kInvPi + fresnel * ggxAnisotropicSpecular(p, wi, wo, frame);
}

// Ambient reflectance k_a: the diffuse albedo ρ_d (the microfacet lobe's share is left out; see
// ambientReflectanceCookTorrance).
inline glm::vec3 ambientReflectanceGgxAnisotropic(const GgxAnisotropicParams& p, glm::vec3 /*wo*/,
                                                  const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo;
}

struct GgxAnisotropic {
    static constexpr const char *id = "ggx_anisotropic", *label = "GGX anisotropic";
    static constexpr const char* citation =
        "B. Walter et al., EGSR 2007; E. Heitz, Understanding the Masking-Shadowing Function in "
        "Microfacet-Based BRDFs, JCGT 3(2), 2014 (anisotropic GGX, height-correlated Smith)";
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kGgxAnisotropicTable;
    using Params = GgxAnisotropicParams;
    static constexpr auto eval = evalGgxAnisotropic;
    static constexpr auto ambientReflectance = ambientReflectanceGgxAnisotropic;
    static constexpr const char* environmentResponse = "ρ_d·E(n)/π + split sum at the isotropic α = √(α_x α_y)";
    static MtlForm mtlForm(const Params& p) {
        return mtlMicrofacet(p.diffuseAlbedo, p.ior, p.extinction, std::sqrt(p.roughnessX * p.roughnessY));
    }
    static GltfForm gltfForm(const Params& p) {
        GltfForm form = gltfMicrofacet(p.diffuseAlbedo, p.ior, p.extinction, std::sqrt(p.roughnessX * p.roughnessY),
                                       {"anisotropy is not kept (α = √(α_x α_y))"});
        if (p.fresnel != FresnelMode::Schlick) form.lost.push_back("glTF's BRDF uses Schlick's Fresnel; other viewers render it so");
        return form;
    }
    static Appearance appearance(const Params& p) {
        return {.diffuse = {p.diffuseAlbedo, {"diffuse_albedo"}},
                .alpha = {glm::vec2(p.roughnessX, p.roughnessY), {"roughness_x", "roughness_y"}}, .ior = {p.ior, {"ior"}},
                .extinction = {p.extinction, {"extinction"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        to.diffuseTo("diffuse_albedo");
        to.indexTo("ior", "extinction");
        to.anisotropicAlphaTo("roughness_x", "roughness_y");
    }
};

}  // namespace glint
