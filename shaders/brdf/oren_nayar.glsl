// Oren-Nayar qualitative rough diffuse model (1994, eq. 30). GLSL twin of core/brdf/oren_nayar.h
// (fields: albedo, roughness [degrees]).

// Twin of orenNayarCoefficients(): (A, B).
vec2 orenNayarCoefficients(float roughnessDegrees) {
    float sigma = roughnessDegrees * (PI / 180.0);
    float sigma2 = sigma * sigma;
    return vec2(1.0 - 0.5 * sigma2 / (sigma2 + 0.33), 0.45 * sigma2 / (sigma2 + 0.09));
}

vec3 evalOrenNayar(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi), cosOut = cosTheta(frame, wo);
    if (cosIn <= 0.0 || cosOut <= 0.0) return vec3(0.0);
    vec2 ab = orenNayarCoefficients(p.roughness);
    float azimuthal = max(0.0, dot(wi, wo) - cosIn * cosOut);
    return p.albedo * INV_PI * (ab.x + ab.y * azimuthal / max(cosIn, cosOut));
}

// Ambient reflectance k_a = ρ (see oren_nayar.h).
vec3 ambientReflectanceOrenNayar(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.albedo;
}

// Twin of orenNayarMoments() (see oren_nayar.h): per unit ρ, x the directional albedo, y and z the
// first moment's parts along n and along ω_o − cos θ_o n, w the band-2 moment.
vec4 orenNayarMoments(float roughnessDegrees, float cosOut) {
    vec2 ab = orenNayarCoefficients(roughnessDegrees);
    float c = clamp(cosOut, 1e-4, 1.0), s = sqrt(1.0 - c * c), t = s / c;
    float theta = acos(c), sin2 = 2.0 * s * c, sin4 = 2.0 * sin2 * (c * c - s * s), s3 = s * s * s;
    float b = 2.0 * ab.y * INV_PI;
    return vec4(ab.x + b * (s * (0.5 * theta - 0.25 * sin2) + t * (1.0 - s3) / 3.0),
                2.0 * ab.x / 3.0 + b * (s3 * s / 3.0 + t * ((0.5 * PI - theta) / 8.0 + sin4 / 32.0)),
                0.5 * ab.y * (2.0 / 3.0 - 0.5 * c + c * c * c / 12.0),
                0.25 * ab.x + b * (s * (sin2 / 8.0 - theta / 16.0 - 3.0 * sin4 / 64.0) + t * (1.0 / 30.0 - s3 / 3.0 + 0.3 * s3 * s * s)));
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment hook: twin of lightingOf(OrenNayarParams) in core/environment/environment_lighting.cpp.
// The irradiance map at ±u and the mean matching the lobe's bands 0-2 (u its lean towards the
// viewer), the lobe's own shape at the peak lights.
vec3 environmentLightingOrenNayar(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float cosOut = cosTheta(frame, wo);
    vec4 m = orenNayarMoments(p.roughness, cosOut);
    vec3 moment = m.y * frame.normal + m.z * (wo - cosOut * frame.normal);
    vec3 u = normalize(moment), albedo = p.albedo * m.x;
    vec3 weights = environmentSmoothWeights(vec2(length(moment), m.w) / m.x);
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_SMOOTH_PEAKS(peaks, albedo, u, weights, wo, frame, evalOrenNayar(p, wi, wo, frame))
    return environmentSmoothRadiance(albedo, u, weights) + peaks;
}
#endif
