// Blinn-Phong in the four BRDF forms of the lectures. GLSL twin of core/brdf/blinn_phong.h;
// MaterialParams is generated from the parameter table
// (fields: diffuse_albedo, specular, exponent, form).

vec3 evalBlinnPhong(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    float cosIn = cosTheta(frame, wi);
    float cosOut = cosTheta(frame, wo);
    if (cosIn <= 0.0 || cosOut <= 0.0) return vec3(0.0);
    vec3 sum = wi + wo;
    vec3 halfway = normalize(sum);
    float lobe = powZeroIsOne(max(cosTheta(frame, halfway), 0.0), p.exponent);
    float specularScale;
    if (p.form == FORM_LECTURE) specularScale = lobe / cosIn;                             // lecture
    else if (p.form == FORM_MAX_COSINE) specularScale = lobe / max(cosIn, cosOut);           // max-Blinn
    else if (p.form == FORM_HALF_VECTOR) specularScale = lobe / dot(sum, sum);                // |L+V|²
    else specularScale = lobe * (p.exponent + 8.0) / (8.0 * PI);               // normalised
    return p.diffuse_albedo * INV_PI + p.specular * specularScale;
}

// Ambient reflectance k_a = ρ_d (see blinn_phong.h).
vec3 ambientReflectanceBlinnPhong(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return p.diffuse_albedo;
}

#ifdef GLINT_HAS_ENVIRONMENT
// The specular lobe's f_r cos θ_i widened to GGX roughness `widened`, keeping its energy.
vec3 blinnPhongPeakLobe(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame, float widened) {
    float exponent = p.exponent;
    p.diffuse_albedo = vec3(0.0);
    p.exponent = min(exponent, 2.0 / (widened * widened) - 2.0);
    float keep = p.form == FORM_NORMALIZED ? 1.0 : (p.exponent + 8.0) / (exponent + 8.0);
    return keep * evalBlinnPhong(p, wi, wo, frame) * cosTheta(frame, wi);
}

// Environment hook: twin of environmentLightingBlinnPhong in core/environment/environment_lighting.cpp.
vec3 environmentLightingBlinnPhong(MaterialParams p, vec3 wo, ShadingFrame frame) {
    float alpha = sqrt(2.0 / (p.exponent + 2.0));
    float normalization = p.form == FORM_NORMALIZED ? 1.0 : (p.exponent + 8.0) / (8.0 * PI);
    float weight = environmentLobeAlbedo(BLINN_PHONG_ALBEDO + p.form, wo, frame, alpha) / normalization;
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, alpha, wo, frame, blinnPhongPeakLobe(p, wi, wo, frame, widened))
    return p.diffuse_albedo * environmentDiffuseRadiance(frame.normal) +
           p.specular * weight * environmentGlossyRadiance(environmentMirrorDirection(wo, frame), alpha) + peaks;
}
#endif
