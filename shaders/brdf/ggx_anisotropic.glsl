// Anisotropic GGX with height-correlated Smith, complex-index Fresnel and Lambert diffuse. GLSL
// twin of core/brdf/ggx_anisotropic.h (fields: diffuse_albedo, ior, extinction, roughness_x,
// roughness_y, fresnel).
#include "brdf/microfacet.glsl"
#include "brdf/microfacet_fresnel.glsl"

float ggxAnisotropicSpecular(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    vec3 inLocal = toLocal(frame, wi), outLocal = toLocal(frame, wo);
    vec3 halfLocal = normalize(inLocal + outLocal);
    float distribution = distributionGgxAnisotropic(halfLocal, p.roughness_x, p.roughness_y);
    float geometry = smithHeightCorrelated(lambdaGgxAnisotropic(inLocal, p.roughness_x, p.roughness_y),
                                           lambdaGgxAnisotropic(outLocal, p.roughness_x, p.roughness_y));
    return distribution * geometry / (4.0 * inLocal.z * outLocal.z);
}

vec3 evalGgxAnisotropic(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    if (cosTheta(frame, wi) <= 0.0 || cosTheta(frame, wo) <= 0.0) return vec3(0.0);
    float cosDifference = dot(wi, normalize(wi + wo));
    vec3 fresnel = microfacetFresnel(p.fresnel, cosDifference, p.ior, p.extinction);
    return p.diffuse_albedo * INV_PI + fresnel * ggxAnisotropicSpecular(p, wi, wo, frame);
}

// Ambient reflectance k_a = ρ_d (see ggx_anisotropic.h).
vec3 ambientReflectanceGgxAnisotropic(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo;
}

#ifdef GLINT_HAS_ENVIRONMENT
// The specular lobe's f_r cos θ_i widened from roughness `alpha` to `widened`, with the Fresnel
// of f82FresnelOf.
vec3 ggxAnisotropicPeakLobe(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame, float alpha, float widened, F82Fresnel f82) {
    vec3 fresnel = fresnelF82(f82.f0, f82.coefficient, dot(wi, normalize(wi + wo)));
    p.roughness_x *= widened / alpha;
    p.roughness_y *= widened / alpha;
    return fresnel * (ggxAnisotropicSpecular(p, wi, wo, frame) * cosTheta(frame, wi));
}

// Environment hook: twin of environmentLightingGgxAnisotropic in core/environment/environment_lighting.cpp.
vec3 environmentLightingGgxAnisotropic(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float alpha = sqrt(p.roughness_x * p.roughness_y);
    F82Fresnel f82 = f82FresnelOf(p.fresnel, p.ior, p.extinction);
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, alpha, wo, frame, ggxAnisotropicPeakLobe(p, wi, wo, frame, alpha, widened, f82))
    return p.diffuse_albedo * environmentDiffuseRadiance(frame.normal) +
           environmentSplitSumSpecular(f82.f0, f82.coefficient, alpha, GGX_SMITH_PAIR, wo, frame) + peaks;
}
#endif
