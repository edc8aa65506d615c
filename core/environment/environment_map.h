// An environment map with its image-based lighting precomputed once, when it is made (never per
// frame): the radiance image, its irradiance map (the cosine convolution of the radiance, exact
// for small bright sources where 9 spherical harmonics ring) and the specular radiance
// prefiltered with the GGX lobe for a ladder of roughnesses (Karis, "Real Shading in Unreal
// Engine 4", SIGGRAPH 2013 course, split-sum). The lookups below are the C++ twins of
// shaders/common/environment.glsl. Rotation and intensity are applied by the caller. Accuracy
// against the Monte-Carlo integral: docs/environment-lighting.md.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "environment/environment_distribution.h"
#include "environment/equirect.h"
#include "environment/prefilter_kernel.h"

namespace glint {

// Prefiltered levels: level k (1..kPrefilteredLevels) holds perceptual roughness r = k/kPrefilteredLevels
// (α = r²); level 0 is the radiance image itself (r = 0, a mirror).
inline constexpr int kPrefilteredLevels = 5;
inline constexpr int kPrefilteredWidth = 128, kPrefilteredHeight = 64;

// The map's concentrated light (its "peaks": each texel's radiance above kPeakThreshold × the
// map's mean luminance, as a share of its luminance, so that a peak keeps its colour) is taken out
// of the radiance that glossy lobes see prefiltered and lit as at most kMaxPeakLights lights, one
// for each of its brightest connected regions, through which the shaders evaluate the material's
// own BRDF with the lobe widened for the light's extent: the split sum's lobe (n = v = R) has the
// wrong shape for a small bright source, and is close on the dim, smooth rest.
inline constexpr float kPeakThreshold = 4.0f;
inline constexpr int kMaxPeakLights = 8;
// A lobe of GGX roughness α takes a light of angular radius ρ as √(α² + (w sin ρ)²), w =
// kPeakWidening (Karis 2013 widens so for sphere lights; the half-vector spreads by half the
// light's angle; measured best of 0.35, 0.5 and 0.7, and the sum α + w sin ρ lost 10-20 dB on the
// small light). Lobes take the peaks from GGX roughness EnvironmentMap::peakMinimumAlpha:
// kPeakMinimumAlpha, or kPeakLobeToLight × the widest light's w sin ρ where that is more. A lobe
// much narrower than a light would show one round widened light where the map has its shape
// (a soft box's rectangle), which the prefiltered map keeps (built-in studio, GGX α 0.05: 25.5 dB
// with its lights, 36.9 dB without).
inline constexpr float kPeakWidening = 0.5f;
inline constexpr float kPeakMinimumAlpha = 0.04f;
inline constexpr float kPeakLobeToLight = 0.75f;
struct EnvironmentPeakLight {
    glm::vec3 direction;   // unit, map space: the luminance-weighted mean direction of its region
    glm::vec3 irradiance;  // [W/m²] at normal incidence: ∫ L_peak dω over its region
    float sinRadius;       // sine of the radius of the disc with the region's mean cosine to `direction`
};

struct EnvironmentMap {
    EquirectImage radiance;                       // base level [W/(sr·m²)], as loaded or baked
    EquirectImage irradiance;                     // E(n)/π at each texel's direction n, prefiltered size
    std::vector<EquirectImage> prefiltered;       // kPrefilteredLevels images, roughness 1/L … 1
    std::vector<EquirectImage> residualPrefiltered;  // the same for the radiance less its peaks
    std::vector<EnvironmentPeakLight> peaks;      // at most kMaxPeakLights; none where no texel is a peak
    glm::vec3 residualMean{0.0f};                 // mean radiance over the sphere of the map less its peaks
    float peakMinimumAlpha = kPeakMinimumAlpha;   // the GGX roughness from which glossy lobes take the peaks
    EnvironmentDistribution distribution;         // for the Monte-Carlo reference's light sampling
};

// Offered the fraction of the precompute done, in [0, 1], from the calling thread (its stages
// weighted by their measured cost, rows within each); returning false cancels it.
using EnvironmentProgress = std::function<bool(float fraction)>;

// Precomputes the lighting of a radiance image (multithreaded; over a second of CPU for the built-in
// studio, which environment_cache.h keeps on disk; about a second for a 1024×512 file on 2 cores).
// Null only when `progress` cancelled it.
std::shared_ptr<const EnvironmentMap> makeEnvironmentMap(EquirectImage radiance, const EnvironmentProgress& progress = {});

// E(n)/π [W/(sr·m²)] for a unit normal n (map space): bilinear in the irradiance map.
glm::vec3 diffuseRadiance(const EnvironmentMap& map, glm::vec3 normal);

// Radiance prefiltered for perceptual roughness r ∈ [0,1] towards `direction` (map space):
// bilinear in the two nearest levels, linear between them.
glm::vec3 prefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness);
// The same for the radiance less its peaks, for r ≥ 1/kPrefilteredLevels (clamped there).
glm::vec3 residualPrefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness);

}  // namespace glint
