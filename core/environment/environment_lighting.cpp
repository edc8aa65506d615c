// Image-based lighting per model (see environment_lighting.h). Each lightingOf(<Model>Params) below
// is the C++ twin of environmentLighting<Model> at the end of shaders/brdf/<model>.glsl.
// Sections: lookups · roughness mapping · per-model hooks · dispatch.
#include "environment/environment_lighting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include "brdf/fresnel.h"
#include "environment/environment_map.h"
#include "environment/lobe_albedo.h"
#include "math/constants.h"

namespace glint {

// --- lookups --------------------------------------------------------------------------------

glm::vec3 environmentMapDirection(const Environment& environment, glm::vec3 d) {
    const float angle = environment.rotationDegrees * (kPi / 180.0f);
    const float cosAngle = std::cos(angle), sinAngle = std::sin(angle);
    return {cosAngle * d.x - sinAngle * d.z, d.y, sinAngle * d.x + cosAngle * d.z};
}

glm::vec3 environmentRadiance(const Environment& environment, glm::vec3 worldDirection) {
    return environment.intensity * sampleEquirect(environment.map->radiance, environmentMapDirection(environment, worldDirection));
}

glm::vec3 environmentDiffuseRadiance(const Environment& environment, glm::vec3 normal) {
    return environment.intensity * diffuseRadiance(*environment.map, environmentMapDirection(environment, normal));
}

glm::vec3 environmentSpecularRadiance(const Environment& environment, glm::vec3 worldDirection, float perceptualRoughness) {
    return environment.intensity *
           prefilteredRadiance(*environment.map, environmentMapDirection(environment, worldDirection), perceptualRoughness);
}

glm::vec3 environmentWorldDirection(const Environment& environment, glm::vec3 d) {
    const float angle = environment.rotationDegrees * (kPi / 180.0f);
    const float cosAngle = std::cos(angle), sinAngle = std::sin(angle);
    return {cosAngle * d.x + sinAngle * d.z, d.y, -sinAngle * d.x + cosAngle * d.z};
}

bool environmentUsesPeaks(const Environment& environment, float alpha) {
    return alpha >= environment.map->peakMinimumAlpha && !environment.map->peaks.empty();
}

glm::vec3 environmentPeakDirection(const Environment& environment, int k) {
    return environmentWorldDirection(environment, environment.map->peaks[k].direction);
}

glm::vec3 environmentPeakIrradiance(const Environment& environment, int k) {
    return environment.intensity * environment.map->peaks[k].irradiance;
}

float environmentPeakAlpha(const Environment& environment, int k, float alpha) {
    const float spread = kPeakWidening * environment.map->peaks[k].sinRadius;
    return std::min(1.0f, std::sqrt(alpha * alpha + spread * spread));
}

glm::vec3 environmentResidualSpecularRadiance(const Environment& environment, glm::vec3 worldDirection,
                                              float perceptualRoughness) {
    return environment.intensity * residualPrefilteredRadiance(*environment.map, environmentMapDirection(environment, worldDirection),
                                                               perceptualRoughness);
}

glm::vec3 environmentResidualMeanRadiance(const Environment& environment) {
    return environment.intensity * environment.map->residualMean;
}

// --- roughness mapping ----------------------------------------------------------------------

namespace {

float blinnAlpha(float exponent) { return std::sqrt(2.0f / (exponent + 2.0f)); }
float phongAlpha(float exponent) { return std::sqrt(2.0f / (4.0f * exponent + 2.0f)); }

glm::vec3 mirrorDirection(glm::vec3 wo, const ShadingFrame& frame) {
    return 2.0f * frame.cosTheta(wo) * frame.normal - wo;
}

// n + (R − n) t, normalised: from the normal (t = 0) to the mirror direction (t = 1).
glm::vec3 towardsMirror(glm::vec3 wo, const ShadingFrame& frame, float t) {
    return glm::normalize(frame.normal + (mirrorDirection(wo, frame) - frame.normal) * t);
}

// The prefiltered radiance at perceptual roughness r, of the map less its peaks where a lobe of GGX
// roughness α takes them; r = √α unless given.
glm::vec3 glossyRadiance(const Environment& e, glm::vec3 worldDirection, float alpha, float perceptual = -1.0f) {
    if (perceptual < 0.0f) perceptual = std::sqrt(alpha);
    return environmentUsesPeaks(e, alpha) ? environmentResidualSpecularRadiance(e, worldDirection, perceptual)
                                          : environmentSpecularRadiance(e, worldDirection, perceptual);
}

// A glossy lobe seen at θ_o is narrower across the plane of incidence than along it, by cos θ_o (a
// half vector tilted across the plane by δ turns the reflection by 2δ·cos θ_o, along it by 2δ),
// but the prefiltered levels hold round lobes (n = v = R). So the lobe along `direction` is read as
// two lookups either side of it in the plane of incidence, α·sin θ_o away, each at the width
// α·cos θ_o; faded out toward α = kObliqueFadeAlpha, where the round levels read better (measured:
// docs/environment-lighting.md), a rough lobe taking one lookup. `perceptual`: the round lobe's
// level, r = √α unless given.
constexpr float kObliqueFadeAlpha = 0.6f;

glm::vec3 obliqueGlossyRadiance(const Environment& e, glm::vec3 direction, const ShadingFrame& frame, glm::vec3 wo,
                                float alpha, float perceptual = -1.0f) {
    if (perceptual < 0.0f) perceptual = std::sqrt(alpha);
    const float cosOut = std::clamp(frame.cosTheta(wo), 0.0f, 1.0f);
    const float fade = std::clamp(1.0f - alpha / kObliqueFadeAlpha, 0.0f, 1.0f);
    if (fade == 0.0f) return glossyRadiance(e, direction, alpha, perceptual);
    const glm::vec3 across = frame.normal - direction * glm::dot(frame.normal, direction);  // in the plane of incidence
    const float acrossLength = glm::length(across);
    const glm::vec3 offset = acrossLength > 1e-6f ? across * (fade * alpha * std::sqrt(1.0f - cosOut * cosOut) / acrossLength)
                                                  : glm::vec3(0.0f);
    const float narrowed = perceptual * std::sqrt(1.0f - fade + fade * cosOut);
    return 0.5f * (glossyRadiance(e, glm::normalize(direction + offset), alpha, narrowed) +
                   glossyRadiance(e, glm::normalize(direction - offset), alpha, narrowed));
}

// Σ_k term(ω_k, α_k) E_k over every peak light k, α_k the lobe's GGX roughness α widened for the
// light's extent; zero where the lobe does not take the peaks or ω_o is below the surface.
template <class Term>
glm::vec3 sumOverPeaks(const Environment& e, float alpha, glm::vec3 wo, const ShadingFrame& frame, Term&& term) {
    glm::vec3 sum(0.0f);
    if (!environmentUsesPeaks(e, alpha) || frame.cosTheta(wo) <= 0.0f) return sum;
    for (int k = 0; k < static_cast<int>(e.map->peaks.size()); ++k)
        sum += term(environmentPeakDirection(e, k), environmentPeakAlpha(e, k, alpha)) * environmentPeakIrradiance(e, k);
    return sum;
}

// The peaks as lights: Σ_k f_r(ω_k, ω_o; α_k) cos θ_k E_k over those above the surface,
// `reflectedCos(ω_i, α_k)` giving the glossy lobe's f_r cos θ_i (Fresnel included) widened to GGX
// roughness α_k for light k's extent. The microfacet lobes take the Fresnel of f82FresnelOf, as the
// split sum does (the exact complex-index equations per light cost a quarter of a studio frame on
// llvmpipe).
template <class ReflectedCos>
glm::vec3 peakLighting(const Environment& e, float alpha, glm::vec3 wo, const ShadingFrame& frame, ReflectedCos&& reflectedCos) {
    return sumOverPeaks(e, alpha, wo, frame, [&](glm::vec3 wi, float widened) {
        return frame.cosTheta(wi) > 0.0f ? reflectedCos(wi, widened) : glm::vec3(0.0f);
    });
}

// A Blinn-Phong or Phong exponent for GGX roughness α (the inverses of blinnAlpha and phongAlpha).
float blinnExponent(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }
float phongExponent(float alpha) { return blinnExponent(alpha) / 4.0f; }

// A Blinn-Phong or Phong specular lobe's f_r cos θ_i with its exponent lowered to `exponent`,
// keeping the lobe's energy: the normalised form carries its factor (n + c)/(cπ) itself, the other
// forms take the ratio (n' + c)/(n + c).
template <class Params, class Evaluate>
glm::vec3 widenedExponentLobe(Params lobe, float exponent, float c, bool normalisedForm, Evaluate&& evaluate, glm::vec3 wi,
                              glm::vec3 wo, const ShadingFrame& frame) {
    const float original = lobe.exponent;
    lobe.diffuseAlbedo = glm::vec3(0.0f);
    lobe.exponent = std::min(original, exponent);
    const float keep = normalisedForm ? 1.0f : (lobe.exponent + c) / (original + c);
    return keep * evaluate(lobe, wi, wo, frame) * frame.cosTheta(wi);
}

// --- per-model hooks ------------------------------------------------------------------------

glm::vec3 lightingOf(const LambertParams& p, glm::vec3, const ShadingFrame& frame, const Environment& e) {
    return p.albedo * environmentDiffuseRadiance(e, frame.normal);
}

// A diffuse-like lobe's shape as a smooth map sees it: its directional albedo k_a(ω_o), the unit
// direction u of its first moment ∫ f_r cos θ_i ω_i dω_i, and its first two Legendre moments per
// unit k_a, band1 = |∫ f_r cos θ_i ω_i dω_i| / k_a (about u) and band2 = ∫ f_r cos θ_i P₂(cos θ_i) dω_i / k_a
// (about n). Lambert's: u = n, 2/3 and 1/4.
struct SmoothResponse {
    glm::vec3 albedo, direction;
    float band1, band2;
};

SmoothResponse smoothResponse(const OrenNayarParams& p, glm::vec3 wo, const ShadingFrame& frame) {
    const OrenNayarMoments m = orenNayarMoments(p.roughnessDegrees, frame.cosTheta(wo));
    const glm::vec3 moment = m.normal * frame.normal + m.tangent * (wo - frame.cosTheta(wo) * frame.normal);
    return {p.albedo * m.albedo, glm::normalize(moment), glm::length(moment) / m.albedo, m.band2 / m.albedo};
}
SmoothResponse smoothResponse(const RetroreflectiveParams& p, glm::vec3 wo, const ShadingFrame& frame) {
    const glm::vec2 bands = diffuseMomentsRetroreflective(p, frame.cosTheta(wo));
    return {ambientReflectanceRetroreflective(p, wo, frame), frame.normal, bands.x, bands.y};
}
glm::vec3 evalLobe(const OrenNayarParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& f) { return evalOrenNayar(p, wi, wo, f); }
glm::vec3 evalLobe(const RetroreflectiveParams& p, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& f) {
    return evalRetroreflective(p, wi, wo, f);
}

// The weights (x, y, z) of E(u)/π, E(−u)/π and the mean radiance L̄ whose bands 0-2 are the lobe's
// (Funk-Hecke: E(u)/π has L's band 1 × 2/3 and band 2 × 1/4): x + y + z = 1, (2/3)(x − y) = band1,
// (x + y)/4 = band2. Lambert's: (1, 0, 0).
glm::vec3 smoothWeights(const SmoothResponse& r) {
    return {0.75f * r.band1 + 2.0f * r.band2, 2.0f * r.band2 - 0.75f * r.band1, 1.0f - 4.0f * r.band2};
}

// Diffuse-like lobes that are not Lambert's: k_a × (x E(u)/π + y E(−u)/π + z L̄), L̄ of the map less
// its peaks (exact under a uniform map, and for any map in bands 0-2: Oren-Nayar's lean towards the
// viewer, limb darkening's wider lobe), plus at each peak light the lobe's own f_r cos θ_k in place of
// what those lookups gave it, Σ_k (f_r cos⁺θ_k − k_a (x cos⁺(u·ω_k) + y cos⁺(−u·ω_k))/π) E_k.
template <class Params>
    requires requires(const Params& p, glm::vec3 w, const ShadingFrame& f) { smoothResponse(p, w, f); }
glm::vec3 lightingOf(const Params& p, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const SmoothResponse r = smoothResponse(p, wo, frame);
    const glm::vec3 w = smoothWeights(r);
    return r.albedo * (w.x * environmentDiffuseRadiance(e, r.direction) + w.y * environmentDiffuseRadiance(e, -r.direction) +
                       w.z * environmentResidualMeanRadiance(e)) +
           sumOverPeaks(e, 1.0f, wo, frame, [&](glm::vec3 wi, float) {
               const float toward = glm::dot(r.direction, wi);
               return evalLobe(p, wi, wo, frame) * std::max(frame.cosTheta(wi), 0.0f) -
                      r.albedo * kInvPi * (w.x * std::max(toward, 0.0f) + w.y * std::max(-toward, 0.0f));
           });
}

glm::vec3 lightingOf(const MirrorParams& p, glm::vec3, const ShadingFrame& frame, const Environment& e) {
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal);
}

// Blinn-Phong, Phong, Ward: a GGX-prefiltered lobe of equivalent α for the map (less its peaks)
// × the lobe's own directional albedo (lobe_albedo.h), their own lobe for the peaks.
float lobeAlbedo(int table, glm::vec3 wo, const ShadingFrame& frame, float alpha) {
    return sampleLobeAlbedo(table, std::max(frame.cosTheta(wo), 0.0f), std::sqrt(alpha)).x;
}

glm::vec3 lightingOf(const BlinnPhongParams& p, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const float alpha = blinnAlpha(p.exponent);
    const float normalization = p.form == BlinnForm::Normalized ? 1.0f : (p.exponent + 8.0f) / (8.0f * kPi);
    const float weight = lobeAlbedo(kBlinnPhongAlbedo + static_cast<int>(p.form), wo, frame, alpha) / normalization;
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal) +
           p.specular * weight * glossyRadiance(e, mirrorDirection(wo, frame), alpha) +
           peakLighting(e, alpha, wo, frame, [&](glm::vec3 wi, float widened) {
               return widenedExponentLobe(p, blinnExponent(widened), 8.0f, p.form == BlinnForm::Normalized, evalBlinnPhong, wi,
                                          wo, frame);
           });
}

