// Fresnel reflectance: the exact equations for a dielectric interface (s and p polarisation,
// unpolarised mean, total internal reflection) and for a conductor with a complex index n + iκ,
// F0 from (n, κ), and Schlick's approximation. Relative indices: η = η_transmitted / η_incident.
// GLSL twin: shaders/brdf/fresnel.glsl. After pbrt-v4 (FrDielectric, FrComplex).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>

#include <glm/glm.hpp>

namespace glint {

struct Polarised {
    float s;  // R_s: electric field perpendicular to the plane of incidence
    float p;  // R_p: parallel
    float unpolarised() const { return 0.5f * (s + p); }
};

// Exact dielectric Fresnel for cos θ_i ∈ [0,1] and relative index η > 0. Snell: sin θ_t =
// sin θ_i / η; when that exceeds 1 the light is totally internally reflected (R_s = R_p = 1).
inline Polarised fresnelDielectricPolarised(float cosIncident, float eta) {
    cosIncident = std::clamp(cosIncident, 0.0f, 1.0f);
    const float sin2Transmitted = (1.0f - cosIncident * cosIncident) / (eta * eta);
    if (sin2Transmitted >= 1.0f) return {1.0f, 1.0f};
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    const float rs = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
    const float rp = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
    return {rs * rs, rp * rp};
}

inline float fresnelDielectric(float cosIncident, float eta) {
    return fresnelDielectricPolarised(cosIncident, eta).unpolarised();
}

// Conductor: complex relative index η = n + iκ; the same equations in complex arithmetic, in the
// precision Real (float to render; tests/metal_index_fit.cpp fits in double). Returns (R_s, R_p).
template <typename Real>
inline std::pair<Real, Real> fresnelConductorSP(Real cosIncident, Real n, Real k) {
    using Complex = std::complex<Real>;
    cosIncident = std::clamp(cosIncident, Real(0), Real(1));
    const Complex eta(n, k);
    const Complex sin2Transmitted = (Real(1) - cosIncident * cosIncident) / (eta * eta);
    const Complex cosTransmitted = std::sqrt(Real(1) - sin2Transmitted);
    const Complex rs = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
    const Complex rp = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
    return {std::norm(rs), std::norm(rp)};
}

inline Polarised fresnelConductorPolarised(float cosIncident, float n, float k) {
    const auto [s, p] = fresnelConductorSP(cosIncident, n, k);
    return {s, p};
}

inline glm::vec3 fresnelConductor(float cosIncident, glm::vec3 n, glm::vec3 k) {
    return {fresnelConductorPolarised(cosIncident, n.x, k.x).unpolarised(),
            fresnelConductorPolarised(cosIncident, n.y, k.y).unpolarised(),
            fresnelConductorPolarised(cosIncident, n.z, k.z).unpolarised()};
}

// Exact Fresnel for a complex index per channel: a channel with κ = 0 takes the dielectric
// equations (so n < 1 gives total internal reflection), any other the conductor ones.
inline glm::vec3 fresnelComplexIndex(float cosIncident, glm::vec3 n, glm::vec3 k) {
    glm::vec3 reflectance;
    for (int c = 0; c < 3; ++c)
        reflectance[c] = k[c] == 0.0f ? fresnelDielectric(cosIncident, n[c])
                                      : fresnelConductorPolarised(cosIncident, n[c], k[c]).unpolarised();
    return reflectance;
}

// Reflectance at normal incidence: F0 = ((n−1)² + κ²) / ((n+1)² + κ²), per channel.
inline glm::vec3 fresnelF0(glm::vec3 n, glm::vec3 k) {
    return ((n - 1.0f) * (n - 1.0f) + k * k) / ((n + 1.0f) * (n + 1.0f) + k * k);
}

// Back from a reflectance F0 at normal incidence, each exact there: a dielectric's index
// n = (1 + √F0)/(1 − √F0); a conductor with n = 1 has κ = 2√(F0/(1 − F0)) (F0 = κ²/(4 + κ²)).
inline float dielectricIorFromF0(float f0) {
    const float root = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    return (1.0f + root) / (1.0f - root);
}
inline float conductorExtinctionFromF0(float f0) {
    const float clamped = std::clamp(f0, 0.0f, 0.999f);
    return 2.0f * std::sqrt(clamped / (1.0f - clamped));
}

// Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", 1994:
// F ≈ F0 + (1 − F0)(1 − cos θ)^5.
inline glm::vec3 fresnelSchlick(glm::vec3 f0, float cosIncident) {
    const float m = std::clamp(1.0f - cosIncident, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

// F82-tint (Hoffman, "Generalization of Adobe's Fresnel Model", 2023; OpenPBR §metal): Schlick's
// form less a·μ(1 − μ)⁶ (μ = cos θ), a chosen so that F(1/7) = tint × Schlick's F(1/7) (θ ≈ 82°,
// near where a metal's curve dips below Schlick's most).
inline constexpr float kF82Cosine = 1.0f / 7.0f;
inline float f82Weight(float cosine) {
    const float m = std::clamp(1.0f - cosine, 0.0f, 1.0f), m3 = m * m * m;
    return cosine * m3 * m3;
}
inline glm::vec3 f82Coefficient(glm::vec3 f0, glm::vec3 tint) {
    return fresnelSchlick(f0, kF82Cosine) * (1.0f - tint) / f82Weight(kF82Cosine);
}
inline glm::vec3 fresnelF82(glm::vec3 f0, glm::vec3 coefficient, float cosine) {
    return glm::max(fresnelSchlick(f0, cosine) - coefficient * f82Weight(cosine), glm::vec3(0.0f));
}

// Brewster's angle, where R_p = 0: tan θ_B = η. Critical angle (η < 1): sin θ_c = η.
inline float brewsterAngle(float eta) { return std::atan(eta); }
inline float criticalAngle(float eta) { return eta < 1.0f ? std::asin(eta) : NAN; }

}  // namespace glint
