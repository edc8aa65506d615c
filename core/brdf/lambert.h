// Lambert: the ideal diffuse reflector, f_r = ρ/π with albedo ρ ∈ [0,1] per channel.
// CPU reference; its GLSL twin is shaders/brdf/lambert.glsl.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/model.h"
#include "brdf/trait_forms.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

struct LambertParams {
    glm::vec3 albedo;  // ρ: reflected flux / incident flux, per channel
};

inline constexpr ParamSpec kLambertTable[] = {
    colorParam("albedo", "Albedo ρ", {0.5f, 0.5f, 0.5f}, "Fraction of incident flux reflected; f_r = ρ/π"),
};

// f_r = ρ/π [1/sr], independent of direction (Lambert 1760).
inline glm::vec3 evalLambert(const LambertParams& p, glm::vec3 /*wi*/, glm::vec3 /*wo*/,
                             const ShadingFrame& /*frame*/) {
    return p.albedo * kInvPi;
}

// Ambient reflectance k_a (the k_a·I_a of Hearn-Baker): under uniform radiance L_a the reflected
// radiance is ∫ f_r L_a cos θ dω = ρ·L_a exactly: the directional albedo ρ.
inline glm::vec3 ambientReflectanceLambert(const LambertParams& p, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.albedo;
}

struct Lambert {
    static constexpr const char *id = "lambert", *label = "Lambert";
    static constexpr const char* citation = "J. H. Lambert, Photometria, 1760";
    static constexpr bool reciprocal = true, energyConserving = true;
    static constexpr const auto& params = kLambertTable;
    using Params = LambertParams;
    static constexpr auto eval = evalLambert;
    static constexpr auto ambientReflectance = ambientReflectanceLambert;
    static constexpr const char* environmentResponse = "ρ·E(n)/π (irradiance map)";
    static constexpr const char* constantForm = "ρ/π";
    static std::optional<TextbookForm> textbookForm(const Params& p) { return TextbookForm{p.albedo, std::nullopt}; }
    static MtlForm mtlForm(const Params& p) { return {.diffuse = p.albedo}; }
    static GltfForm gltfForm(const Params& p) { return gltfRoughDielectric(p.albedo); }
    static Appearance appearance(const Params& p) { return {.diffuse = {p.albedo, {"albedo"}}}; }
    static void takeAppearance(AppearanceWriter& to) { to.diffuseTo("albedo"); }
};

}  // namespace glint
