// Light sources in radiometric units (docs/architecture.md): a directional light gives irradiance M
// [W/m²] on a surface perpendicular to it; a point light emits radiant power Φ [W]
// uniformly, giving E = Φ/(4πd²)·cos θ; a spot light is the same point light limited to a cone
// (Hearn-Baker falloff cos^a α, smooth edge); an ambient light is a uniform radiance L_a
// [W/(sr·m²)] from every direction. Colour is a linear-RGB filter on that quantity.
// This file computes what reaches a point; it does not shade. GLSL twin: shaders/common/lights.glsl.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "light/shadow_settings.h"
#include "math/constants.h"

namespace glint {

enum class LightType { Directional, Point, Spot, Ambient };

// The classic textbook radial attenuation f(d) = 1/(a0 + a1·d + a2·d²) (Hearn-Baker). NOT
// physical: when enabled it replaces the inverse-square law 1/d² of point and spot lights
// (coefficients {0, 0, 1} give the physical law back). Off by default.
struct ClassicAttenuation {
    bool enabled = false;
    glm::vec3 coefficients{0.0f, 0.0f, 1.0f};  // a0 [1], a1 [1/m], a2 [1/m²]
};

struct Light {
    std::string name;
    LightType type = LightType::Directional;
    bool enabled = true;
    glm::vec3 color{1.0f};            // linear RGB filter, usually ≤ 1
    float irradiance = kPi;           // M [W/m²], directional only
    glm::vec3 direction{0, 0, -1};    // direction the light travels: directional, and a spot's axis
    float power = 100.0f;             // Φ [W] of the isotropic point light (point and spot)
    glm::vec3 position{0, 2, 2};      // [m], point and spot
    float coneHalfAngleDegrees = 30.0f;  // spot: θ_c ∈ (0°, 90°], nothing outside it
    float falloffExponent = 0.0f;        // spot: a in the Hearn-Baker falloff cos^a α
    float edgeWidthDegrees = 5.0f;       // spot: smooth edge w ∈ [0, θ_c] inside the cone
    float ambientRadiance = 0.1f;        // L_a [W/(sr·m²)], ambient only
    ClassicAttenuation attenuation;      // point and spot only; off by default
    bool castsShadows = false;           // delta lights only (light/shadow_settings.h)
    ShadowSettings shadow;
};

// A spot light's angular factor for cos α, α the angle between its axis and the direction
// from the light to the point (Hearn-Baker §17: I_l·cos^a α inside the cone, 0 outside),
// times a smooth edge: smoothstep in cos α from cos θ_c (0) to cos(θ_c − w) (1).
inline float spotFactor(float cosAlpha, float cosOuter, float cosInner, float falloffExponent) {
    if (cosAlpha <= 0.0f || cosAlpha <= cosOuter) return 0.0f;
    float edge = 1.0f;
    if (cosAlpha < cosInner) {
        const float t = (cosAlpha - cosOuter) / (cosInner - cosOuter);
        edge = t * t * (3.0f - 2.0f * t);  // GLSL smoothstep
    }
    return std::pow(cosAlpha, falloffExponent) * edge;
}

inline float spotCosOuter(const Light& light) { return std::cos(glm::radians(light.coneHalfAngleDegrees)); }
inline float spotCosInner(const Light& light) {
    return std::cos(glm::radians(light.coneHalfAngleDegrees - light.edgeWidthDegrees));
}

// The radiant intensity [W/sr] of the isotropic point light with power Φ: I = Φ/4π.
// A spot light's intensity is this times spotFactor(): Φ is NOT the power the spot emits.
inline glm::vec3 pointIntensity(const Light& light) { return light.color * (light.power / (4.0f * kPi)); }

// The factor that turns intensity I [W/sr] into E⊥ [W/m²] at distance d: 1/d² (inverse-square
// law) or, with the classic option, 1/(a0 + a1·d + a2·d²).
inline float distanceFactor(const ClassicAttenuation& attenuation, float distance) {
    if (!attenuation.enabled) return 1.0f / (distance * distance);
    const glm::vec3& a = attenuation.coefficients;
    return 1.0f / (a.x + a.y * distance + a.z * distance * distance);
}

// What one delta light (directional, point, spot) delivers at a point. Ambient lights deliver
// radiance from every direction instead; see ambientRadiance().
struct LightArrival {
    glm::vec3 towardsLight;      // unit vector from the point to the light
    float distance;              // [m]; infinity for directional lights
    glm::vec3 normalIrradiance;  // E⊥ [W/m²] on a surface facing the light, per channel
};

inline LightArrival lightArrival(const Light& light, glm::vec3 point) {
    if (light.type == LightType::Directional) {
        return {-glm::normalize(light.direction), INFINITY, light.color * light.irradiance};
    }
    if (light.type == LightType::Ambient) return {glm::vec3(0, 0, 1), INFINITY, glm::vec3(0.0f)};
    const glm::vec3 toLight = light.position - point;
    const float distance = std::sqrt(glm::dot(toLight, toLight));
    const glm::vec3 towardsLight = toLight / distance;
    // Isotropic point source: intensity I = Φ/4π [W/sr], E⊥ = I/d² (inverse-square law).
    glm::vec3 normalIrradiance = pointIntensity(light) * distanceFactor(light.attenuation, distance);
    if (light.type == LightType::Spot) {
        const float cosAlpha = glm::dot(-towardsLight, glm::normalize(light.direction));
        normalIrradiance *= spotFactor(cosAlpha, spotCosOuter(light), spotCosInner(light), light.falloffExponent);
    }
    return {towardsLight, distance, normalIrradiance};
}

// The uniform radiance L_a [W/(sr·m²)] of an ambient light, per channel (zero for the others).
inline glm::vec3 ambientRadiance(const Light& light) {
    return light.type == LightType::Ambient && light.enabled ? light.color * light.ambientRadiance : glm::vec3(0.0f);
}

}  // namespace glint