glm::vec3 lightingOf(const PhongParams& p, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const float alpha = phongAlpha(p.exponent);
    const float normalization = p.form == PhongForm::Normalized ? 1.0f : (p.exponent + 2.0f) / (2.0f * kPi);
    const float weight = lobeAlbedo(kPhongAlbedo + static_cast<int>(p.form), wo, frame, alpha) / normalization;
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal) +
           p.specular * weight * glossyRadiance(e, mirrorDirection(wo, frame), alpha) +
           peakLighting(e, alpha, wo, frame, [&](glm::vec3 wi, float widened) {
               return widenedExponentLobe(p, phongExponent(widened), 2.0f, p.form == PhongForm::Normalized, evalPhong, wi, wo,
                                          frame);
           });
}

// Ward's lobe and Beckmann's D are Gaussians in slopes, exp(−tan²θ_h/α²), per axis of variance
// α²/2; a light of angular radius ρ spreads the half vector's slope uniformly over a disc of radius
// ρ/2, of variance ρ²/16 per axis, and variances add: α_w² = α² + ρ²/8, half the (0.5 sin ρ)² GGX's
// lobes are widened by (environmentPeakAlpha; GGX's long tails make its best factor measured, not
// derived). On the studio HDRI at α 0.05 Ward's ratio went from 1.028 with GGX's widening to 0.997,
// Beckmann's from 1.039 to 1.002 (CPU twin).
float gaussianSlopePeakAlpha(float alpha, float widened) {
    return std::sqrt(alpha * alpha + 0.5f * (widened * widened - alpha * alpha));
}

