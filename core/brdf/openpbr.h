// OpenPBR Surface (ASWF, 2024): fuzz over coat over a base that mixes a metal (F82 tint) and a
// dielectric (GGX specular over EON diffuse or transmission), with thin-film iridescence and
// emission. Layers combine by albedo scaling: each layer passes on 1 − its directional albedo
// at ω_o (OpenPBR §layering), so the stack conserves energy but is not reciprocal. The rough
// lobes get Turquin's multiple-scattering compensation 1 + F0·(1 − E)/E ("Practical multiple
// scattering compensation for microfacet models", 2019) from the tables of openpbr_albedo.h.
// CPU reference; GLSL twin: shaders/brdf/openpbr.glsl. Lobes: openpbr_lobes.h; parameters:
// openpbr_params.h. Transmission and emission are traced by render/openpbr_transport.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "brdf/appearance.h"
#include "brdf/export_forms.h"
#include "brdf/fresnel.h"
#include "brdf/openpbr_albedo.h"
#include "brdf/openpbr_lobes.h"
#include "brdf/openpbr_params.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {

// What the lobes need that depends on the parameters and ω_o only (not on ω_i).
struct OpenPbrView {
    float cosOut;
    glm::vec2 specularAlphas, coatAlphas;  // (α_t, α_b)
    float specularRoughness, coatRoughness;  // isotropic equivalents (perceptual) for tables and maps
    float dielectricF0, dielectricF90, coatF0;
    glm::vec3 metalF0, metalF82;             // F0 and the F82 coefficient a
    glm::vec3 filmDielectric, filmMetal;     // thin-film reflectance at θ_o (used when filmWeight > 0)
    float filmWeight;
    glm::vec3 dielectricCompensation, metalCompensation;
    float coatCompensation;
    glm::vec3 dielectricAlbedo, metalAlbedo;  // directional albedo of each specular lobe (compensated, untinted)
    float coatAlbedo, sheenAlbedo;
    float sheenScale;         // 1/max(1, E_sheen): see openPbrView
    float underFuzz;          // 1 − w_f·E_sheen(θ_o)
    glm::vec3 underCoat;      // (1 − w_c·E_coat(θ_o)) × darkening
};

// The coat's index as seen by the layers under it, mixed by coat presence.
inline float openPbrOutsideIor(const OpenPbrParams& p) { return 1.0f + (p.coatIor - 1.0f) * p.coatWeight; }

// cos θ inside a layer of index η for cos θ outside (Snell).
inline float refractedCosine(float cosine, float eta) {
    return std::sqrt(std::max(0.0f, 1.0f - (1.0f - cosine * cosine) / (eta * eta)));
}

// Coat absorption along the two refracted paths, as a transmittance per channel: coat_color is
// the transmittance of a path through the coat at normal incidence and back (OpenPBR §coat).
inline glm::vec3 coatAbsorption(const OpenPbrParams& p, float cosIn, float cosOut) {
    if (p.coatWeight <= 0.0f) return glm::vec3(1.0f);
    const float path = 0.5f / std::max(refractedCosine(cosIn, p.coatIor), 1e-4f) +
                       0.5f / std::max(refractedCosine(cosOut, p.coatIor), 1e-4f);
    const glm::vec3 transmittance = glm::pow(glm::max(p.coatColor, glm::vec3(0.0f)), glm::vec3(path));
    return glm::mix(glm::vec3(1.0f), transmittance, p.coatWeight);
}

