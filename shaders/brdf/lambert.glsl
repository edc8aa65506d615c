// Lambert: f_r = ρ/π. GLSL twin of core/brdf/lambert.h; MaterialParams is generated from the
// parameter table (fields: albedo).

vec3 evalLambert(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    return p.albedo * INV_PI;
}

// Ambient reflectance k_a = ρ (the exact directional albedo; see lambert.h).
vec3 ambientReflectanceLambert(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.albedo;
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of environmentLightingLambert in core/environment/environment_lighting.cpp.
vec3 environmentLightingLambert(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.albedo * environmentDiffuseRadiance(frame.normal);
}
#endif
