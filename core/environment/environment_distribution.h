// Importance sampling of an equirectangular radiance image: texels drawn in proportion to the mean
// luminance of the bilinear image over them × their solid angle (a marginal CDF over rows, a conditional CDF over each row's columns,
// Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed., §12.5), a point uniform in the
// texel's (u, v), and the density over solid angle with the equirect's Jacobian
// p(ω) = p(u, v) / (2π² sin θ). Directions in the map's own frame. Used by the Monte-Carlo
// reference (render/environment_sampling.h); the real-time lookups never need it.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "environment/equirect.h"

namespace glint {

struct EnvironmentDirectionSample {
    glm::vec3 direction;  // unit, map space
    float pdf;            // [1/sr]
};

class EnvironmentDistribution {
public:
    EnvironmentDistribution() = default;
    explicit EnvironmentDistribution(const EquirectImage& radiance);

    // A direction for the point u ∈ [0,1)², by inversion of the two CDFs.
    EnvironmentDirectionSample sample(glm::vec2 u) const;
    // The density [1/sr] with which sample() draws `direction` (map space, unit).
    float pdf(glm::vec3 direction) const;

private:
    int width_ = 0, height_ = 0;
    std::vector<float> rowCdf_;     // height_ + 1 entries, 0 … 1
    std::vector<float> columnCdf_;  // height_ rows of width_ + 1 entries, 0 … 1
    std::vector<float> texelProbability_;  // width_ × height_, summing to 1
};

}  // namespace glint
