// Fresnel reflectance: exact dielectric (with total internal reflection) and conductor
// (complex index n + iκ), F0 from (n, κ), and Schlick. GLSL twin of core/brdf/fresnel.h;
// complex numbers are vec2 (real, imaginary).

float fresnelDielectric(float cosIncident, float eta) {
    cosIncident = clamp(cosIncident, 0.0, 1.0);
    float sin2Transmitted = (1.0 - cosIncident * cosIncident) / (eta * eta);
    if (sin2Transmitted >= 1.0) return 1.0;  // total internal reflection
    float cosTransmitted = sqrt(1.0 - sin2Transmitted);
    float rs = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
    float rp = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
    return 0.5 * (rs * rs + rp * rp);
}

vec2 complexMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 complexDiv(vec2 a, vec2 b) { return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / dot(b, b); }
vec2 complexSqrt(vec2 z) {  // principal root, as std::sqrt(std::complex)
    float modulus = length(z);
    float re = sqrt(max(0.5 * (modulus + z.x), 0.0));
    float im = sqrt(max(0.5 * (modulus - z.x), 0.0));
    return vec2(re, z.y < 0.0 ? -im : im);
}

float fresnelConductorChannel(float cosIncident, float n, float k) {
    cosIncident = clamp(cosIncident, 0.0, 1.0);
    vec2 eta = vec2(n, k);
    vec2 sin2Transmitted = complexDiv(vec2(1.0 - cosIncident * cosIncident, 0.0), complexMul(eta, eta));
    vec2 cosTransmitted = complexSqrt(vec2(1.0, 0.0) - sin2Transmitted);
    vec2 etaCosT = complexMul(eta, cosTransmitted);
    vec2 etaCosI = eta * cosIncident;
    vec2 rs = complexDiv(vec2(cosIncident, 0.0) - etaCosT, vec2(cosIncident, 0.0) + etaCosT);
    vec2 rp = complexDiv(etaCosI - cosTransmitted, etaCosI + cosTransmitted);
    return 0.5 * (dot(rs, rs) + dot(rp, rp));
}

vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k) {
    return vec3(fresnelConductorChannel(cosIncident, n.r, k.r), fresnelConductorChannel(cosIncident, n.g, k.g),
                fresnelConductorChannel(cosIncident, n.b, k.b));
}

// Twin of fresnelComplexIndex: dielectric equations (with TIR) where κ = 0, conductor elsewhere.
float fresnelComplexIndexChannel(float cosIncident, float n, float k) {
    return k == 0.0 ? fresnelDielectric(cosIncident, n) : fresnelConductorChannel(cosIncident, n, k);
}

vec3 fresnelComplexIndex(float cosIncident, vec3 n, vec3 k) {
    return vec3(fresnelComplexIndexChannel(cosIncident, n.r, k.r), fresnelComplexIndexChannel(cosIncident, n.g, k.g),
                fresnelComplexIndexChannel(cosIncident, n.b, k.b));
}

vec3 fresnelF0(vec3 n, vec3 k) {
    return ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
}

vec3 fresnelSchlick(vec3 f0, float cosIncident) {
    float m = clamp(1.0 - cosIncident, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// The F82-tint form (twin of fresnel.h): Schlick's less a·μ(1 − μ)⁶, F(1/7) = tint × Schlick's F(1/7).
const float F82_COSINE = 1.0 / 7.0;  // kF82Cosine

float f82Weight(float cosine) {
    float m = clamp(1.0 - cosine, 0.0, 1.0), m3 = m * m * m;
    return cosine * m3 * m3;
}

vec3 f82Coefficient(vec3 f0, vec3 tint) {
    return fresnelSchlick(f0, F82_COSINE) * (1.0 - tint) / f82Weight(F82_COSINE);
}

vec3 fresnelF82(vec3 f0, vec3 coefficient, float cosine) {
    return max(fresnelSchlick(f0, cosine) - coefficient * f82Weight(cosine), vec3(0.0));
}
