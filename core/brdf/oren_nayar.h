// Oren-Nayar rough diffuse reflection, the qualitative model of Oren & Nayar, "Generalization of
// Lambert's Reflectance Model", SIGGRAPH 1994 (eq. 30): Lambert times A + B·max(0, cos Δφ)·sin α·tan β.
// CPU reference; its GLSL twin is shaders/brdf/oren_nayar.glsl. No interreflection term.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/model.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

struct OrenNayarParams {
    glm::vec3 albedo;       // ρ per channel
    float roughnessDegrees;  // σ: standard deviation of the facet slope angle [degrees]
};

inline constexpr ParamSpec kOrenNayarTable[] = {
    colorParam("albedo", "Albedo ρ", {0.8f, 0.8f, 0.8f}, "Facet albedo; σ = 0 gives Lambert ρ/π"),
    {.name = "roughness", .label = "Roughness σ", .unit = "deg", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 90, .validMin = 0, .validMax = 90, .defaultValue = {30, 0, 0},
     .help = "Standard deviation of the facet slope angle, in degrees"},
};

// f_r = ρ/π (A + B max(0, cos(φ_i − φ_o)) sin α tan β), α = max(θ_i, θ_o), β = min(θ_i, θ_o),
// A = 1 − 0.5 σ²/(σ² + 0.33), B = 0.45 σ²/(σ² + 0.09), σ in radians. Uses
// sin θ_i sin θ_o cos Δφ = ω_i·ω_o − cos θ_i cos θ_o and sin α tan β = sin θ_i sin θ_o / max(cos θ_i, cos θ_o).
inline glm::vec3 evalOrenNayar(const OrenNayarParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi), cosOut = frame.cosTheta(wo);
    if (cosIn <= 0.0f || cosOut <= 0.0f) return glm::vec3(0.0f);
    const float sigma = p.roughnessDegrees * (kPi / 180.0f);
    const float sigma2 = sigma * sigma;
    const float a = 1.0f - 0.5f * sigma2 / (sigma2 + 0.33f);
    const float b = 0.45f * sigma2 / (sigma2 + 0.09f);
    const float azimuthal = std::max(0.0f, glm::dot(wi, wo) - cosIn * cosOut);
    return p.albedo * kInvPi * (a + b * azimuthal / std::max(cosIn, cosOut));
}

// The qualitative model's directional albedo ∫ f_r cos θ_i dω_i / ρ at cos θ_o, in closed form:
// A + (2B/π)[sin θ_o (θ_o/2 − sin 2θ_o/4) + tan θ_o (1 − sin³θ_o)/3] (the B term integrated over
// θ_i < θ_o, where α = θ_o, and θ_i > θ_o, where β = θ_o; ∫ max(0, cos Δφ) dφ = 2).
inline float directionalAlbedoOrenNayar(float roughnessDegrees, float cosOut) {
    const float sigma = roughnessDegrees * (kPi / 180.0f);
    const float sigma2 = sigma * sigma;
    const float a = 1.0f - 0.5f * sigma2 / (sigma2 + 0.33f);
    const float b = 0.45f * sigma2 / (sigma2 + 0.09f);
    const float cosine = std::clamp(cosOut, 1e-4f, 1.0f), sine = std::sqrt(1.0f - cosine * cosine);
    const float theta = std::acos(cosine);
    const float below = sine * (0.5f * theta - 0.5f * sine * cosine);
    const float above = sine / cosine * (1.0f - sine * sine * sine) / 3.0f;
    return a + 2.0f * b * kInvPi * (below + above);
}

// Ambient reflectance k_a: the facet albedo ρ, the exact directional albedo at σ = 0 (Lambert).
// For σ > 0 the qualitative model's own albedo differs from ρ by a few percent, either way
// (brdf_test); ρ is the lecture's k_a = k_d.
inline glm::vec3 ambientReflectanceOrenNayar(const OrenNayarParams& p, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.albedo;
}

struct OrenNayar {
    static constexpr const char *id = "oren_nayar", *label = "Oren-Nayar";
    static constexpr const char* citation = "M. Oren, S. K. Nayar, Generalization of Lambert's Reflectance Model, SIGGRAPH 1994 (qualitative model, eq. 30)";
    // Qualitative model: its albedo reaches about 1.015 ρ at grazing view for σ ≈ 12° (brdf_test).
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kOrenNayarTable;
    using Params = OrenNayarParams;
    static constexpr auto eval = evalOrenNayar;
    static constexpr auto ambientReflectance = ambientReflectanceOrenNayar;
    static constexpr const char* environmentResponse = "ρ·a(θ_o)·E(n)/π (irradiance map × the directional albedo) + the lobe's departure from Lambert at the map's peak lights";
    static MtlForm mtlForm(const Params& p) {
        return {.diffuse = p.albedo, .lost = {"roughness σ is not kept (written as Lambert)"}};
    }
    static GltfForm gltfForm(const Params& p) { return gltfRoughDielectric(p.albedo); }
    static Appearance appearance(const Params& p) { return {.diffuse = {p.albedo, {"albedo"}}}; }
    static void takeAppearance(AppearanceWriter& to) { to.diffuseTo("albedo"); }
};

}  // namespace glint
