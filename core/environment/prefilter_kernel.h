// The kernel a prefiltered level of an environment map holds (environment_map.cpp): GGX light
// directions around R (n = v = R, Karis 2013), each weighted by its cos θ_l and read from the
// radiance pyramid at the level whose texels match the solid angle the sample stands for (filtered
// importance sampling, Colbert & Křivánek, GPU Gems 3, ch. 20). The GGX stand-ins (lobe_albedo.h)
// choose their level by this kernel's mean cosine, texel blur included.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace glint {

// GGX samples per prefiltered texel (Hammersley points).
inline constexpr int kPrefilterSamples = 128;
// The pyramid texels a sample reads cover this many times the solid angle it stands for: one
// level coarser than the match, against aliasing.
inline constexpr float kPrefilterTexelsPerSample = 4.0f;

struct PrefilterSample {
    glm::vec3 light;   // the light direction in the local frame, z = R (above R's horizon)
    float solidAngle;  // the solid angle it stands for, 1/(kPrefilterSamples · pdf) [sr]
};

// The samples of the level of GGX roughness α.
std::vector<PrefilterSample> prefilterSamples(float alpha);

// The mean cosine to R by which the GGX stand-ins take the level of GGX roughness α for a lobe:
// Σ cos θ_l E[cos] / Σ cos θ_l over its samples, each spread by a part of its pyramid texels' blur.
float prefilterKernelMeanCosine(float alpha);

}  // namespace glint
