// The prefiltered levels' kernel (see prefilter_kernel.h).
#include "environment/prefilter_kernel.h"

#include <algorithm>

#include "brdf/microfacet.h"
#include "environment/ggx_sampling.h"

namespace glint {

std::vector<PrefilterSample> prefilterSamples(float alpha) {
    std::vector<PrefilterSample> samples;
    for (int i = 0; i < kPrefilterSamples; ++i) {
        const glm::vec3 half = sampleGgxHalfVector(hammersley(i, kPrefilterSamples), alpha);
        const glm::vec3 light = 2.0f * half.z * half - glm::vec3(0.0f, 0.0f, 1.0f);
        if (light.z <= 0.0f) continue;
        // The light direction's pdf with n = v: D(h) cos θ_h / (4 v·h) = D(h)/4.
        const float pdf = distributionGgx(half.z, std::max(0.0f, 1.0f - half.z * half.z), alpha) * 0.25f;
        samples.push_back({light, 1.0f / (kPrefilterSamples * pdf)});
    }
    return samples;
}

// A direction spread about its place by a small isotropic blur of variance σ² (both axes together)
// keeps E[cos] = cos θ (1 − σ²/2) to R. The bilinear read of box-filtered pyramid texels of solid
// angle A spreads it by about σ² = A/2, and the levels hold that (a linear map's level r = 1 reads a
// mean cosine of 0.593; the samples alone 0.667, with σ² = A/4 0.634), but one mean cosine is not
// the whole lobe: σ² = A/4 fits the lobes best (measured against A/2, the held kernel and none,
// docs/environment-lighting.md).
float prefilterKernelMeanCosine(float alpha) {
    constexpr float kSpreadPerTexelSolidAngle = 0.25f;
    double weight = 0.0, moment = 0.0;
    for (const PrefilterSample& sample : prefilterSamples(alpha)) {
        const float spread = kSpreadPerTexelSolidAngle * kPrefilterTexelsPerSample * sample.solidAngle;
        weight += sample.light.z;
        moment += sample.light.z * sample.light.z * (1.0f - 0.5f * spread);
    }
    return static_cast<float>(moment / weight);
}

}  // namespace glint