// Ward's lobe (Beckmann-like, without GGX's long tails) takes its GGX stand-in (lobe_albedo.h): the
// prefiltered level with its mean cosine, along its mean direction n + (R − n) t.
glm::vec3 lightingOf(const WardParams& p, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const float alpha = std::sqrt(p.roughnessX * p.roughnessY);
    const glm::vec2 standIn = sampleLobeAlbedo(kWardStandIn + static_cast<int>(p.normalization),
                                               std::max(frame.cosTheta(wo), 0.0f), std::sqrt(alpha));
    const glm::vec3 direction = towardsMirror(wo, frame, standIn.y);
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal) +
           p.specular * lobeAlbedo(kWardAlbedo + static_cast<int>(p.normalization), wo, frame, alpha) *
               obliqueGlossyRadiance(e, direction, frame, wo, alpha, standIn.x) +
           peakLighting(e, alpha, wo, frame, [&](glm::vec3 wi, float widened) {
               WardParams lobe = p;
               const float wardWidened = gaussianSlopePeakAlpha(alpha, widened);
               lobe.roughnessX *= wardWidened / alpha, lobe.roughnessY *= wardWidened / alpha;
               return p.specular * (wardSpecular(lobe, wi, wo, frame) * frame.cosTheta(wi));
           });
}