inline OpenPbrView openPbrView(const OpenPbrParams& p, float cosOut) {
    OpenPbrView v;
    v.cosOut = std::clamp(cosOut, 0.0f, 1.0f);
    // The coat roughens what lies below (OpenPBR §coat: r⁴ + 2 r_c⁴).
    const float coated = std::pow(std::min(1.0f, 2.0f * std::pow(p.coatRoughness, 4.0f) + std::pow(p.specularRoughness, 4.0f)), 0.25f);
    const float specularRoughness = p.specularRoughness + (coated - p.specularRoughness) * p.coatWeight;
    v.specularAlphas = openPbrAlphas(specularRoughness, p.specularAnisotropy);
    v.coatAlphas = openPbrAlphas(p.coatRoughness, p.coatAnisotropy);
    v.specularRoughness = openPbrEquivalentRoughness(v.specularAlphas);
    v.coatRoughness = openPbrEquivalentRoughness(v.coatAlphas);
    const float outsideIor = openPbrOutsideIor(p);
    // specular_weight scales F0 (capped at 1) and, below 1, the grazing reflectance too.
    v.dielectricF0 = std::min(1.0f, p.specularWeight * dielectricF0(p.specularIor / outsideIor));
    v.dielectricF90 = std::min(1.0f, p.specularWeight);
    v.coatF0 = dielectricF0(p.coatIor);
    const float metalScale = std::min(1.0f, p.specularWeight);
    v.metalF0 = metalScale * p.baseWeight * p.baseColor;
    v.metalF82 = f82Coefficient(v.metalF0, p.specularColor);
    v.filmWeight = p.thinFilmWeight;
    v.filmDielectric = v.filmMetal = glm::vec3(0.0f);
    if (v.filmWeight > 0.0f) {
        const float thicknessNm = 1000.0f * p.thinFilmThickness;
        v.filmDielectric = thinFilmFresnel(outsideIor, p.thinFilmIor, thicknessNm, v.cosOut,
                                           glm::vec3(v.dielectricF0));
        v.filmMetal = thinFilmFresnel(outsideIor, p.thinFilmIor, thicknessNm, v.cosOut, v.metalF0);
    }
    // Specular lobes: E = A + B is the albedo of the F = 1 lobe.
    const glm::vec3 terms = ggxAlbedoTerms(v.cosOut, v.specularRoughness);
    const float energy = std::max(terms.x + terms.y, 1e-4f);
    const glm::vec3 dielectricReference = glm::mix(glm::vec3(v.dielectricF0), v.filmDielectric, v.filmWeight);
    const glm::vec3 metalReference = glm::mix(v.metalF0, v.filmMetal, v.filmWeight);
    v.dielectricCompensation = 1.0f + dielectricReference * (1.0f - energy) / energy;
    v.metalCompensation = 1.0f + metalReference * (1.0f - energy) / energy;
    v.dielectricAlbedo = v.dielectricCompensation *
                         glm::mix(glm::vec3(v.dielectricF0 * terms.x + v.dielectricF90 * terms.y),
                                  v.filmDielectric * energy, v.filmWeight);
    v.metalAlbedo = v.metalCompensation *
                    glm::mix(v.metalF0 * terms.x + terms.y - v.metalF82 * terms.z, v.filmMetal * energy, v.filmWeight);
    // Coat.
    const glm::vec3 coatTerms = ggxAlbedoTerms(v.cosOut, v.coatRoughness);
    const float coatEnergy = std::max(coatTerms.x + coatTerms.y, 1e-4f);
    v.coatCompensation = 1.0f + v.coatF0 * (1.0f - coatEnergy) / coatEnergy;
    v.coatAlbedo = v.coatCompensation * (v.coatF0 * coatTerms.x + coatTerms.y);
    // Darkening: light under the coat reflects back down from its underside with K = 1 −
    // (1 − F_avg)/η² and meets the base (albedo ≈ base colour) again: Δ = (1 − K)/(1 − E_b·K).
    const float coatAverageFresnel = v.coatF0 + (1.0f - v.coatF0) / 21.0f;
    const float internal = 1.0f - (1.0f - coatAverageFresnel) / (p.coatIor * p.coatIor);
    const glm::vec3 baseAlbedo = p.baseWeight * p.baseColor;
    const glm::vec3 darkening = (1.0f - internal) / (1.0f - baseAlbedo * internal);
    v.underCoat = (1.0f - p.coatWeight * v.coatAlbedo) *
                  glm::mix(glm::vec3(1.0f), darkening, p.coatWeight * p.coatDarkening);
    // With Neubelt's visibility thin fibres reflect more than they receive at grazing views (the
    // table reaches 3.7 at r = 0.07, cos θ_o = 1/64): the lobe is scaled down to an albedo of 1 there.
    const float sheen = sheenAlbedo(v.cosOut, std::max(p.fuzzRoughness, kOpenPbrMinFuzzRoughness));
    v.sheenScale = 1.0f / std::max(1.0f, sheen);
    v.sheenAlbedo = sheen * v.sheenScale;
    v.underFuzz = 1.0f - p.fuzzWeight * v.sheenAlbedo;
    return v;
}

