// Minnaert or Lommel-Seeliger limb darkening plus a retroreflective lobe. GLSL twin of
// core/brdf/retroreflective.h (fields: albedo, limb_darkening, minnaert_k, retroreflection,
// retro_exponent).

vec3 evalRetroreflective(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi), cosOut = cosTheta(frame, wo);
    if (cosIn <= 0.0 || cosOut <= 0.0) return vec3(0.0);
    float diffuse;
    if (p.limb_darkening == LIMB_DARKENING_MINNAERT)
        diffuse = (p.minnaert_k + 1.0) / (2.0 * PI) * pow(cosIn * cosOut, p.minnaert_k - 1.0);
    else diffuse = 1.0 / (4.0 * PI * (cosIn + cosOut));
    float retro = (p.retro_exponent + 1.0) / (2.0 * PI) * powZeroIsOne(max(dot(wi, wo), 0.0), p.retro_exponent);
    return p.albedo * diffuse + p.retroreflection * retro;
}

// Ambient reflectance k_a: the diffuse law's exact directional albedo (see retroreflective.h).
vec3 ambientReflectanceRetroreflective(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float cosOut = cosTheta(frame, wo);
    if (cosOut <= 0.0) return vec3(0.0);
    if (p.limb_darkening == LIMB_DARKENING_MINNAERT) return p.albedo * pow(cosOut, p.minnaert_k - 1.0);
    return p.albedo * (0.5 * (1.0 - cosOut * log(1.0 + 1.0 / cosOut)));
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of environmentLightingRetroreflective in core/environment/environment_lighting.cpp.
// The albedo × E(n)/π plus the lobe's departure from Lambert's shape at the peak lights.
vec3 environmentLightingRetroreflective(MaterialParams p, vec3 wo, ShadingFrame frame) {
    vec3 albedo = ambientReflectanceRetroreflective(p, wo, frame);
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, 1.0, wo, frame, (evalRetroreflective(p, wi, wo, frame) - albedo * INV_PI) * cosTheta(frame, wi))
    return albedo * environmentDiffuseRadiance(frame.normal) + peaks;
}
#endif