// The direction the GGX lobe's reflected light mostly comes from: the mirror direction bent
// towards the normal as α grows (Lagarde & de Rousiers, "Moving Frostbite to PBR", SIGGRAPH 2014
// course, listing 22: lerp(n, R, s(√s + α)) with s = 1 − α).
glm::vec3 dominantDirection(glm::vec3 wo, const ShadingFrame& frame, float alpha) {
    const float smoothness = std::clamp(1.0f - alpha, 0.0f, 1.0f);
    const float factor = smoothness * (std::sqrt(smoothness) + alpha);
    return towardsMirror(wo, frame, factor);
}

// Split sum (Karis 2013): ∫ f_spec L cos ≈ prefiltered(dominant direction, α) · (F0·A + B − a·C) with
// the F82 form's F0 and a (f82FresnelOf) and the tables of the lobe's D × G pair (microfacetPair);
// of the map less its peaks where the lobe takes them as directions. A lobe other than GGX with
// Smith, whose shape the levels hold, takes its GGX stand-in: the level with its mean cosine along
// its mean direction, as Ward's does.
glm::vec3 splitSumSpecular(const F82Fresnel& fresnel, float alpha, MicrofacetDistribution distribution,
                           MicrofacetGeometry geometry, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const int pair = microfacetPair(distribution, geometry);
    const float perceptual = std::sqrt(alpha), cosOut = std::max(frame.cosTheta(wo), 0.0f);
    const glm::vec2 scaleBias = sampleLobeAlbedo(kMicrofacetSplitSum + pair, cosOut, perceptual);
    const glm::vec3 f82 = fresnel.coefficient == glm::vec3(0.0f)
                              ? glm::vec3(0.0f)
                              : fresnel.coefficient * sampleLobeAlbedo(kMicrofacetF82 + pair, cosOut, perceptual).x;
    glm::vec3 direction = dominantDirection(wo, frame, alpha);
    float level = perceptual;
    if (pair != kGgxSmithPair) {
        const glm::vec2 standIn = sampleLobeAlbedo(kMicrofacetStandIn + pair, cosOut, perceptual);
        direction = towardsMirror(wo, frame, standIn.y);
        level = standIn.x;
    }
    return obliqueGlossyRadiance(e, direction, frame, wo, alpha, level) * (fresnel.f0 * scaleBias.x + scaleBias.y - f82);
}

