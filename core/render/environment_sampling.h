// Monte-Carlo ground truth for environment lighting, for the CPU reference when asked for
// (ReferenceOptions::sampleEnvironment): L_o = ∫ f_r(ω_i, ω_o) L_env(ω_i) cos θ_i dω_i estimated
// with the model's own f_r (evalBrdf) by multiple importance sampling: equal shares of samples
// drawn from the map's luminance (environment/environment_distribution.h), from the cosine lobe
// and, for glossy models, from GGX visible normals (Heitz 2018) at the model's environment
// roughness, combined by the balance heuristic (Veach 1997, §9.2). Fixed Hammersley points,
// rotated per pixel and strategy by a hash of the pixel's seed: the same image on every run and
// thread count. The environment is not occluded by other objects.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "brdf/model_registry.h"
#include "math/frame.h"
#include "scene/environment.h"

namespace glint {

glm::vec3 sampleEnvironmentLighting(BrdfModel model, std::span<const float> values, glm::vec3 wo,
                                    const ShadingFrame& frame, const Environment& environment, uint32_t pixelSeed,
                                    int sampleCount);

}  // namespace glint