// A direction in the anisotropy's local frame: the shading frame turned by the tangent rotation.
inline glm::vec3 openPbrLocal(const OpenPbrParams& p, const ShadingFrame& frame, glm::vec3 world) {
    const glm::vec3 local = frame.toLocal(world);
    const float angle = p.tangentRotation * (kPi / 180.0f);
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * local.x + s * local.y, -s * local.x + c * local.y, local.z};
}

// The base's specular reflection [1/sr] for the GGX lobe value `lobe` (D·G/(4 cos θ_i cos θ_o)):
// the tinted dielectric's and the metal's, mixed by metalness, before the layers above.
inline glm::vec3 openPbrBaseSpecular(const OpenPbrParams& p, const OpenPbrView& v, float cosDifference, float lobe) {
    const glm::vec3 metalFresnel = glm::mix(fresnelF82(v.metalF0, v.metalF82, cosDifference), v.filmMetal, v.filmWeight);
    const glm::vec3 dielectricFresnel =
        glm::mix(schlickF90(glm::vec3(v.dielectricF0), glm::vec3(v.dielectricF90), cosDifference), v.filmDielectric,
                 v.filmWeight);
    return glm::mix(p.specularColor * v.dielectricCompensation * dielectricFresnel, v.metalCompensation * metalFresnel,
                    p.baseMetalness) *
           lobe;
}

// The coat's reflection [1/sr] for ω_i, ω_o in the coat's frame (a coat normal map tilts it:
// frame.coatFrame()), its lobe at GGX roughness `alphas`.
inline float openPbrCoat(const OpenPbrParams& p, const OpenPbrView& v, glm::vec3 coatIn, glm::vec3 coatOut, glm::vec2 alphas) {
    if (coatIn.z <= 0.0f || coatOut.z <= 0.0f) return 0.0f;
    const float cosDifference = glm::dot(coatIn, glm::normalize(coatIn + coatOut));
    const float coatFresnel = schlickF90(glm::vec3(v.coatF0), glm::vec3(1.0f), cosDifference).x;
    return p.coatWeight * v.coatCompensation * coatFresnel * ggxLobe(coatIn, coatOut, alphas);
}

// f_r [1/sr] for light from wi seen from wo.
inline glm::vec3 evalOpenpbr(const OpenPbrParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const glm::vec3 in = openPbrLocal(p, frame, wi), out = openPbrLocal(p, frame, wo);
    if (in.z <= 0.0f || out.z <= 0.0f) return glm::vec3(0.0f);
    const OpenPbrView v = openPbrView(p, out.z);
    const glm::vec3 diffuse = (1.0f - v.dielectricAlbedo) * (1.0f - p.transmissionWeight) *
                              eonLobe(p.baseWeight * p.baseColor, p.baseDiffuseRoughness, in, out);
    const float cosDifference = glm::dot(in, glm::normalize(in + out));
    const glm::vec3 base =
        openPbrBaseSpecular(p, v, cosDifference, ggxLobe(in, out, v.specularAlphas)) + (1.0f - p.baseMetalness) * diffuse;
    const ShadingFrame coatFrame = frame.coatFrame();
    const float coat = openPbrCoat(p, v, openPbrLocal(p, coatFrame, wi), openPbrLocal(p, coatFrame, wo), v.coatAlphas);
    const glm::vec3 fuzz = p.fuzzWeight * p.fuzzColor * v.sheenScale * sheenLobe(in, out, p.fuzzRoughness);
    return fuzz + v.underFuzz * (coat + v.underCoat * coatAbsorption(p, in.z, out.z) * base);
}

// How much of each kind of incident light the stack returns towards ω_o: weights of the diffuse
// irradiance E(n)/π, of the coat's and the base's prefiltered specular radiance, and of the
// light transmitted from behind. Under a uniform radiance L the first three sum to the
// directional albedo.
struct OpenPbrResponse {
    glm::vec3 diffuse, coat, specular, transmission;
};

