// Cosine-weighted directions on the hemisphere around z (Malley's method: a uniform point on
// the unit disc lifted onto the hemisphere), p(ω) = cos θ / π. Local frame: z is the normal.
// Shared by the Monte-Carlo environment lighting and the path tracer.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "math/constants.h"

namespace glint {

inline glm::vec3 cosineDirection(glm::vec2 u) {
    const float radius = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    return {radius * std::cos(phi), radius * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

// The density [1/sr] of cosineDirection for a direction with cos θ = cosTheta.
inline float cosineDirectionPdf(float cosTheta) { return std::max(cosTheta, 0.0f) * kInvPi; }

}  // namespace glint
