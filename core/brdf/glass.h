// Glass: a smooth dielectric (index η in air) that reflects and refracts ideally, weighted by the
// exact Fresnel equations or by the classic Hearn-Baker transparency k_t, and absorbs inside by
// Beer-Lambert e^(−σ·d). Both lobes are deltas, so f_r for point lights is 0: the renderer traces
// them (render/specular_transport.h). CPU half; GLSL twin: shaders/brdf/glass.glsl.
#pragma once

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/fresnel.h"
#include "brdf/model.h"
#include "brdf/trait_forms.h"
#include "math/frame.h"

namespace glint {

enum class GlassTransparency {
    Fresnel = 0,  // exact dielectric Fresnel at each interface (physical)
    Classic = 1,  // Hearn-Baker I = (1 − k_t)·I_refl + k_t·I_trans (not physical)
};

inline constexpr EnumOption kGlassTransparencyOptions[] = {
    {"fresnel", "Fresnel (exact)"},
    {"classic", "Classic (1 − k_t) I_refl + k_t I_trans"},
};

struct GlassParams {
    float ior;                        // η of the glass relative to the air around it
    glm::vec3 absorption;             // σ [1/m] per channel
    GlassTransparency transparency;
    float transmission;               // k_t, classic only
};

inline constexpr ParamSpec kGlassTable[] = {
    {.name = "ior", .label = "Index η", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 2.5f, .validMin = 1, .validMax = 4, .defaultValue = {1.5f, 0, 0},
     .help = "Refractive index (window glass 1.5, water 1.33, diamond 2.42)"},
    {.name = "absorption", .label = "Absorption σ", .unit = "1/m", .kind = ParamKind::PerChannel,
     .sliderMin = 0, .sliderMax = 10, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0, 0, 0},
     .help = "Beer-Lambert coefficient: transmittance e^(−σ·d) over a path d inside"},
    {.name = "transparency", .label = "Transparency", .unit = "", .kind = ParamKind::Enum,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {0, 0, 0},
     .options = kGlassTransparencyOptions, .help = "Exact Fresnel, or the classic constant k_t"},
    fractionParam("transmission", "Transmission k_t", 0.9f,
        "Classic transparency only: fraction transmitted at each interface"),
};

// f_r for delta lights: 0 (both lobes are deltas; a point light's reflection has zero area).
inline glm::vec3 evalGlass(const GlassParams& /*p*/, glm::vec3 /*wi*/, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return glm::vec3(0.0f);
}

struct Glass {
    static constexpr const char *id = "glass", *label = "Glass (dielectric)";
    static constexpr const char* citation = "Snell's law and Fresnel (1823); transparency after Hearn & Baker, Computer Graphics, §14.5";
    static constexpr bool reciprocal = true, energyConserving = true;
    static constexpr const auto& params = kGlassTable;
    using Params = GlassParams;
    static constexpr auto eval = evalGlass;
    // No environment hook: only the traced lobes see the map.
    static constexpr const char* environmentNote = "refracts and reflects the map through its traced delta lobes";
    static constexpr bool tracesDeltaLobes = true;
    static constexpr const char* onlyDeltaLobes = "Glass's reflection and refraction";
    // From air into glass (η ≥ 1) there is no total internal reflection.
    static DeltaLobeWeights deltaLobeWeights(const Params& p, float cosIncident) {
        const float reflected =
            p.transparency == GlassTransparency::Fresnel ? fresnelDielectric(cosIncident, p.ior) : 1.0f - p.transmission;
        return {glm::vec3(reflected), glm::vec3(1.0f - reflected), p.ior};
    }
    static bool transmits(const Params&) { return true; }
    static constexpr const char* dispersiveIndex = "ior";  // Cauchy's n(λ) about its value at the sodium D line
    static MtlForm mtlForm(const Params& p) {
        MtlForm form{.illum = 7, .specular = glm::vec3(1.0f), .ior = p.ior};
        if (p.absorption != glm::vec3(0.0f)) form.lost.push_back("absorption σ is not kept");
        if (p.transparency != GlassTransparency::Fresnel) form.lost.push_back("classic transparency k_t is not kept");
        return form;
    }
    static GltfForm gltfForm(const Params& p) {
        GltfForm form{.kind = GltfForm::Kind::Glass, .ior = p.ior, .alpha = 0.0f, .absorption = p.absorption};
        if (p.transparency != GlassTransparency::Fresnel) form.lost.push_back("classic transparency k_t is not kept (glTF is Fresnel)");
        return form;
    }
    static Appearance appearance(const Params& p) {
        return {.alpha = {glm::vec2(0.0f), {}}, .glassIor = {p.ior, {"ior"}}, .absorption = {p.absorption, {"absorption"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        const Appearance& a = to.source();
        if (a.glassIor) {
            to.set("ior", *a.glassIor);
            to.use(a.glassIor, joinedNames(a.glassIor.from) + " → ior");
        } else if (a.ior && !to.metal()) {
            to.set("ior", (*a.ior).g);
            to.use(a.ior, joinedNames(a.ior.from) + " → ior (green channel)");
        }
        if (a.absorption) to.set("absorption", *a.absorption), to.use(a.absorption, joinedNames(a.absorption.from) + " → absorption");
    }
};

}  // namespace glint
