// MERL measured BRDFs (Matusik et al., "A Data-Driven Reflectance Model", SIGGRAPH 2003): GLSL
// twin of lookupMerlTrilinear (core/interchange/merl.cpp) and of the albedo hooks in
// core/render/measured_shading.cpp. The table comes as a texture; no analytic parameters.

// The table, RGB f_r [1/sr]: x = φ_d bin (180), y = θ_d bin (90), z = θ_h bin (90), read with
// texelFetch (the interpolation is done here, in full float, as on the CPU).
uniform sampler3D merlTable;
// Directional albedo ρ(θ_o) at cos θ_o = (k + ½)/32 (MeasuredBrdf::directionalAlbedo).
uniform vec3 merlAlbedo[32];

// Rotation of v about a unit axis (Rodrigues), as the reference reader's rotate_vector.
vec3 merlRotate(vec3 v, vec3 axis, float angle) {
    float c = cos(angle), s = sin(angle);
    return v * c + axis * (dot(v, axis) * (1.0 - c)) + cross(axis, v) * s;
}

// Continuous bin coordinates (θ_h, θ_d, φ_d) of a direction pair in the local frame: the
// Rusinkiewicz half/difference angles (EGWR 1998), θ_h index 90·√(θ_h/(π/2)), θ_d index
// 90·θ_d/(π/2), φ_d folded into [0, π) by reciprocity, index 180·φ_d/π. Twin of
// toHalfDifference + merlBinCoordinates.
vec3 merlBinCoordinates(vec3 wi, vec3 wo, ShadingFrame frame) {
    vec3 towardsLight = vec3(dot(wi, frame.tangent), dot(wi, frame.bitangent), dot(wi, frame.normal));
    vec3 towardsViewer = vec3(dot(wo, frame.tangent), dot(wo, frame.bitangent), dot(wo, frame.normal));
    vec3 halfVector = normalize(towardsLight + towardsViewer);
    float thetaHalf = acos(clamp(halfVector.z, -1.0, 1.0));
    float phiHalf = atan(halfVector.y, halfVector.x);
    vec3 difference = merlRotate(merlRotate(towardsLight, vec3(0.0, 0.0, 1.0), -phiHalf), vec3(0.0, 1.0, 0.0), -thetaHalf);
    float thetaDifference = acos(clamp(difference.z, -1.0, 1.0));
    float phiDifference = atan(difference.y, difference.x);
    if (phiDifference < 0.0) phiDifference += PI;
    return vec3(90.0 * sqrt(max(thetaHalf, 0.0) / (0.5 * PI)), 90.0 * thetaDifference / (0.5 * PI),
                180.0 * phiDifference / PI);
}

vec3 merlSample(int thetaHalf, int thetaDifference, int phiDifference) {
    return texelFetch(merlTable, ivec3(phiDifference, thetaDifference, thetaHalf), 0).rgb;
}

// f_r: trilinear between the 8 surrounding samples; θ_h and θ_d clamp at the last sample, φ_d
// wraps (sample 180 is sample 0); 0 below either horizon.
vec3 evalMerl(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    if (!(dot(wi, frame.normal) > 0.0 && dot(wo, frame.normal) > 0.0)) return vec3(0.0);
    vec3 bins = merlBinCoordinates(wi, wo, frame);
    if (any(isnan(bins)) || any(isinf(bins))) return vec3(0.0);
    float u = clamp(bins.x, 0.0, 89.0), v = clamp(bins.y, 0.0, 89.0), w = clamp(bins.z, 0.0, 180.0);
    int u0 = min(int(u), 88), v0 = min(int(v), 88), w0 = min(int(w), 179);
    float tu = u - float(u0), tv = v - float(v0), tw = w - float(w0);
    int w1 = (w0 + 1) % 180;
    vec3 sum = vec3(0.0);
    for (int du = 0; du < 2; ++du)
        for (int dv = 0; dv < 2; ++dv)
            for (int dw = 0; dw < 2; ++dw) {
                float weight = (du == 1 ? tu : 1.0 - tu) * (dv == 1 ? tv : 1.0 - tv) * (dw == 1 ? tw : 1.0 - tw);
                sum += weight * merlSample(u0 + du, v0 + dv, dw == 1 ? w1 : w0);
            }
    return sum;
}

// ρ(θ_o), linear in cos θ_o between the tabulated samples (twin of measuredDirectionalAlbedo).
vec3 merlDirectionalAlbedo(float cosThetaOut) {
    float position = clamp(cosThetaOut * 32.0 - 0.5, 0.0, 31.0);
    int below = min(int(position), 30);
    float t = position - float(below);
    return (1.0 - t) * merlAlbedo[below] + t * merlAlbedo[below + 1];
}

// Ambient: uniform radiance reflects as ρ(θ_o)·L_a.
vec3 ambientReflectanceMerl(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return merlDirectionalAlbedo(dot(wo, frame.normal));
}

#ifdef GLINT_HAS_ENVIRONMENT
// Environment: the diffuse approximation ρ(θ_o)·E(n)/π (measuredEnvironmentLighting).
vec3 environmentLightingMerl(MaterialParams p, vec3 wo, ShadingFrame frame) {
    return merlDirectionalAlbedo(dot(wo, frame.normal)) * environmentDiffuseRadiance(frame.normal);
}
#endif