inline OpenPbrResponse openPbrResponse(const OpenPbrParams& p, const OpenPbrView& v) {
    const glm::vec3 underCoat = v.underFuzz * v.underCoat * coatAbsorption(p, v.cosOut, v.cosOut);
    const glm::vec3 dielectricBelow = (1.0f - p.baseMetalness) * (1.0f - v.dielectricAlbedo);
    OpenPbrResponse r;
    r.diffuse = p.fuzzWeight * p.fuzzColor * v.sheenAlbedo +
                underCoat * dielectricBelow * (1.0f - p.transmissionWeight) *
                    eonAlbedo(p.baseWeight * p.baseColor, p.baseDiffuseRoughness, v.cosOut);
    r.coat = glm::vec3(v.underFuzz * p.coatWeight * v.coatAlbedo);
    r.specular = underCoat * glm::mix(p.specularColor * v.dielectricAlbedo, v.metalAlbedo, p.baseMetalness);
    r.transmission = underCoat * dielectricBelow * p.transmissionWeight;
    return r;
}

// Ambient reflectance k_a: the directional albedo, the reflected part of the response to a
// uniform radiance (the transmitted part belongs to the transport hook).
inline glm::vec3 ambientReflectanceOpenpbr(const OpenPbrParams& p, glm::vec3 wo, const ShadingFrame& frame) {
    const OpenPbrResponse r = openPbrResponse(p, openPbrView(p, frame.cosTheta(wo)));
    return r.diffuse + r.coat + r.specular;
}

// Emitted radiance [W/(sr·m²)]: luminance [nit] / 683 lm/W per channel of emission_color, seen
// through the coat (one way: the square root of the round trip) and the fuzz above it.
inline glm::vec3 emissionOpenPbr(const OpenPbrParams& p, const OpenPbrView& v) {
    const float throughCoat = 1.0f - p.coatWeight * v.coatAlbedo;
    return p.emissionLuminance / kLumensPerWatt * p.emissionColor * v.underFuzz * throughCoat *
           glm::sqrt(coatAbsorption(p, v.cosOut, v.cosOut));
}

