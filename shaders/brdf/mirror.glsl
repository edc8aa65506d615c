// Mirror: GLSL twin of core/brdf/mirror.h (fields: ior, extinction, diffuse_albedo). The delta lobe
// is traced by traceMirror() in common/specular_transport.glsl.

vec3 evalMirror(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo * INV_PI;
}

vec3 ambientReflectanceMirror(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo;
}

vec3 transportMirror(MaterialParams p, vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    return traceMirror(p.ior, p.extinction, frame.normal, towardsViewer);
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of environmentLightingMirror in core/environment/environment_lighting.cpp.
vec3 environmentLightingMirror(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo * environmentDiffuseRadiance(frame.normal);
}
#endif
