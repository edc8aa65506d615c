// Phong in the four BRDF forms of the lectures. GLSL twin of core/brdf/phong.h
// (fields: diffuse_albedo, specular, exponent, form).

vec3 evalPhong(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi);
    float cosOut = cosTheta(frame, wo);
    if (cosIn <= 0.0 || cosOut <= 0.0) return vec3(0.0);
    float cosMirror = 2.0 * cosIn * cosOut - dot(wi, wo);  // R·ω_o
    float lobe = powZeroIsOne(max(cosMirror, 0.0), p.exponent);
    float specularScale;
    vec3 sum = wi + wo;
    if (p.form == FORM_LECTURE) specularScale = lobe / cosIn;                             // lecture
    else if (p.form == FORM_MAX_COSINE) specularScale = lobe / max(cosIn, cosOut);           // max-cosine
    else if (p.form == FORM_HALF_VECTOR) specularScale = lobe / dot(sum, sum);                // |L+V|²
    else specularScale = lobe * (p.exponent + 2.0) / (2.0 * PI);               // normalised
    return p.diffuse_albedo * INV_PI + p.specular * specularScale;
}

// Ambient reflectance k_a = ρ_d (see phong.h).
vec3 ambientReflectancePhong(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo;
}

#ifdef GLINT_HAS_ENVIRONMENT
// The specular lobe's f_r cos θ_i widened to GGX roughness `widened`, keeping its energy.
vec3 phongPeakLobe(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame, float widened) {
    float exponent = p.exponent;
    p.diffuse_albedo = vec3(0.0);
    p.exponent = min(exponent, (2.0 / (widened * widened) - 2.0) / 4.0);
    float keep = p.form == FORM_NORMALIZED ? 1.0 : (p.exponent + 2.0) / (exponent + 2.0);
    return keep * evalPhong(p, wi, wo, frame) * cosTheta(frame, wi);
}

// Environment hook: twin of environmentLightingPhong in core/environment/environment_lighting.cpp.
vec3 environmentLightingPhong(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float alpha = sqrt(2.0 / (4.0 * p.exponent + 2.0));
    float normalization = p.form == FORM_NORMALIZED ? 1.0 : (p.exponent + 2.0) / (2.0 * PI);
    float weight = environmentLobeAlbedo(PHONG_ALBEDO + p.form, wo, frame, alpha) / normalization;
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, alpha, wo, frame, phongPeakLobe(p, wi, wo, frame, widened))
    return p.diffuse_albedo * environmentDiffuseRadiance(frame.normal) +
           p.specular * weight * environmentGlossyRadiance(environmentMirrorDirection(wo, frame), alpha) + peaks;
}
#endif
