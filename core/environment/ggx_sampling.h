// Sample points and GGX sampling shared by the environment precomputation and the CPU reference's
// Monte-Carlo environment lighting: the Hammersley set, GGX half vectors from D(h)·cos θ_h
// (Walter et al., EGSR 2007, eqs. 35-36) and visible normals (Heitz, "Sampling the GGX
// Distribution of Visible Normals", JCGT 7(4), 2018). Local frame: z is the normal. No BRDFs.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "math/constants.h"

namespace glint {

// Van der Corput's radical inverse in base 2.
inline float radicalInverse(uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return static_cast<float>(bits) * 2.3283064365386963e-10f;
}

// Point i of the n-point Hammersley set in [0,1)².
inline glm::vec2 hammersley(int i, int n) {
    return {(i + 0.5f) / n, radicalInverse(static_cast<uint32_t>(i))};
}

// A half vector with density D(h)·cos θ_h for isotropic GGX of roughness α.
inline glm::vec3 sampleGgxHalfVector(glm::vec2 u, float alpha) {
    const float cos2 = (1.0f - u.x) / (1.0f + (alpha * alpha - 1.0f) * u.x);
    const float cosTheta = std::sqrt(cos2), sinTheta = std::sqrt(std::max(0.0f, 1.0f - cos2));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// A visible normal for the view direction `view` (local, z > 0) of isotropic GGX, density
// G1(v) max(0, v·h) D(h) / cos θ_v (Heitz 2018, listing 1).
inline glm::vec3 sampleGgxVisibleNormal(glm::vec3 view, glm::vec2 u, float alpha) {
    const glm::vec3 stretched = glm::normalize(glm::vec3(alpha * view.x, alpha * view.y, view.z));
    const float lengthSquared = stretched.x * stretched.x + stretched.y * stretched.y;
    const glm::vec3 t1 = lengthSquared > 0.0f ? glm::vec3(-stretched.y, stretched.x, 0.0f) / std::sqrt(lengthSquared)
                                              : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(stretched, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + stretched.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 normal = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * stretched;
    return glm::normalize(glm::vec3(alpha * normal.x, alpha * normal.y, std::max(1e-6f, normal.z)));
}

}  // namespace glint
