// Monte-Carlo environment lighting (see environment_sampling.h).
#include "render/environment_sampling.h"

#include <cmath>

#include "brdf/microfacet.h"
#include "environment/environment_lighting.h"
#include "environment/environment_map.h"
#include "environment/ggx_sampling.h"
#include "math/constants.h"
#include "render/cosine_sampling.h"

namespace glint {
namespace {

// A 32-bit integer hash (the PCG output permutation, O'Neill 2014) to [0,1).
float hashToUnit(uint32_t value) {
    uint32_t state = value * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * 2.3283064365386963e-10f;
}

// Density of the light direction `light` (local) under visible-normal sampling for `view`:
// G1(v) D(h) / (4 cos θ_v) (Heitz 2018, eq. 17 with the reflection Jacobian 1/(4 v·h)).
float visibleNormalPdf(glm::vec3 view, glm::vec3 light, float alpha) {
    const glm::vec3 halfway = glm::normalize(view + light);
    const float sin2Half = std::max(0.0f, 1.0f - halfway.z * halfway.z);
    const float maskingView = 1.0f / (1.0f + lambdaGgx(view.z, alpha));
    return maskingView * distributionGgx(halfway.z, sin2Half, alpha) / (4.0f * view.z);
}

enum Strategy { kEnvironment, kCosine, kGgx, kStrategyCount };

}  // namespace

glm::vec3 sampleEnvironmentLighting(BrdfModel model, std::span<const float> values, glm::vec3 wo,
                                    const ShadingFrame& frame, const Environment& environment, uint32_t pixelSeed,
                                    int sampleCount) {
    if (!environment.enabled() || !modelInfo(model).glslEnvironment) return glm::vec3(0.0f);  // delta lobes only
    const glm::vec3 view = frame.toLocal(wo);
    if (view.z <= 0.0f) return glm::vec3(0.0f);
    const float alpha = std::max(environmentRoughness(model, values), 1e-3f);
    const bool glossy = environmentRoughness(model, values) > 0.0f;
    const EnvironmentDistribution& distribution = environment.map->distribution;
    // Samples per strategy: the map and the cosine lobe, and for glossy models the GGX lobe too,
    // each its own Hammersley set (interleaving one set would give each strategy half the azimuths).
    const int strategies = glossy ? 3 : 2;
    const int perStrategy = std::max(1, sampleCount / strategies);
    const float share = 1.0f / strategies;  // n_s / N of each strategy in the balance heuristic
    glm::vec3 sum(0.0f);
    for (int strategy = 0; strategy < strategies; ++strategy) {
        const uint32_t seed = 2u * (pixelSeed * kStrategyCount + static_cast<uint32_t>(strategy));
        const glm::vec2 shift{hashToUnit(seed), hashToUnit(seed + 1u)};
        for (int i = 0; i < perStrategy; ++i) {
            const glm::vec2 u = glm::fract(hammersley(i, perStrategy) + shift);
            glm::vec3 lightWorld;
            if (strategy == kEnvironment) {
                lightWorld = environmentWorldDirection(environment, distribution.sample(u).direction);
            } else if (strategy == kCosine) {
                lightWorld = frame.toWorld(cosineDirection(u));
            } else {
                const glm::vec3 halfway = sampleGgxVisibleNormal(view, u, alpha);
                lightWorld = frame.toWorld(2.0f * glm::dot(view, halfway) * halfway - view);
            }
            const glm::vec3 light = frame.toLocal(lightWorld);
            if (light.z <= 0.0f) continue;
            // Balance heuristic (Veach 1997, §9.2.2): f·L·cos / Σ_s (n_s/N) p_s.
            float pdf = share * (distribution.pdf(environmentMapDirection(environment, lightWorld)) + cosineDirectionPdf(light.z));
            if (glossy) pdf += share * visibleNormalPdf(view, light, alpha);
            if (!(pdf > 0.0f)) continue;
            sum += evalBrdf(model, values, lightWorld, wo, frame) * environmentRadiance(environment, lightWorld) *
                   (light.z / pdf);
        }
    }
    return sum / static_cast<float>(perStrategy * strategies);
}

}  // namespace glint