glm::vec3 lightingOf(const CookTorranceParams& p, glm::vec3 wo, const ShadingFrame& frame,
                                          const Environment& e) {
    const F82Fresnel fresnel = f82FresnelOf(p.fresnel, p.ior, p.extinction);
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal) +
           splitSumSpecular(fresnel, p.roughness, p.distribution, p.geometry, wo, frame, e) +
           peakLighting(e, p.roughness, wo, frame, [&](glm::vec3 wi, float widened) {
               CookTorranceParams lobe = p;
               lobe.roughness = p.distribution == MicrofacetDistribution::Beckmann ? gaussianSlopePeakAlpha(p.roughness, widened)
                                                                                  : widened;
               return fresnelF82(fresnel.f0, fresnel.coefficient, glm::dot(wi, glm::normalize(wi + wo))) *
                      (cookTorranceSpecular(lobe, wi, wo, frame) * frame.cosTheta(wi));
           });
}

glm::vec3 lightingOf(const GgxAnisotropicParams& p, glm::vec3 wo, const ShadingFrame& frame,
                                            const Environment& e) {
    const float alpha = std::sqrt(p.roughnessX * p.roughnessY);
    const F82Fresnel fresnel = f82FresnelOf(p.fresnel, p.ior, p.extinction);
    return p.diffuseAlbedo * environmentDiffuseRadiance(e, frame.normal) +
           splitSumSpecular(fresnel, alpha, MicrofacetDistribution::Ggx, MicrofacetGeometry::Smith, wo, frame, e) +
           peakLighting(e, alpha, wo, frame, [&](glm::vec3 wi, float widened) {
               GgxAnisotropicParams lobe = p;
               lobe.roughnessX *= widened / alpha, lobe.roughnessY *= widened / alpha;
               return fresnelF82(fresnel.f0, fresnel.coefficient, glm::dot(wi, glm::normalize(wi + wo))) *
                      (ggxAnisotropicSpecular(lobe, wi, wo, frame) * frame.cosTheta(wi));
           });
}

