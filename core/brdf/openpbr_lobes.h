// The lobes of the OpenPBR model, each alone: anisotropic GGX (OpenPBR's roughness/anisotropy
// mapping), the F82-tint metal Fresnel, the energy-preserving Oren-Nayar diffuse (EON), the
// Charlie sheen of the fuzz and the thin-film Fresnel. Layering and weights: openpbr.h.
// GLSL twin: shaders/brdf/openpbr_lobes.glsl. Local frames have z along the normal.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "brdf/microfacet.h"
#include "math/constants.h"

namespace glint {

// Numerical floors: a GGX α below this is a mirror that point lights cannot show (the
// environment hook shows it), and fuzz fibres thinner than this make the sheen a delta.
inline constexpr float kOpenPbrMinAlpha = 1e-3f;
inline constexpr float kOpenPbrMinFuzzRoughness = 0.07f;

// OpenPBR's mapping of (perceptual roughness r, anisotropy a) to (α_t, α_b): α_t =
// min(1, r²·√(2/(1 + (1 − a)²))), α_b = (1 − a)·α_t (OpenPBR Surface 1.1, §specular anisotropy).
inline glm::vec2 openPbrAlphas(float roughness, float anisotropy) {
    const float inverse = 1.0f - anisotropy;
    const float alphaT = std::min(1.0f, roughness * roughness * std::sqrt(2.0f / (1.0f + inverse * inverse)));
    return {std::max(alphaT, kOpenPbrMinAlpha), std::max(inverse * alphaT, kOpenPbrMinAlpha)};
}

// The isotropic perceptual roughness the albedo tables and prefiltered levels use: √√(α_t α_b).
inline float openPbrEquivalentRoughness(glm::vec2 alphas) { return std::sqrt(std::sqrt(alphas.x * alphas.y)); }

// D·G2 / (4 cos θ_i cos θ_o) of anisotropic GGX with height-correlated Smith (Heitz 2014,
// eqs. 85, 86, 99), F = 1; wi, wo local in the anisotropy's frame.
inline float ggxLobe(glm::vec3 wi, glm::vec3 wo, glm::vec2 alphas) {
    const glm::vec3 halfway = glm::normalize(wi + wo);
    return distributionGgxAnisotropic(halfway, alphas.x, alphas.y) *
           smithHeightCorrelated(lambdaGgxAnisotropic(wi, alphas.x, alphas.y),
                                 lambdaGgxAnisotropic(wo, alphas.x, alphas.y)) /
           (4.0f * wi.z * wo.z);
}

// Generalised Schlick F0 + (F90 − F0)(1 − c)^5.
inline glm::vec3 schlickF90(glm::vec3 f0, glm::vec3 f90, float cosine) {
    const float m = std::clamp(1.0f - cosine, 0.0f, 1.0f);
    return f0 + (f90 - f0) * (m * m * m * m * m);
}

// F0 of a dielectric interface of relative index η: ((η − 1)/(η + 1))².
inline float dielectricF0(float eta) { return ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f)); }

// EON: energy-preserving Fujii Oren-Nayar (Portsmouth et al., "EON: A practical energy-preserving
// rough diffuse BRDF", JCGT 14(1), 2025), with its polynomial E_FON; ρ albedo, r ∈ [0, 1].
inline constexpr float kFonConstant1 = 0.5f - 2.0f / (3.0f * kPi);
inline constexpr float kFonConstant2 = 2.0f / 3.0f - 28.0f / (15.0f * kPi);
inline float fujiiAlbedo(float cosine, float roughness) {
    const float m = 1.0f - cosine;
    const float gOverPi = m * (0.0571085289f + m * (0.491881867f + m * (-0.332181442f + m * 0.0714429953f)));
    return (1.0f + roughness * gOverPi) / (1.0f + kFonConstant1 * roughness);
}
inline float fujiiAverageAlbedo(float roughness) {
    return (1.0f + kFonConstant2 * roughness) / (1.0f + kFonConstant1 * roughness);
}
inline glm::vec3 eonMultipleAlbedo(glm::vec3 albedo, float roughness) {
    const float average = fujiiAverageAlbedo(roughness);
    return albedo * albedo * average / (1.0f - albedo * (1.0f - average));
}
inline glm::vec3 eonLobe(glm::vec3 albedo, float roughness, glm::vec3 wi, glm::vec3 wo) {
    const float s = glm::dot(wi, wo) - wi.z * wo.z;
    const float sOverT = s > 0.0f ? s / std::max(wi.z, wo.z) : s;
    const float single = (1.0f + roughness * sOverT) / (1.0f + kFonConstant1 * roughness);
    const float multiple = std::max(1e-7f, 1.0f - fujiiAlbedo(wo.z, roughness)) *
                           std::max(1e-7f, 1.0f - fujiiAlbedo(wi.z, roughness)) /
                           std::max(1e-7f, 1.0f - fujiiAverageAlbedo(roughness));
    return (albedo * single + eonMultipleAlbedo(albedo, roughness) * multiple) * kInvPi;
}
// Its directional albedo: ρ·E_FON(θ_o) + ρ_ms·(1 − E_FON(θ_o)).
inline glm::vec3 eonAlbedo(glm::vec3 albedo, float roughness, float cosOut) {
    const float single = fujiiAlbedo(cosOut, roughness);
    return albedo * single + eonMultipleAlbedo(albedo, roughness) * (1.0f - single);
}

