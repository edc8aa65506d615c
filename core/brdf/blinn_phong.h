// Blinn-Phong: a diffuse Lambert term plus the specular lobe (N·H)^n around the halfway
// vector (Blinn 1977), in the four BRDF forms of the shading lectures.
// CPU reference; its GLSL twin is shaders/brdf/blinn_phong.glsl.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/microfacet.h"
#include "brdf/model.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

// How the lobe k_s·cos^n δ becomes a BRDF: here δ = angle between N and H; Phong's (phong.h) takes
// the same forms, δ between the mirrored light direction R and ω_o.
enum class BlinnForm {
    Lecture = 0,     // k_s·cos^n δ / cos θ'       (θ' to the light; not reciprocal)
    MaxCosine = 1,   // k_s·cos^n δ / max(cos θ, cos θ')   (reciprocal repair)
    HalfVector = 2,  // k_s·cos^n δ / |L+V|²       (reciprocal repair)
    Normalized = 3,  // k_s·(n+c)/(cπ)·cos^n δ     (energy-normalised; c = 8: Akenine-Möller et al.)
};

// The lobe cos^n δ made a BRDF by `form` (c: the normalised form's constant).
inline float lobeAsBrdf(BlinnForm form, float lobe, float exponent, float c, glm::vec3 wi, glm::vec3 wo, float cosIn,
                        float cosOut) {
    switch (form) {
        case BlinnForm::Lecture: return lobe / cosIn;
        case BlinnForm::MaxCosine: return lobe / std::max(cosIn, cosOut);
        case BlinnForm::HalfVector: return lobe / glm::dot(wi + wo, wi + wo);
        case BlinnForm::Normalized: return lobe * (exponent + c) / (c * kPi);
    }
    return 0.0f;
}

inline constexpr EnumOption kBlinnFormOptions[] = {
    {"lecture", "k_s cos^n δ / cos θ' (lecture)"},
    {"max_cosine", "k_s cos^n δ / max(cos θ, cos θ')"},
    {"half_vector", "k_s cos^n δ / |L+V|²"},
    {"normalized", "k_s (n+8)/8π cos^n δ"},
};

struct BlinnPhongParams {
    glm::vec3 diffuseAlbedo;  // ρ_d of the Lambert term
    glm::vec3 specular;       // k_s: white for dielectrics, coloured for metals
    float exponent;           // n: sharpness of the lobe
    BlinnForm form;
};

inline constexpr ParamSpec kBlinnPhongTable[] = {
    colorParam("diffuse_albedo", "Diffuse albedo ρ_d", {0.5f, 0.1f, 0.1f}, "Lambert term ρ_d/π"),
    colorParam("specular", "Specular k_s", {0.04f, 0.04f, 0.04f},
        "Specular strength; white for dielectrics, coloured for metals"),
    {.name = "exponent", .label = "Exponent n", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 10000, .validMin = 0, .validMax = kUnbounded, .defaultValue = {64, 0, 0},
     .scale = ParamScale::Log, .help = "Sharpness of the highlight, cos^n δ"},
    {.name = "form", .label = "BRDF form", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 3, .validMin = 0, .validMax = 3, .defaultValue = {3, 0, 0},
     .options = kBlinnFormOptions, .help = "How the lobe is made a BRDF"},
};

// f_r = ρ_d/π + specular form (see BlinnForm), zero below the horizon.
inline glm::vec3 evalBlinnPhong(const BlinnPhongParams& p, glm::vec3 wi, glm::vec3 wo,
                                const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi);
    const float cosOut = frame.cosTheta(wo);
    if (cosIn <= 0.0f || cosOut <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 halfway = glm::normalize(wi + wo);
    const float lobe = std::pow(std::max(frame.cosTheta(halfway), 0.0f), p.exponent);
    return p.diffuseAlbedo * kInvPi + p.specular * lobeAsBrdf(p.form, lobe, p.exponent, 8.0f, wi, wo, cosIn, cosOut);
}

// Ambient reflectance k_a: the diffuse albedo ρ_d, the exact answer for the Lambert term; the
// specular lobe's share of a uniform sky is left out, as in the lecture's k_a = k_d.
inline glm::vec3 ambientReflectanceBlinnPhong(const BlinnPhongParams& p, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo;
}

struct BlinnPhong {
    static constexpr const char *id = "blinn_phong", *label = "Blinn-Phong";
    static constexpr const char* citation = "J. F. Blinn, Models of Light Reflection for Computer Synthesized Pictures, SIGGRAPH 1977";
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kBlinnPhongTable;
    using Params = BlinnPhongParams;
    static constexpr auto eval = evalBlinnPhong;
    static constexpr auto ambientReflectance = ambientReflectanceBlinnPhong;
    static constexpr const char* environmentResponse = "ρ_d·E(n)/π + k_s·a·prefiltered radiance at α = √(2/(n+2)) (a: the form's albedo at θ_o)";
    static bool isReciprocal(const Params& p) { return p.form != BlinnForm::Lecture; }  // the lecture form is not
    // MTL's highlight is Ks·(N·H)^Ns: Blinn-Phong's lecture form.
    static MtlForm mtlForm(const Params& p) {
        MtlForm form{.illum = 2, .diffuse = p.diffuseAlbedo, .specular = p.specular, .exponent = p.exponent};
        if (p.form != BlinnForm::Lecture) form.lost.push_back("MTL's highlight is Ks·(N·H)^Ns (the lecture form); the BRDF form is not kept");
        return form;
    }
    static GltfForm gltfForm(const Params& p) { return gltfFromExponent(p.diffuseAlbedo, p.exponent); }
    static Appearance appearance(const Params& p) {
        return {.diffuse = {p.diffuseAlbedo, {"diffuse_albedo"}}, .specular = {p.specular, {"specular"}},
                .alpha = {glm::vec2(alphaFromBlinnPhongExponent(p.exponent)), {"exponent"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        to.diffuseTo("diffuse_albedo");
        to.reflectanceTo("specular");
        to.alphaTo("exponent", blinnPhongExponentFromAlpha(std::max(to.isotropicAlpha(), 0.01f)), " (n = 2/α² − 2)");
    }
};

}  // namespace glint