// Fuzz and diffuse under the irradiance map, coat and specular each prefiltered at its own
// roughness along its dominant direction, weighted by the albedos of openPbrResponse (which sum
// to the directional albedo: exact under a uniform map); where a lobe takes the map's peaks, it
// sees the map less them, and each peak light through its own lobe, under the layers above it (as
// evalOpenpbr). Transmission: render/openpbr_transport.h.
glm::vec3 lightingOf(const OpenPbrParams& p, glm::vec3 wo, const ShadingFrame& frame, const Environment& e) {
    const OpenPbrView v = openPbrView(p, frame.cosTheta(wo));
    const OpenPbrResponse r = openPbrResponse(p, v);
    const float coatAlpha = v.coatRoughness * v.coatRoughness, specularAlpha = v.specularRoughness * v.specularRoughness;
    const ShadingFrame coatFrame = frame.coatFrame();
    const glm::vec3 out = openPbrLocal(p, frame, wo), coatOut = openPbrLocal(p, coatFrame, wo);
    const glm::vec3 specularPeaks = peakLighting(e, specularAlpha, wo, frame, [&](glm::vec3 wi, float widened) {
        const glm::vec3 in = openPbrLocal(p, frame, wi);
        const float lobe = ggxLobe(in, out, v.specularAlphas * (widened / specularAlpha));
        return v.underFuzz * v.underCoat * coatAbsorption(p, in.z, out.z) *
               openPbrBaseSpecular(p, v, glm::dot(in, glm::normalize(in + out)), lobe) * in.z;
    });
    const glm::vec3 coatPeaks = p.coatWeight > 0.0f ? peakLighting(e, coatAlpha, wo, coatFrame, [&](glm::vec3 wi, float widened) {
        const glm::vec3 coatIn = openPbrLocal(p, coatFrame, wi);
        return glm::vec3(v.underFuzz * openPbrCoat(p, v, coatIn, coatOut, v.coatAlphas * (widened / coatAlpha)) * coatIn.z);
    }) : glm::vec3(0.0f);
    return r.diffuse * environmentDiffuseRadiance(e, frame.normal) +
           r.coat * obliqueGlossyRadiance(e, dominantDirection(wo, coatFrame, coatAlpha), coatFrame, wo, coatAlpha, v.coatRoughness) +
           coatPeaks +
           r.specular * obliqueGlossyRadiance(e, dominantDirection(wo, frame, specularAlpha), frame, wo, specularAlpha,
                                              v.specularRoughness) +
           specularPeaks;
}

// The GGX α each glossy lobe is prefiltered with: split sum for microfacet lobes, an equivalent
// roughness along R for the others (see environment_lighting.h).
float splitSumAlpha(const CookTorranceParams& p) { return p.roughness; }
float splitSumAlpha(const GgxAnisotropicParams& p) { return std::sqrt(p.roughnessX * p.roughnessY); }
float splitSumAlpha(const OpenPbrParams& p) {
    const float roughness = openPbrEquivalentRoughness(openPbrAlphas(p.specularRoughness, p.specularAnisotropy));
    return roughness * roughness;
}
float lobeAlpha(const BlinnPhongParams& p) { return blinnAlpha(p.exponent); }
float lobeAlpha(const PhongParams& p) { return phongAlpha(p.exponent); }
float lobeAlpha(const WardParams& p) { return std::sqrt(p.roughnessX * p.roughnessY); }

