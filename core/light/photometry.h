// Photometric equivalents of the radiometric light quantities, for display beside them
// (docs/architecture.md: never instead of them): lm for Φ, lx for irradiance, cd for intensity, nit for
// radiance. It does not change how anything is rendered.
#pragma once

#include <glm/glm.hpp>

#include "light/light.h"

namespace glint {

// Relative luminance Y of a linear Rec. 709 colour (ITU-R BT.709): white (1,1,1) has Y = 1.
inline float relativeLuminance(glm::vec3 linearRgb) {
    return 0.2126f * linearRgb.r + 0.7152f * linearRgb.g + 0.0722f * linearRgb.b;
}

// Each: kLumensPerWatt = 683 lm/W (math/constants.h) × the radiometric quantity weighted by Y of its linear-RGB colour, so that
// 1 W of white light is 683 lm. `rgb` is the per-channel radiometric value (colour × amount).
inline float luminousFlux(glm::vec3 radiantPowerRgb) { return kLumensPerWatt * relativeLuminance(radiantPowerRgb); }      // lm
inline float illuminance(glm::vec3 irradianceRgb) { return kLumensPerWatt * relativeLuminance(irradianceRgb); }          // lx = lm/m²
inline float luminousIntensity(glm::vec3 intensityRgb) { return kLumensPerWatt * relativeLuminance(intensityRgb); }      // cd = lm/sr
inline float luminance(glm::vec3 radianceRgb) { return kLumensPerWatt * relativeLuminance(radianceRgb); }                // nit = cd/m²

// What a light panel shows beside the radiometric values; a field is zero where it does not
// apply to the light's type.
struct LightPhotometry {
    float lumens = 0;       // point and spot: flux of the isotropic point light with power Φ
    float candelas = 0;     // point: I = Φ/4π; spot: on its axis (cos^a 0 = 1, edge 1)
    float lux = 0;          // directional: illuminance on a perpendicular surface
    float nits = 0;         // ambient: luminance of the uniform radiance
};

inline LightPhotometry lightPhotometry(const Light& light) {
    LightPhotometry photometry;
    switch (light.type) {
        case LightType::Directional: photometry.lux = illuminance(light.color * light.irradiance); break;
        case LightType::Point:
        case LightType::Spot:
            photometry.lumens = luminousFlux(light.color * light.power);
            photometry.candelas = luminousIntensity(pointIntensity(light));
            break;
        case LightType::Ambient: photometry.nits = luminance(light.color * light.ambientRadiance); break;
    }
    return photometry;
}

}  // namespace glint
