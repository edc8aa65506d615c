// Limb-darkened diffuse reflection (Minnaert 1941, or Lommel-Seeliger) for the moon, plus a
// retroreflective lobe around the light direction for safety vests and road signs.
// CPU reference; its GLSL twin is shaders/brdf/retroreflective.glsl.
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

enum class LimbDarkening {
    Minnaert = 0,        // ρ (k+1)/(2π) (cos θ_i cos θ_o)^(k−1)
    LommelSeeliger = 1,  // ρ / (4π (cos θ_i + cos θ_o)), ρ the single-scattering albedo
};

inline constexpr EnumOption kLimbDarkeningOptions[] = {
    {"minnaert", "Minnaert (cos θ_i cos θ_o)^(k−1)"},
    {"lommel_seeliger", "Lommel-Seeliger 1/(cos θ_i + cos θ_o)"},
};

struct RetroreflectiveParams {
    glm::vec3 albedo;           // ρ: Minnaert albedo at normal incidence, or single-scattering albedo
    LimbDarkening limbDarkening;
    float minnaertExponent;     // k: 1 is Lambert, < 1 flattens the disc (the full moon), > 1 darkens the limb
    glm::vec3 retroreflection;  // k_r: weight of the lobe around ω_i
    float retroExponent;        // m: sharpness of that lobe
};

inline constexpr ParamSpec kRetroreflectiveTable[] = {
    colorParam("albedo", "Albedo ρ", {0.12f, 0.12f, 0.12f},
        "Minnaert: directional albedo at normal incidence; Lommel-Seeliger: single-scattering albedo"),
    {.name = "limb_darkening", .label = "Limb darkening", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1, 0, 0},
     .options = kLimbDarkeningOptions, .help = "The diffuse law"},
    {.name = "minnaert_k", .label = "Minnaert exponent k", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 0.1f, .sliderMax = 2, .validMin = 0.1f, .validMax = 2, .defaultValue = {0.7f, 0, 0},
     .help = "Minnaert only: 1 = Lambert, < 1 flatter (moon-like), > 1 darker limb"},
    colorParam("retroreflection", "Retroreflection k_r", {0.0f, 0.0f, 0.0f},
        "Weight of the lobe (m+1)/(2π) cos^m γ, γ the angle between ω_o and ω_i"),
    {.name = "retro_exponent", .label = "Retro exponent m", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 1000, .validMin = 0, .validMax = kUnbounded, .defaultValue = {50, 0, 0},
     .scale = ParamScale::Log, .help = "Sharpness of the retroreflective lobe"},
};

// f_r = diffuse law + k_r (m+1)/(2π) max(0, ω_i·ω_o)^m. Both terms are symmetric in ω_i, ω_o.
// Minnaert's BRDF (cos θ_i cos θ_o)^(k−1) (Minnaert 1941, "The reciprocity principle in lunar
// photometry") is normalised so that its albedo at normal incidence is ρ; Lommel-Seeliger
// (Hapke 1981, single scattering) reflects at most ρ/2.
inline glm::vec3 evalRetroreflective(const RetroreflectiveParams& p, glm::vec3 wi, glm::vec3 wo,
                                     const ShadingFrame& frame) {
    const float cosIn = frame.cosTheta(wi), cosOut = frame.cosTheta(wo);
    if (cosIn <= 0.0f || cosOut <= 0.0f) return glm::vec3(0.0f);
    float diffuse;
    if (p.limbDarkening == LimbDarkening::Minnaert)
        diffuse = (p.minnaertExponent + 1.0f) / (2.0f * kPi) * std::pow(cosIn * cosOut, p.minnaertExponent - 1.0f);
    else diffuse = 1.0f / (4.0f * kPi * (cosIn + cosOut));
    const float retro = (p.retroExponent + 1.0f) / (2.0f * kPi) * std::pow(std::max(glm::dot(wi, wo), 0.0f), p.retroExponent);
    return p.albedo * diffuse + p.retroreflection * retro;
}