template <class M>
concept SplitSum = requires(const typename M::Params& p) { splitSumAlpha(p); };
template <class M>
concept EquivalentLobe = requires(const typename M::Params& p) { lobeAlpha(p); };
template <class M>
concept DiffuseLike = requires(const typename M::Params& p, glm::vec3 w, const ShadingFrame& f) { smoothResponse(p, w, f); };

}  // namespace

float environmentRoughness(BrdfModel model, std::span<const float> values) {
    return dispatch(model, [&]<class M>(M) {
        if constexpr (SplitSum<M>) return splitSumAlpha(unpack<M>(values.data()));
        else if constexpr (EquivalentLobe<M>) return lobeAlpha(unpack<M>(values.data()));
        else return 0.0f;
    });
}

std::string environmentApproximation(BrdfModel model, std::span<const float> values, const Environment& environment) {
    static constexpr const char* kSplitSum = "GGX split sum along the dominant direction (narrowed across the plane of incidence)";
    const char* lobe = dispatch(model, [&]<class M>(M) -> const char* {
        if constexpr (!HasEnvironment<M>) return nullptr;
        if constexpr (HasEnvironmentApproximation<M>)
            if (const char* own = M::environmentApproximation(unpack<M>(values.data()))) return own;
        if constexpr (SplitSum<M>) return kSplitSum;
        else if constexpr (EquivalentLobe<M>) return "GGX-prefiltered lobe of equivalent roughness along R × its directional albedo";
        else return "";
    });
    if (!lobe) return "none (traced)";
    const size_t lights = environment.enabled() ? environment.map->peaks.size() : 0;
    if (!*lobe) {
        const bool diffuseLike = dispatch(model, []<class M>(M) { return DiffuseLike<M>; });
        if (!diffuseLike) return "irradiance map";
        const std::string smooth = "irradiance map at ±(the lobe's mean direction) and the map's mean, matching the lobe's bands 0-2";
        if (lights == 0) return smooth;
        return smooth + " + the lobe's own shape at " + std::to_string(lights) +
               " peak light" + (lights == 1 ? "" : "s");
    }
    const float alpha = environmentRoughness(model, values);
    if (lights == 0) return std::string("irradiance map + ") + lobe + " (the map has no peaks)";
    char threshold[96];
    std::snprintf(threshold, sizeof threshold, "α %.3g %s the map's peak-light α %.3g", alpha,
                  environmentUsesPeaks(environment, alpha) ? "≥" : "<", environment.map->peakMinimumAlpha);
    if (!environmentUsesPeaks(environment, alpha))
        return std::string("irradiance map + ") + lobe + " of the whole map (" + threshold + ")";
    return std::string("irradiance map + ") + lobe + " of the map less its peaks + " + std::to_string(lights) +
           " peak light" + (lights == 1 ? "" : "s") + " through the model's own lobe, widened for their extent (" + threshold + ")";
}

// --- dispatch -------------------------------------------------------------------------------

glm::vec3 environmentLighting(BrdfModel model, std::span<const float> values, glm::vec3 wo, const ShadingFrame& frame,
                              const Environment& e) {
    if (!e.enabled()) return glm::vec3(0.0f);
    return dispatch(model, [&]<class M>(M) {
        constexpr bool twin = requires(const typename M::Params& p, glm::vec3 w, const ShadingFrame& f, const Environment& env) {
            lightingOf(p, w, f, env);
        };
        static_assert(twin == HasEnvironment<M>, "a model with an environment hook needs its lightingOf here");
        if constexpr (twin) return lightingOf(unpack<M>(values.data()), wo, frame, e);
        else return glm::vec3(0.0f);  // delta lobes only: traced (specular_transport.h)
    });
}

}  // namespace glint
