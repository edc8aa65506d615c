// The Fresnel choice of the models with a `fresnel` parameter (FRESNEL_SCHLICK or exact): GLSL
// twin of microfacetFresnel in core/brdf/microfacet.h. Apart from microfacet.glsl, whose D and G
// terms models without that parameter (openpbr) use too.
#include "brdf/fresnel.glsl"

vec3 microfacetFresnel(int mode, float cosDifference, vec3 ior, vec3 extinction) {
    if (mode == FRESNEL_SCHLICK) return fresnelSchlick(fresnelF0(ior, extinction), cosDifference);
    return fresnelComplexIndex(cosDifference, ior, extinction);
}
