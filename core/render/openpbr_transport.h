// What the OpenPBR model adds to a surface beyond its reflection of lights and environment: the
// emission, and the light its transmission lets through from behind. Transmitted light is seen
// through the environment's prefiltered level at the specular roughness (rough transmission);
// a thin-walled surface, a plane or a mesh lets it pass straight on, tinted by
// transmission_color; a volume sphere refracts it in and out (Snell) and absorbs it on the chord
// by Beer-Lambert, transmission_color being the transmittance after transmission_depth. No
// internal reflections. GLSL twin: transportOpenpbr in shaders/brdf/openpbr.glsl.
#pragma once

#include <glm/glm.hpp>

#include "brdf/openpbr.h"
#include "render/miss_radiance.h"
#include "render/specular_transport.h"

namespace glint {

// Transmittance over a path of `distance` metres: transmission_color^(d/depth), or the colour
// itself as a tint when the depth is 0.
inline glm::vec3 openPbrVolumeTransmittance(const OpenPbrParams& p, float distance) {
    if (p.transmissionDepth <= 0.0f) return p.transmissionColor;
    return glm::pow(glm::max(p.transmissionColor, glm::vec3(0.0f)), glm::vec3(distance / p.transmissionDepth));
}

inline glm::vec3 transportOpenpbr(const OpenPbrParams& p, const MissRadiance& miss, const SphereGeometry* sphere,
                                  glm::vec3 position, glm::vec3 normal, glm::vec3 towardsViewer) {
    const OpenPbrView view = openPbrView(p, glm::dot(normal, towardsViewer));
    const glm::vec3 emission = emissionOpenPbr(p, view);
    if (p.transmissionWeight <= 0.0f) return emission;
    const glm::vec3 weight = openPbrResponse(p, view).transmission;
    const glm::vec3 incoming = -towardsViewer;
    const bool outsideSphere = sphere && glm::dot(normal, position - sphere->center) > 0.0f;
    if (p.thinWalled || !outsideSphere)
        return emission + weight * p.transmissionColor * miss.rough(incoming, view.specularRoughness);
    const glm::vec3 refracted = refractDirection(incoming, normal, 1.0f / p.specularIor);
    const float chord = sphereExitDistance(*sphere, position, refracted);
    const glm::vec3 inwardNormal = (sphere->center - (position + chord * refracted)) / sphere->radius;
    const float exitReflectance = fresnelDielectric(-glm::dot(refracted, inwardNormal), 1.0f / p.specularIor);
    if (exitReflectance >= 1.0f) return emission;
    const glm::vec3 leaving = refractDirection(refracted, inwardNormal, p.specularIor);
    return emission + weight * openPbrVolumeTransmittance(p, chord) * (1.0f - exitReflectance) *
                          miss.rough(leaving, view.specularRoughness);
}

}  // namespace glint
