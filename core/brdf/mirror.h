// Mirror: an ideal specular reflector weighted by the exact conductor Fresnel F(θ; n + iκ) per
// channel (κ = 0 gives a dielectric mirror), plus an optional small Lambert part ρ_d/π. The delta
// lobe has no f_r for point lights: the renderer traces it (render/specular_transport.h).
// CPU reference; its GLSL twin is shaders/brdf/mirror.glsl.
#pragma once

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/fresnel.h"
#include "brdf/model.h"
#include "brdf/trait_forms.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

struct MirrorParams {
    glm::vec3 ior;            // n: real part of the complex index, per channel
    glm::vec3 extinction;     // κ: extinction coefficient, per channel
    glm::vec3 diffuseAlbedo;  // ρ_d of the optional Lambert part
};

// Default: aluminium (RGB fit of measured n, κ; pbrt-v4 and Mitsuba ship the same data).
inline constexpr ParamSpec kMirrorTable[] = {
    {.name = "ior", .label = "Index n", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0.05f, .sliderMax = 4, .validMin = 0.001f, .validMax = kUnbounded, .defaultValue = {1.66f, 0.88f, 0.52f},
     .help = "Real part of the complex refractive index n + iκ (per channel)"},
    {.name = "extinction", .label = "Extinction κ", .unit = "", .kind = ParamKind::PerChannel,
     .sliderMin = 0, .sliderMax = 10, .validMin = 0, .validMax = kUnbounded, .defaultValue = {9.22f, 6.27f, 4.84f},
     .help = "Imaginary part κ of n + iκ; 0 for a dielectric"},
    colorParam("diffuse_albedo", "Diffuse albedo ρ_d", {0, 0, 0},
        "Optional small Lambert part, lit by the lights and the ambient light; added to the mirror "
        "lobe, not balanced against it (F + ρ_d may exceed 1)"),
};

// f_r for delta lights: only the Lambert part ρ_d/π (the mirror lobe is a delta).
inline glm::vec3 evalMirror(const MirrorParams& p, glm::vec3 /*wi*/, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo * kInvPi;
}

// Ambient reflectance k_a: the Lambert part's albedo ρ_d (the mirror lobe sees the background).
inline glm::vec3 ambientReflectanceMirror(const MirrorParams& p, glm::vec3 /*wo*/, const ShadingFrame& /*frame*/) {
    return p.diffuseAlbedo;
}

struct Mirror {
    static constexpr const char *id = "mirror", *label = "Mirror (conductor Fresnel)";
    static constexpr const char* citation = "A. Fresnel (1823); complex index after Born & Wolf, Principles of Optics, §14.2";
    static constexpr bool reciprocal = true, energyConserving = false;
    static constexpr const auto& params = kMirrorTable;
    using Params = MirrorParams;
    static constexpr auto eval = evalMirror;
    static constexpr auto ambientReflectance = ambientReflectanceMirror;
    static constexpr const char* environmentResponse = "ρ_d·E(n)/π; the mirror lobe is traced into the map";
    static constexpr bool tracesDeltaLobes = true;
    static constexpr const char* onlyDeltaLobes = "A mirror's reflection";
    static DeltaLobeWeights deltaLobeWeights(const Params& p, float cosIncident) {
        return {.reflected = fresnelComplexIndex(cosIncident, p.ior, p.extinction)};
    }
    static MtlForm mtlForm(const Params& p) {
        return {.illum = 3, .diffuse = p.diffuseAlbedo, .specular = fresnelF0(p.ior, p.extinction),
                .lost = {"the complex index n + iκ is written as its normal-incidence reflectance Ks"}};
    }
    static GltfForm gltfForm(const Params& p) { return gltfMetal(p.diffuseAlbedo, p.ior, p.extinction, 0.0f); }
    static Appearance appearance(const Params& p) {
        return {.diffuse = {p.diffuseAlbedo, {"diffuse_albedo"}}, .alpha = {glm::vec2(0.0f), {}}, .ior = {p.ior, {"ior"}},
                .extinction = {p.extinction, {"extinction"}}};
    }
    static void takeAppearance(AppearanceWriter& to) {
        to.diffuseTo("diffuse_albedo");
        to.indexTo("ior", "extinction");
    }
};

}  // namespace glint
