// Light sources in radiometric units (DESIGN.md): a directional light gives irradiance M
// [W/m²] on a surface perpendicular to it; a point light emits radiant power Φ [W]
// uniformly, giving E = Φ/(4πd²)·cos θ. Colour is a linear-RGB filter on that quantity.
// This file computes what reaches a point; it does not shade.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "math/constants.h"

namespace glint {

enum class LightType { Directional, Point };

struct Light {
    std::string name;
    LightType type = LightType::Directional;
    bool enabled = true;
    glm::vec3 color{1.0f};            // linear RGB filter, usually ≤ 1
    float irradiance = kPi;           // M [W/m²], directional only
    glm::vec3 direction{0, 0, -1};    // direction the light travels, directional only
    float power = 100.0f;             // Φ [W], point only
    glm::vec3 position{0, 2, 2};      // [m], point only
};

// What one light delivers at a point.
struct LightArrival {
    glm::vec3 towardsLight;      // unit vector from the point to the light
    float distance;              // [m]; infinity for directional lights
    glm::vec3 normalIrradiance;  // E⊥ [W/m²] on a surface facing the light, per channel
};

inline LightArrival lightArrival(const Light& light, glm::vec3 point) {
    if (light.type == LightType::Directional) {
        return {-glm::normalize(light.direction), INFINITY, light.color * light.irradiance};
    }
    const glm::vec3 toLight = light.position - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    const float distance = std::sqrt(distanceSquared);
    // Isotropic point source: intensity I = Φ/4π [W/sr], E⊥ = I/d² (inverse-square law).
    const glm::vec3 normalIrradiance = light.color * (light.power / (4.0f * kPi * distanceSquared));
    return {toLight / distance, distance, normalIrradiance};
}


}  // namespace glint
