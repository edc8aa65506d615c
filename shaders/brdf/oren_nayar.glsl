// Oren-Nayar qualitative rough diffuse model (1994, eq. 30). GLSL twin of core/brdf/oren_nayar.h
// (fields: albedo, roughness [degrees]).

vec3 evalOrenNayar(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi), cosOut = cosTheta(frame, wo);
    if (cosIn <= 0.0 || cosOut <= 0.0) return vec3(0.0);
    float sigma = p.roughness * (PI / 180.0);
    float sigma2 = sigma * sigma;
    float a = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float b = 0.45 * sigma2 / (sigma2 + 0.09);
    float azimuthal = max(0.0, dot(wi, wo) - cosIn * cosOut);
    return p.albedo * INV_PI * (a + b * azimuthal / max(cosIn, cosOut));
}

// Ambient reflectance k_a = ρ (see oren_nayar.h).
vec3 ambientReflectanceOrenNayar(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.albedo;
}

// Twin of directionalAlbedoOrenNayar() (see oren_nayar.h).
float directionalAlbedoOrenNayar(float roughnessDegrees, float cosOut) {
    float sigma = roughnessDegrees * (PI / 180.0);
    float sigma2 = sigma * sigma;
    float a = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float b = 0.45 * sigma2 / (sigma2 + 0.09);
    float cosine = clamp(cosOut, 1e-4, 1.0), sine = sqrt(1.0 - cosine * cosine);
    float theta = acos(cosine);
    float below = sine * (0.5 * theta - 0.5 * sine * cosine);
    float above = sine / cosine * (1.0 - sine * sine * sine) / 3.0;
    return a + 2.0 * b * INV_PI * (below + above);
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of environmentLightingOrenNayar in core/environment/environment_lighting.cpp.
// The albedo × E(n)/π plus the lobe's departure from Lambert's shape at the peak lights.
vec3 environmentLightingOrenNayar(MaterialParams p, vec3 wo, ShadingFrame frame) {
    vec3 albedo = p.albedo * directionalAlbedoOrenNayar(p.roughness, cosTheta(frame, wo));
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, 1.0, wo, frame, (evalOrenNayar(p, wi, wo, frame) - albedo * INV_PI) * cosTheta(frame, wi))
    return albedo * environmentDiffuseRadiance(frame.normal) + peaks;
}
#endif
