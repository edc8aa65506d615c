// Cook-Torrance microfacet BRDF D·G·F / (4 cos θ_i cos θ_o) plus Lambert diffuse. GLSL twin of
// core/brdf/cook_torrance.h; MaterialParams is generated from its parameter table (fields:
// diffuse_albedo, ior, extinction, roughness, distribution, geometry, fresnel).
#include "brdf/microfacet.glsl"
#include "brdf/microfacet_fresnel.glsl"

float cookTorranceSpecular(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi), cosOut = cosTheta(frame, wo);
    vec3 halfway = normalize(wi + wo);
    float cosHalf = cosTheta(frame, halfway);
    float cosDifference = dot(wo, halfway);
    float sin2Half = sinSquared(frame.normal, halfway);
    bool ggx = p.distribution == DISTRIBUTION_GGX;
    float distribution = ggx ? distributionGgx(cosHalf, sin2Half, p.roughness)
                             : distributionBeckmann(cosHalf, sin2Half, p.roughness);
    float geometry;
    if (p.geometry == GEOMETRY_V_CAVITY) geometry = maskingVCavity(cosHalf, cosIn, cosOut, cosDifference);
    else if (ggx) geometry = smithHeightCorrelated(lambdaGgx(cosIn, p.roughness), lambdaGgx(cosOut, p.roughness));
    else geometry = smithHeightCorrelated(lambdaBeckmann(cosIn, p.roughness), lambdaBeckmann(cosOut, p.roughness));
    return distribution * geometry / (4.0 * cosIn * cosOut);
}

vec3 evalCookTorrance(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    if (cosTheta(frame, wi) <= 0.0 || cosTheta(frame, wo) <= 0.0) return vec3(0.0);
    float cosDifference = dot(wi, normalize(wi + wo));
    vec3 fresnel = microfacetFresnel(p.fresnel, cosDifference, p.ior, p.extinction);
    return p.diffuse_albedo * INV_PI + fresnel * cookTorranceSpecular(p, wi, wo, frame);
}

// Ambient reflectance k_a = ρ_d (see cook_torrance.h).
vec3 ambientReflectanceCookTorrance(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo;
}

#ifdef GLINT_HAS_ENVIRONMENT
// The specular lobe's f_r cos θ_i widened to roughness `widened`, with the Fresnel of f82FresnelOf.
vec3 cookTorrancePeakLobe(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame, float widened, F82Fresnel f82) {
    vec3 fresnel = fresnelF82(f82.f0, f82.coefficient, dot(wi, normalize(wi + wo)));
    p.roughness = p.distribution == DISTRIBUTION_BECKMANN ? environmentGaussianSlopePeakAlpha(p.roughness, widened) : widened;
    return fresnel * (cookTorranceSpecular(p, wi, wo, frame) * cosTheta(frame, wi));
}

// Environment hook: twin of environmentLightingCookTorrance in core/environment/environment_lighting.cpp.
vec3 environmentLightingCookTorrance(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float alpha = p.roughness;
    F82Fresnel f82 = f82FresnelOf(p.fresnel, p.ior, p.extinction);
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, alpha, wo, frame, cookTorrancePeakLobe(p, wi, wo, frame, widened, f82))
    int pair = 2 * p.distribution + p.geometry;  // microfacetPair
    return p.diffuse_albedo * environmentDiffuseRadiance(frame.normal) +
           environmentSplitSumSpecular(f82.f0, f82.coefficient, alpha, pair, wo, frame) + peaks;
}
#endif
