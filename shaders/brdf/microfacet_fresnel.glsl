// The Fresnel choice of the models with a `fresnel` parameter (FRESNEL_SCHLICK or exact): GLSL
// twin of microfacetFresnel in core/brdf/microfacet.h. Apart from microfacet.glsl, whose D and G
// terms models without that parameter (openpbr) use too.
#include "brdf/fresnel.glsl"

vec3 microfacetFresnel(int mode, float cosDifference, vec3 ior, vec3 extinction) {
    if (mode == FRESNEL_SCHLICK) return fresnelSchlick(fresnelF0(ior, extinction), cosDifference);
    return fresnelComplexIndex(cosDifference, ior, extinction);
}

// Twin of F82Fresnel and f82FresnelOf (core/brdf/microfacet.h): the environment's Fresnel, the
// F82-tint form fitted to the exact Fresnel at cos θ = 1/7 in the exact mode, Schlick's otherwise.
struct F82Fresnel {
    vec3 f0, coefficient;
};

F82Fresnel f82FresnelOf(int mode, vec3 ior, vec3 extinction) {
    vec3 f0 = fresnelF0(ior, extinction);
    if (mode == FRESNEL_SCHLICK) return F82Fresnel(f0, vec3(0.0));
    vec3 tint = fresnelComplexIndex(F82_COSINE, ior, extinction) / fresnelSchlick(f0, F82_COSINE);
    return F82Fresnel(f0, f82Coefficient(f0, tint));
}
