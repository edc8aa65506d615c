// Image-based lighting of a surface by the scene's environment, as the GPU computes it (twin of
// shaders/common/environment.glsl and of each model's environmentLighting<Model> GLSL hook):
// diffuse terms take the irradiance map's E(n)/π, glossy terms the GGX-prefiltered radiance along
// the mirror direction at the model's equivalent roughness × the lobe's own directional albedo
// (lobe_albedo.h), microfacet models the split-sum scale and bias with the lookup along the
// dominant direction; from α 0.04 the map's peaks are
// lit as directional lights through the model's own BRDF and the prefiltered terms see the rest.
// The Monte-Carlo ground truth is render/environment_sampling.h.
#pragma once

#include <span>
#include <string>

#include <glm/glm.hpp>

#include "brdf/model_registry.h"
#include "math/frame.h"
#include "scene/environment.h"

namespace glint {

// A world direction in the map's own frame: turned by −rotation about +y.
glm::vec3 environmentMapDirection(const Environment& environment, glm::vec3 worldDirection);
// Radiance [W/(sr·m²)] arriving from a world direction: intensity × bilinear base level.
glm::vec3 environmentRadiance(const Environment& environment, glm::vec3 worldDirection);
// E(n)/π: the radiance a white Lambert surface with unit normal n reflects.
glm::vec3 environmentDiffuseRadiance(const Environment& environment, glm::vec3 normal);
// Prefiltered radiance along a world direction for perceptual roughness r = √α.
glm::vec3 environmentSpecularRadiance(const Environment& environment, glm::vec3 worldDirection, float perceptualRoughness);

// Glossy lobes from GGX roughness EnvironmentMap::peakMinimumAlpha on take the map's peaks as
// lights through their own BRDF and the prefiltered rest (environment_map.h); sharper lobes, which
// would show a light's widened disc where the map has a shape, the prefiltered map as a whole.
bool environmentUsesPeaks(const Environment& environment, float alpha);
// Peak k's world direction and irradiance [W/m²] at normal incidence (× the intensity).
glm::vec3 environmentPeakDirection(const Environment& environment, int k);
glm::vec3 environmentPeakIrradiance(const Environment& environment, int k);
// The GGX roughness a lobe of roughness α takes for peak k, widened for the light's extent:
// √(α² + (kPeakWidening sin ρ)²), at most 1.
float environmentPeakAlpha(const Environment& environment, int k, float alpha);
// The prefiltered radiance of the map less its peaks (r clamped to ≥ 1/kPrefilteredLevels).
glm::vec3 environmentResidualSpecularRadiance(const Environment& environment, glm::vec3 worldDirection,
                                              float perceptualRoughness);
// The mean radiance over the sphere of the map less its peaks (× the intensity).
glm::vec3 environmentResidualMeanRadiance(const Environment& environment);
// The inverse of environmentMapDirection.
glm::vec3 environmentWorldDirection(const Environment& environment, glm::vec3 mapDirection);

// The GGX roughness α a model's glossy lobe is prefiltered with (0 when it has none): microfacet
// α itself (√(α_x α_y) when anisotropic), Ward √(α_x α_y), Blinn-Phong √(2/(n+2)) (Walter et al.
// 2007, after eq. 30: the Beckmann α of a Blinn exponent n), Phong √(2/(4n+2)) (a Phong lobe
// around R of exponent n is about a Blinn lobe of exponent 4n, since θ_h ≈ δ/2).
float environmentRoughness(BrdfModel model, std::span<const float> values);

// How the preview approximates a material's environment light on this map, in a few words (for the
// probe): the diffuse and glossy methods, and whether the map's peak lights are in use.
std::string environmentApproximation(BrdfModel model, std::span<const float> values, const Environment& environment);

// The model's environment hook (ModelInfo::glslEnvironment): radiance reflected towards wo
// from the environment by the model's non-delta lobes. Zero for models without one (glass).
glm::vec3 environmentLighting(BrdfModel model, std::span<const float> values, glm::vec3 wo, const ShadingFrame& frame,
                              const Environment& environment);

}  // namespace glint
