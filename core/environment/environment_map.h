// An environment map with its image-based lighting precomputed once, when it is made (never per
// frame): the radiance image, its irradiance as 9 spherical-harmonic coefficients (Ramamoorthi &
// Hanrahan, "An Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001) and
// the specular radiance prefiltered with the GGX lobe for a ladder of roughnesses (Karis, "Real
// Shading in Unreal Engine 4", SIGGRAPH 2013 course, split-sum). The lookups below are the C++
// twins of shaders/common/environment.glsl. Rotation and intensity are applied by the caller.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "environment/equirect.h"

namespace glint {

// Prefiltered levels: level k (1..kPrefilteredLevels) holds perceptual roughness r = k/kPrefilteredLevels
// (α = r²); level 0 is the radiance image itself (r = 0, a mirror).
inline constexpr int kPrefilteredLevels = 5;
inline constexpr int kPrefilteredWidth = 128, kPrefilteredHeight = 64;
// GGX samples per prefiltered texel (Hammersley points, filtered importance sampling).
inline constexpr int kPrefilterSamples = 128;

struct EnvironmentMap {
    EquirectImage radiance;                       // base level [W/(sr·m²)], as loaded or baked
    std::array<glm::vec3, 9> irradianceSh{};      // SH coefficients L_lm of the radiance (l ≤ 2)
    std::vector<EquirectImage> prefiltered;       // kPrefilteredLevels images, roughness 1/5 … 1
};

// Precomputes the lighting of a radiance image (multithreaded; tens to hundreds of ms).
std::shared_ptr<const EnvironmentMap> makeEnvironmentMap(EquirectImage radiance);

// Irradiance E(n) [W/m²] at a surface with unit normal n from the 9 coefficients
// (Ramamoorthi & Hanrahan 2001, eq. 8 with Â_0 = π, Â_1 = 2π/3, Â_2 = π/4).
glm::vec3 shIrradiance(const std::array<glm::vec3, 9>& coefficients, glm::vec3 normal);

// Radiance prefiltered for perceptual roughness r ∈ [0,1] towards `direction` (map space):
// bilinear in the two nearest levels, linear between them.
glm::vec3 prefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness);

// The split-sum BRDF table (Karis 2013) for GGX with height-correlated Smith masking: at
// (cos θ_o, perceptual roughness) the directional albedo of D·G/(4 cos θ_i cos θ_o) splits into
// scale A and bias B with ∫ f_r cos θ_i dω_i = F0·A + B under Schlick's Fresnel.
inline constexpr int kSplitSumLutSize = 32;
struct SplitSumLut {
    std::vector<glm::vec2> texels;  // row = roughness index, column = cos θ_o index; (A, B)
};
const SplitSumLut& splitSumLut();
// Bilinear lookup, texel centres at (i + ½)/size, clamped at the edges.
glm::vec2 sampleSplitSum(const SplitSumLut& lut, float cosOut, float perceptualRoughness);

}  // namespace glint
