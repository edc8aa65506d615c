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

// A = 1 − 0.5 σ²/(σ² + 0.33) and B = 0.45 σ²/(σ² + 0.09) for σ in degrees.
inline glm::vec2 orenNayarCoefficients(float roughnessDegrees) {
    const float sigma = roughnessDegrees * (kPi / 180.0f);
    const float sigma2 = sigma * sigma;
    return {1.0f - 0.5f * sigma2 / (sigma2 + 0.33f), 0.45f * sigma2 / (sigma2 + 0.09f)};
}

// f_r = ρ/π (A + B max(0, cos(φ_i − φ_o)) sin α tan β), α = max(θ_i, θ_o), β = min(θ_i, θ_o).
// Uses sin θ_i sin θ_o cos Δφ = ω_i·ω_o − cos θ_i cos θ_o and sin α tan β = sin θ_i sin θ_o / max(cos θ_i, cos θ_o).
inline glm::vec3 evalOrenNayar(const OrenNayarParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi), cosOut = frame.cosTheta(wo);
    if (cosIn <= 0.0f || cosOut <= 0.0f) return glm::vec3(0.0f);
    const glm::vec2 ab = orenNayarCoefficients(p.roughnessDegrees);
    const float azimuthal = std::max(0.0f, glm::dot(wi, wo) - cosIn * cosOut);
    return p.albedo * kInvPi * (ab.x + ab.y * azimuthal / std::max(cosIn, cosOut));
}

// The qualitative model's moments per unit ρ at cos θ_o, in closed form: the B term integrated over
// θ_i < θ_o, where α = θ_o, and θ_i > θ_o, where β = θ_o (∫ max(0, cos Δφ) dφ = 2, ∫ max(0, cos Δφ) cos Δφ dφ = π/2).
struct OrenNayarMoments {
    // ∫ f_r cos θ_i dω_i: A + (2B/π)[sin θ_o (θ_o/2 − sin 2θ_o/4) + tan θ_o (1 − sin³θ_o)/3]
    float albedo;
    // ∫ f_r cos θ_i ω_i dω_i = normal·n + tangent·(ω_o − cos θ_o n): the B term leans it towards the viewer.
    // normal: 2A/3 + (2B/π)[sin⁴θ_o/3 + tan θ_o ((π/2 − θ_o)/8 + sin 4θ_o/32)]; tangent: (B/2)(2/3 − c/2 + c³/12)
    float normal, tangent;
    // ∫ f_r cos θ_i P₂(cos θ_i) dω_i: A/4 + (2B/π)[sin θ_o (sin 2θ_o/8 − θ_o/16 − 3 sin 4θ_o/64)
    // + tan θ_o (1/30 − sin³θ_o/3 + 3 sin⁵θ_o/10)]
    float band2;
};
inline OrenNayarMoments orenNayarMoments(float roughnessDegrees, float cosOut) {
    const glm::vec2 ab = orenNayarCoefficients(roughnessDegrees);
    const float c = std::clamp(cosOut, 1e-4f, 1.0f), s = std::sqrt(1.0f - c * c), t = s / c;
    const float theta = std::acos(c), sin2 = 2.0f * s * c, sin4 = 2.0f * sin2 * (c * c - s * s), s3 = s * s * s;
    const float b = 2.0f * ab.y * kInvPi;
    return {ab.x + b * (s * (0.5f * theta - 0.25f * sin2) + t * (1.0f - s3) / 3.0f),
            2.0f * ab.x / 3.0f + b * (s3 * s / 3.0f + t * ((0.5f * kPi - theta) / 8.0f + sin4 / 32.0f)),
            0.5f * ab.y * (2.0f / 3.0f - 0.5f * c + c * c * c / 12.0f),
            0.25f * ab.x + b * (s * (sin2 / 8.0f - theta / 16.0f - 3.0f * sin4 / 64.0f) + t * (1.0f / 30.0f - s3 / 3.0f + 0.3f * s3 * s * s))};
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
    static constexpr const char* environmentResponse = "ρ·a(θ_o)·(x E(u) + y E(−u))/π + z L̄: the lobe's bands 0-2, u leaning to the viewer; its own shape at peak lights";
    static MtlForm mtlForm(const Params& p) {
        return {.diffuse = p.albedo, .lost = {"roughness σ is not kept (written as Lambert)"}};
    }
    static GltfForm gltfForm(const Params& p) { return gltfRoughDielectric(p.albedo); }
    static Appearance appearance(const Params& p) { return {.diffuse = {p.albedo, {"albedo"}}}; }
    static void takeAppearance(AppearanceWriter& to) { to.diffuseTo("albedo"); }
};

}  // namespace glint
