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

// Twin of diffuseMomentsRetroreflective() (see retroreflective.h): the diffuse law's band-1 and
// band-2 moments per unit k_a.
vec2 diffuseMomentsRetroreflective(MaterialParams p, float cosOut) {
    if (p.limb_darkening == LIMB_DARKENING_MINNAERT) {
        float k = p.minnaert_k;
        return vec2((k + 1.0) / (k + 2.0), k / (k + 3.0));
    }
    float mu = max(cosOut, 1e-4);
    float i0 = 1.0 - mu * log(1.0 + 1.0 / mu), i1 = 0.5 - mu * i0, i2 = 1.0 / 3.0 - mu * i1;
    return vec2(i1 / i0, 1.5 * i2 / i0 - 0.5);
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of lightingOf(RetroreflectiveParams) in core/environment/environment_lighting.cpp.
// The irradiance map at ±n and the mean matching the diffuse law's bands 0-2, both lobes' own
// shape at the peak lights.
vec3 environmentLightingRetroreflective(MaterialParams p, vec3 wo, ShadingFrame frame) {
    vec3 albedo = ambientReflectanceRetroreflective(p, wo, frame);
    vec3 weights = environmentSmoothWeights(diffuseMomentsRetroreflective(p, cosTheta(frame, wo)));
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_SMOOTH_PEAKS(peaks, albedo, frame.normal, weights, wo, frame, evalRetroreflective(p, wi, wo, frame))
    return environmentSmoothRadiance(albedo, frame.normal, weights) + peaks;
}
#endif