// Charlie sheen D (Estevez & Kulla, "Production Friendly Microfacet Sheen BRDF", 2017) with
// Neubelt & Pettineo's visibility 1/(4(cos θ_i + cos θ_o − cos θ_i cos θ_o)) (2013), α = r².
inline float sheenLobe(glm::vec3 wi, glm::vec3 wo, float roughness) {
    const float r = std::max(roughness, kOpenPbrMinFuzzRoughness);
    const float inverseAlpha = 1.0f / (r * r);
    const glm::vec3 halfway = glm::normalize(wi + wo);
    const float sin2Half = std::max(0.0f, 1.0f - halfway.z * halfway.z);
    const float distribution = (2.0f + inverseAlpha) * std::pow(sin2Half, 0.5f * inverseAlpha) / (2.0f * kPi);
    return distribution / (4.0f * (wi.z + wo.z - wi.z * wo.z));
}

// Thin-film interference over a base of reflectance F0 (Belcour & Barla, "A Practical Extension
// to Microfacet Theory for the Modeling of Varying Iridescence", SIGGRAPH 2017), in the Schlick
// and Gaussian-sensitivity simplification of the glTF KHR_materials_iridescence sample renderer:
// the Airy sum's first two orders, each integrated against the CIE sensitivities in closed form.
inline glm::vec3 thinFilmSensitivity(float opticalPathNm, glm::vec3 shift) {
    const float phase = 2.0f * kPi * opticalPathNm * 1e-9f;
    const glm::vec3 value(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    const glm::vec3 position(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    const glm::vec3 variance(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    glm::vec3 xyz = value * glm::sqrt(2.0f * kPi * variance) * glm::cos(position * phase + shift) *
                    glm::exp(-phase * phase * variance);
    xyz.x += 9.7470e-14f * std::sqrt(2.0f * kPi * 4.5282e+09f) * std::cos(2.2399e+06f * phase + shift.x) *
             std::exp(-4.5282e+09f * phase * phase);
    xyz /= 1.0685e-7f;
    return {3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
            -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
            0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z};
}

// Reflectance of a film (index filmIor, thickness in nm) between a medium of index outsideIor
// and a base of reflectance baseF0, at cos θ in the outside medium; clamped to [0, 1].
inline glm::vec3 thinFilmFresnel(float outsideIor, float filmIor, float thicknessNm, float cosine, glm::vec3 baseF0) {
    // A film thinner than 30 nm fades into the outside medium (no interference colours left).
    const float t = std::clamp(thicknessNm / 30.0f, 0.0f, 1.0f);
    const float ior = outsideIor + (filmIor - outsideIor) * t * t * (3.0f - 2.0f * t);
    const float sin2Film = (outsideIor / ior) * (outsideIor / ior) * (1.0f - cosine * cosine);
    if (sin2Film >= 1.0f) return glm::vec3(1.0f);
    const float cosFilm = std::sqrt(1.0f - sin2Film);
    const float r0 = ((ior - outsideIor) / (ior + outsideIor)) * ((ior - outsideIor) / (ior + outsideIor));
    const float r12 = schlickF90(glm::vec3(r0), glm::vec3(1.0f), cosine).x;
    const float t121 = 1.0f - r12;
    const float phi12 = ior < outsideIor ? kPi : 0.0f;
    const float phi21 = kPi - phi12;
    const glm::vec3 sqrtF0 = glm::sqrt(glm::clamp(baseF0, glm::vec3(0.0f), glm::vec3(0.9999f)));
    const glm::vec3 baseIor = (1.0f + sqrtF0) / (1.0f - sqrtF0);
    const glm::vec3 baseR0 = ((baseIor - ior) / (baseIor + ior)) * ((baseIor - ior) / (baseIor + ior));
    const glm::vec3 r23 = schlickF90(baseR0, glm::vec3(1.0f), cosFilm);
    const glm::vec3 phi23(baseIor.x < ior ? kPi : 0.0f, baseIor.y < ior ? kPi : 0.0f, baseIor.z < ior ? kPi : 0.0f);
    const float opticalPath = 2.0f * ior * thicknessNm * cosFilm;
    const glm::vec3 phi = glm::vec3(phi21) + phi23;
    const glm::vec3 r123 = glm::clamp(r12 * r23, glm::vec3(1e-5f), glm::vec3(0.9999f));
    const glm::vec3 rs = t121 * t121 * r23 / (1.0f - r123);
    glm::vec3 reflectance = r12 + rs;
    glm::vec3 cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= glm::sqrt(r123);
        reflectance += cm * 2.0f * thinFilmSensitivity(static_cast<float>(m) * opticalPath, static_cast<float>(m) * phi);
    }
    return glm::clamp(reflectance, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace glint
