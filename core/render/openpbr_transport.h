// What the OpenPBR model adds to a surface beyond its reflection of lights and environment: the
// emission, and the light its transmission lets through from behind. Transmitted light is the
// frame's opaque objects where the backdrop shows them (MissRadiance::transmittedRough, blurred by
// the specular roughness), else the environment's prefiltered level at that roughness;
// a thin-walled surface, a plane or a mesh lets it pass straight on, tinted by
// transmission_color; a volume sphere refracts it in and out (Snell) and absorbs it on the chord
// by Beer-Lambert, transmission_color being the transmittance after transmission_depth; a volume
// plane or mesh with a geometry_thickness d does as three.js does with glTF's thickness: the light
// seen is the backdrop where the refracted ray has gone d, absorbed over d. No internal reflections. GLSL twin: transportOpenpbr in shaders/brdf/openpbr.glsl.
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
    if (!p.thinWalled && !sphere && p.thickness > 0.0f) {
        const glm::vec3 exitPoint = position + p.thickness * refractDirection(incoming, normal, 1.0f / p.specularIor);
        return emission + weight * openPbrVolumeTransmittance(p, p.thickness) *
                              miss.transmittedRough(exitPoint, incoming, incoming, view.specularRoughness, p.specularIor);
    }
    if (p.thinWalled || !outsideSphere)
        return emission + weight * p.transmissionColor *
                              miss.transmittedRough(position, incoming, incoming, view.specularRoughness, p.specularIor);
    const glm::vec3 refracted = refractDirection(incoming, normal, 1.0f / p.specularIor);
    const float chord = sphereExitDistance(*sphere, position, refracted);
    const glm::vec3 exitPoint = position + chord * refracted;
    const glm::vec3 inwardNormal = (sphere->center - exitPoint) / sphere->radius;
    const float exitReflectance = fresnelDielectric(-glm::dot(refracted, inwardNormal), 1.0f / p.specularIor);
    if (exitReflectance >= 1.0f) return emission;
    const glm::vec3 leaving = refractDirection(refracted, inwardNormal, p.specularIor);
    return emission + weight * openPbrVolumeTransmittance(p, chord) * (1.0f - exitReflectance) *
                          miss.transmittedRough(exitPoint, leaving, incoming, view.specularRoughness, p.specularIor);
}

}  // namespace glint