// The model (brdf/model.h). Its transport hook traces transmission and adds emission
// (render/openpbr_transport.h); its GLSL twin reads the albedo tables generated by glslTables.
struct OpenPbr {
    static constexpr const char *id = "openpbr", *label = "OpenPBR Surface";
    static constexpr const char* citation = "OpenPBR Surface 1.1, Academy Software Foundation, 2024 (layering by albedo scaling); E. Turquin, Practical multiple scattering compensation for microfacet models, 2019; J. Portsmouth et al., EON, JCGT 14(1), 2025; A. Estevez, C. Kulla, Charlie sheen, 2017; L. Belcour, P. Barla, thin-film iridescence, SIGGRAPH 2017; N. Hoffman, F82 tint, 2023";
    // Albedo-scaled layering conserves energy but is not reciprocal (OpenPBR §layering).
    static constexpr bool reciprocal = false, energyConserving = true;
    static constexpr const auto& params = kOpenPbrTable;
    using Params = OpenPbrParams;
    static constexpr auto eval = evalOpenpbr;
    static constexpr auto ambientReflectance = ambientReflectanceOpenpbr;
    static constexpr const char* environmentResponse =
        "fuzz and diffuse: E(n)/π × their albedo; coat and specular: prefiltered radiance along the dominant "
        "direction × their compensated albedo; transmission: prefiltered radiance through the surface";
    static constexpr bool tracesDeltaLobes = true;
    static bool transmits(const Params& p) { return p.transmissionWeight > 0.0f; }
    static constexpr bool coatNormalMap = true;
    static std::string glslTables() { return openPbrAlbedoGlsl(); }
    // The base only: Kd = weight·colour·(1 − metalness); Ks = the specular F0 mixed with the metal's colour.
    static MtlForm mtlForm(const Params& p) {
        const float dielectricF0 = std::min(fresnelF0(glm::vec3(p.specularIor), glm::vec3(0.0f)).x * p.specularWeight, 1.0f);
        const float alpha = std::max(p.specularRoughness, 0.03f);
        return {.illum = 2, .diffuse = p.baseWeight * p.baseColor * (1.0f - p.baseMetalness),
                .specular = glm::mix(glm::vec3(dielectricF0) * p.specularColor, p.baseColor, p.baseMetalness),
                .exponent = 2.0f / (alpha * alpha * alpha * alpha) - 2.0f,  // α = r², Walter et al. 2007, eq. 33
                .lost = {"OpenPBR is written as its base with a Blinn-Phong highlight (Ks = F0, Ns = 2/α² − 2); coat, fuzz, "
                         "transmission, thin film and emission are not kept"}};
    }
    static constexpr bool gltfOpenPbr = true;
    static Appearance appearance(const Params& p) {
        // OpenPBR's anisotropic mapping: α_t = r²·√(2/(1 + (1 − a)²)), α_b = (1 − a)·α_t.
        const float r = p.specularRoughness, anisotropy = p.specularAnisotropy;
        const float alphaT = std::min(1.0f, r * r * std::sqrt(2.0f / (1.0f + (1.0f - anisotropy) * (1.0f - anisotropy))));
        Appearance a{.alpha = {glm::vec2(alphaT, (1.0f - anisotropy) * alphaT),
                               anisotropy > 0.0f ? std::vector<std::string>{"specular_roughness", "specular_roughness_anisotropy"}
                                                 : std::vector<std::string>{"specular_roughness"}}};
        const glm::vec3 base = p.baseColor * p.baseWeight;
        if (p.transmissionWeight >= 0.5f) {
            a.glassIor = {p.specularIor, {"specular_ior"}};
            const glm::vec3 tint = glm::max(p.transmissionColor, glm::vec3(1e-4f));
            if (p.transmissionDepth > 0.0f) a.absorption = {-glm::log(tint) / p.transmissionDepth, {"transmission_color", "transmission_depth"}};
            a.alpha.from.clear();  // Glint's glass is smooth
        } else if (p.baseMetalness >= 0.5f) {
            a.specular = {base, {"base_color", "base_metalness"}};
            const glm::vec3 f0 = glm::clamp(base, glm::vec3(0.0f), glm::vec3(0.999f));
            a.ior = {glm::vec3(1.0f), {"base_metalness"}};
            a.extinction = {glm::vec3(conductorExtinctionFromF0(f0.r), conductorExtinctionFromF0(f0.g), conductorExtinctionFromF0(f0.b)),
                            {"base_color", "base_metalness"}};
        } else {
            a.diffuse = {base, p.baseWeight != 1.0f ? std::vector<std::string>{"base_color", "base_weight"}
                                                    : std::vector<std::string>{"base_color"}};
            a.ior = {glm::vec3(p.specularIor), {"specular_ior"}};
            a.extinction = {glm::vec3(0.0f), {}};
        }
        return a;
    }
    static void takeAppearance(AppearanceWriter& to) {
        const Appearance& a = to.source();
        if (a.glassIor) {
            to.set("transmission_weight", 1.0f);
            to.set("specular_ior", *a.glassIor);
            to.use(a.glassIor, joinedNames(a.glassIor.from) + " → specular_ior, transmission_weight 1");
            if (a.absorption) {
                // Beer-Lambert over 1 m: transmission_color = e^(−σ·1 m) at transmission_depth 1 m.
                to.set("transmission_depth", 1.0f);
                to.set("transmission_color", glm::exp(-*a.absorption));
                to.use(a.absorption, joinedNames(a.absorption.from) + " → transmission_color at transmission_depth 1 m");
            }
        } else if (to.metal() || (a.specular && !a.diffuse && !a.ior)) {
            to.set("base_metalness", 1.0f);
            to.reflectanceTo("base_color");
        } else {
            to.diffuseTo("base_color");
            if (a.ior) {
                to.set("specular_ior", std::max((*a.ior).g, 1.0f));
                to.use(a.ior, joinedNames(a.ior.from) + " → specular_ior (green channel)");
            } else if (a.specular) {
                to.set("specular_ior", dielectricIorFromF0((*a.specular).g));
                to.use(a.specular, joinedNames(a.specular.from) + " → specular_ior (same F0)");
            }
        }
        if (a.alpha && !a.glassIor) {
            // Inverting OpenPBR's mapping: a = 1 − α_b/α_t, r = √(α_t / √(2/(1 + (1 − a)²))).
            const float alphaT = std::max((*a.alpha).x, (*a.alpha).y), alphaB = std::min((*a.alpha).x, (*a.alpha).y);
            const float anisotropy = alphaT > 0.0f ? 1.0f - alphaB / alphaT : 0.0f;
            const float stretch = std::sqrt(2.0f / (1.0f + (1.0f - anisotropy) * (1.0f - anisotropy)));
            if (anisotropy > 1e-3f) to.set("specular_roughness_anisotropy", anisotropy);
            to.alphaTo("specular_roughness", std::sqrt(alphaT / stretch), anisotropy > 1e-3f ? " (r = √α, with anisotropy)" : " (r = √α)");
        }
    }
};

}  // namespace glint