// Ambient reflectance k_a: the diffuse law's exact directional albedo ∫ f_r cos θ_i dω_i at
// μ_o = cos θ_o. Minnaert: (k+1)/(2π) μ_o^(k−1) · 2π ∫₀¹ μ_i^k dμ_i = μ_o^(k−1), so k_a = ρ μ_o^(k−1).
// Lommel-Seeliger: 1/(4π) · 2π ∫₀¹ μ_i/(μ_i + μ_o) dμ_i = ½ (1 − μ_o ln(1 + 1/μ_o)).
// The retroreflective lobe's share is left out (it has no closed form over the hemisphere).
inline glm::vec3 ambientReflectanceRetroreflective(const RetroreflectiveParams& p, glm::vec3 wo,
                                                   const ShadingFrame& frame) {
    const float cosOut = frame.cosTheta(wo);
    if (cosOut <= 0.0f) return glm::vec3(0.0f);
    if (p.limbDarkening == LimbDarkening::Minnaert) return p.albedo * std::pow(cosOut, p.minnaertExponent - 1.0f);
    return p.albedo * (0.5f * (1.0f - cosOut * std::log(1.0f + 1.0f / cosOut)));
}

// The diffuse law's first two Legendre moments per unit k_a (its lobe in ω_i is symmetric about
// n): band1 = ∫ f_r cos θ_i cos θ_i dω_i / k_a, band2 = ∫ f_r cos θ_i P₂(cos θ_i) dω_i / k_a. Minnaert
// (μ_i^k): (k+1)/(k+2) and k/(k+3); Lommel-Seeliger (μ_i/(μ_i + μ_o)): I₁/I₀ and (3 I₂/I₀ − 1)/2,
// I_j = ∫₀¹ μ^(j+1)/(μ + μ_o) dμ = 1/(j+1) − μ_o I_(j−1), I₀ = 1 − μ_o ln(1 + 1/μ_o). Lambert: 2/3, 1/4.
inline glm::vec2 diffuseMomentsRetroreflective(const RetroreflectiveParams& p, float cosOut) {
    if (p.limbDarkening == LimbDarkening::Minnaert) {
        const float k = p.minnaertExponent;
        return {(k + 1.0f) / (k + 2.0f), k / (k + 3.0f)};
    }
    const float mu = std::max(cosOut, 1e-4f);
    const float i0 = 1.0f - mu * std::log(1.0f + 1.0f / mu), i1 = 0.5f - mu * i0, i2 = 1.0f / 3.0f - mu * i1;
    return {i1 / i0, 1.5f * i2 / i0 - 0.5f};
}

struct Retroreflective {
    static constexpr const char *id = "retroreflective", *label = "Moon / retroreflective";
    static constexpr const char* citation =
        "M. Minnaert, The Reciprocity Principle in Lunar Photometry, ApJ 93, 1941; "
        "B. Hapke, Bidirectional Reflectance Spectroscopy 1, JGR 86, 1981 (Lommel-Seeliger)";
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kRetroreflectiveTable;
    using Params = RetroreflectiveParams;
    static constexpr auto eval = evalRetroreflective;
    static constexpr auto ambientReflectance = ambientReflectanceRetroreflective;
    static constexpr const char* environmentResponse = "k_a(ω_o)·(x E(n) + y E(−n))/π + z L̄ (the law's bands 0-2); both lobes at the peak lights";
    static MtlForm mtlForm(const Params& p) {
        return {.diffuse = p.albedo, .lost = {"the limb darkening and retroreflective lobe are not kept (written as Lambert)"}};
    }
    static GltfForm gltfForm(const Params& p) { return gltfRoughDielectric(p.albedo); }
    static Appearance appearance(const Params& p) { return {.diffuse = {p.albedo, {"albedo"}}}; }
    static void takeAppearance(AppearanceWriter& to) { to.diffuseTo("albedo"); }
};

}  // namespace glint
