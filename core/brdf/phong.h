// Phong: a diffuse Lambert term plus the specular lobe (R·V)^n around the mirror direction of the
// light (Phong 1975), in the four BRDF forms of the shading lectures (as Blinn-Phong).
// CPU reference; its GLSL twin is shaders/brdf/phong.glsl.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/blinn_phong.h"
#include "brdf/export_forms.h"
#include "brdf/microfacet.h"
#include "brdf/model.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

// How the lobe k_s·cos^n δ (δ = angle between the mirrored light direction R and ω_o) becomes a
// BRDF: Blinn-Phong's four forms, the normalised one k_s·(n+2)/(2π)·cos^n δ (Lewis 1994).
using PhongForm = BlinnForm;

inline constexpr EnumOption kPhongFormOptions[] = {
    {"lecture", "k_s cos^n δ / cos θ' (lecture)"},
    {"max_cosine", "k_s cos^n δ / max(cos θ, cos θ')"},
    {"half_vector", "k_s cos^n δ / |L+V|²"},
    {"normalized", "k_s (n+2)/2π cos^n δ"},
};

struct PhongParams {
    glm::vec3 diffuseAlbedo;  // ρ_d of the Lambert term
    glm::vec3 specular;       // k_s
    float exponent;           // n: sharpness of the lobe
    PhongForm form;
};

inline constexpr ParamSpec kPhongTable[] = {
    colorParam("diffuse_albedo", "Diffuse albedo ρ_d", {0.1f, 0.3f, 0.5f}, "Lambert term ρ_d/π"),
    colorParam("specular", "Specular k_s", {0.04f, 0.04f, 0.04f},
        "Specular strength; white for dielectrics, coloured for metals"),
    {.name = "exponent", .label = "Exponent n", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 10000, .validMin = 0, .validMax = kUnbounded, .defaultValue = {32, 0, 0},
     .scale = ParamScale::Log, .help = "Sharpness of the highlight, cos^n δ"},
    {.name = "form", .label = "BRDF form", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 3, .validMin = 0, .validMax = 3, .defaultValue = {3, 0, 0},
     .options = kPhongFormOptions, .help = "How the lobe is made a BRDF"},
};

// f_r = ρ_d/π + specular form (see PhongForm), R = 2(N·ω_i)N − ω_i; zero below the horizon.
// R·ω_o = 2(N·ω_i)(N·ω_o) − ω_i·ω_o is symmetric in ω_i and ω_o, so the lobe itself is reciprocal.
inline glm::vec3 evalPhong(const PhongParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi);
    const float cosOut = frame.cosTheta(wo);
    if (cosIn <= 0.0f || cosOut <= 0.0f) return glm::vec3(0.0f);
    const float cosMirror = 2.0f * cosIn * cosOut - glm::dot(wi, wo);
    const float lobe = std::pow(std::max(cosMirror, 0.0f), p.exponent);
    return p.diffuseAlbedo * kInvPi + p.specular * lobeAsBrdf(p.form, lobe, p.exponent, 2.0f, wi, wo, cosIn, cosOut);
}

// Ambient reflectance k_a: the diffuse albedo ρ_d, exact for the Lambert term; the specular
// lobe's share of a uniform sky is left out, as in the lecture's k_a = k_d.
inline glm::vec3 ambientReflectancePhong(const PhongParams& p, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo;
}

struct Phong {
    static constexpr const char *id = "phong", *label = "Phong";
    static constexpr const char* citation =
        "B. T. Phong, Illumination for Computer Generated Pictures, CACM 18(6), 1975; "
        "normalisation: R. R. Lewis, Making Shaders More Physically Plausible, 1994";
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kPhongTable;
    using Params = PhongParams;
    static constexpr auto eval = evalPhong;
    static constexpr auto ambientReflectance = ambientReflectancePhong;
    static constexpr const char* environmentResponse = "ρ_d·E(n)/π + k_s·a(θ_o)·prefiltered radiance at α = √(2/(4n+2)) (a: the form's directional albedo, tabulated)";
    static bool isReciprocal(const Params& p) { return p.form != PhongForm::Lecture; }  // the lecture form is not
    static MtlForm mtlForm(const Params& p) {
        MtlForm form{.illum = 2, .diffuse = p.diffuseAlbedo, .specular = p.specular, .exponent = p.exponent};
        if (p.form != PhongForm::Lecture) form.lost.push_back("MTL's highlight is Ks·(N·H)^Ns (the lecture form); the BRDF form is not kept");
        form.lost.push_back("MTL has no Phong (mirror-direction) lobe; written as illum 2, which is Blinn's half-vector lobe");
        return form;
    }
    static GltfForm gltfForm(const Params& p) { return gltfFromExponent(p.diffuseAlbedo, p.exponent); }
    // Phong's lobe about the mirror direction is about as wide as Blinn-Phong's with 4× the exponent.
    static Appearance appearance(const Params& p) {
        return {.diffuse = {p.diffuseAlbedo, {"diffuse_albedo"}}, .specular = {p.specular, {"specular"}},
                .alpha = {glm::vec2(alphaFromBlinnPhongExponent(4.0f * p.exponent)), {"exponent"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        to.diffuseTo("diffuse_albedo");
        to.reflectanceTo("specular");
        to.alphaTo("exponent", blinnPhongExponentFromAlpha(std::max(to.isotropicAlpha(), 0.01f)) / 4.0f, " (n = (2/α² − 2)/4)");
    }
};

}  // namespace glint
