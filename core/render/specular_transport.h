// Specular transport of the delta-lobe materials (mirror, glass), traced analytically: ideal
// reflection weighted by exact Fresnel; ideal refraction (Snell) through a sphere with internal
// reflections, Beer-Lambert absorption e^(−σ·d) and the (η_t/η_i)² radiance scaling; and the
// classic Hearn-Baker transparency I = (1−k_t)·I_refl + k_t·I_trans. Reflected rays see the
// environment map, or the background when there is none (MissRadiance); transmitted rays see the
// frame's opaque objects where the backdrop shows them (MissRadiance::transmitted).
// GLSL twin: shaders/common/specular_transport.glsl. It does not evaluate f_r for lights.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include <span>

#include "brdf/fresnel.h"
#include "brdf/model_registry.h"
#include "render/miss_radiance.h"

namespace glint {

// A sphere a refracted ray travels inside (centre [m], radius [m]).
struct SphereGeometry {
    glm::vec3 center;
    float radius;
};

// Internal bounces followed inside a glass sphere; what remains after the last is dropped. A ray
// entering a sphere meets every exit at its own refraction angle (by symmetry), which is below
// the critical angle, so the loss is F^6: about 4e-9 at normal incidence for η = 1.5 and large
// only at grazing entry, where almost nothing enters. Total internal reflection (F = 1) happens
// for rays that start inside the glass, e.g. a camera inside a glass sphere.
inline constexpr int kMaxInternalBounces = 6;

// Mirror direction of `incoming` (travelling towards the surface) about the unit normal n.
inline glm::vec3 reflectDirection(glm::vec3 incoming, glm::vec3 normal) {
    return incoming - 2.0f * glm::dot(incoming, normal) * normal;
}

// Snell's law: the refracted direction of `incoming` through a surface whose unit normal faces
// against it, with etaRatio = η_incident/η_transmitted. Only call it without total reflection.
inline glm::vec3 refractDirection(glm::vec3 incoming, glm::vec3 normal, float etaRatio) {
    const float cosIncident = -glm::dot(incoming, normal);
    const float sin2Transmitted = etaRatio * etaRatio * (1.0f - cosIncident * cosIncident);
    const float cosTransmitted = std::sqrt(std::max(0.0f, 1.0f - sin2Transmitted));
    return etaRatio * incoming + (etaRatio * cosIncident - cosTransmitted) * normal;
}

// The far root t of |o + t·d − c| = r for a ray starting inside (or on) the sphere, with the
// discriminant r² − |l|² of Haines et al. (Ray Tracing Gems, 2019, ch. 7).
inline float sphereExitDistance(const SphereGeometry& sphere, glm::vec3 origin, glm::vec3 direction) {
    const glm::vec3 offset = origin - sphere.center;
    const float b = glm::dot(offset, direction);
    const glm::vec3 perpendicular = offset - b * direction;
    return -b + std::sqrt(std::max(0.0f, sphere.radius * sphere.radius - glm::dot(perpendicular, perpendicular)));
}

// Ideal conductor mirror: L_o = F(θ_o; n + iκ) · L_background(reflected direction).
inline glm::vec3 traceMirror(glm::vec3 eta, glm::vec3 kappa, const MissRadiance& miss, glm::vec3 normal,
                             glm::vec3 towardsViewer) {
    const float cosOut = glm::dot(normal, towardsViewer);
    return fresnelConductor(cosOut, eta, kappa) * miss(reflectDirection(-towardsViewer, normal));
}

// How a glass surface splits light: exact Fresnel, or the classic constant k_t.
struct GlassInterface {
    float ior;            // η of the glass (outside is air, η = 1)
    bool classic;         // Hearn-Baker: reflect 1 − k_t, transmit k_t (total reflection stays 1)
    float transmission;   // k_t, classic only
};

// The glass model's interface (brdf/glass.h).
inline GlassInterface glassInterface(const GlassParams& glass) {
    return {glass.ior, glass.transparency == GlassTransparency::Classic, glass.transmission};
}

// Fraction reflected at cos θ_i with relative index η = η_t/η_i; 1 under total reflection.
inline float glassReflectance(const GlassInterface& glass, float cosIncident, float eta) {
    const float fresnel = fresnelDielectric(cosIncident, eta);
    if (!glass.classic || fresnel >= 1.0f) return fresnel;
    return 1.0f - glass.transmission;
}

// A ray inside a glass sphere arriving at the wall point `origin` with direction `direction`
// and throughput `throughput` (absorption so far included): at each wall it splits into the part
// that leaves (Fresnel 1 − F, radiance scaled by 1/η², seeing the background) and the part
// reflected inside (F; 1 under total internal reflection), for kMaxInternalBounces walls. The
// first exit sees the objects behind it too (MissRadiance::transmitted, `viewDirection` the
// primary ray's); the later ones carry at most F² of the light and see the background only.
inline glm::vec3 traceInsideSphere(const GlassInterface& glass, glm::vec3 absorption, const MissRadiance& miss,
                                   const SphereGeometry& sphere, glm::vec3 origin, glm::vec3 direction,
                                   glm::vec3 throughput, glm::vec3 viewDirection) {
    glm::vec3 radiance(0.0f);
    for (int bounce = 0; bounce < kMaxInternalBounces; ++bounce) {
        const glm::vec3 inwardNormal = (sphere.center - origin) / sphere.radius;
        const float exitReflectance = glassReflectance(glass, -glm::dot(direction, inwardNormal), 1.0f / glass.ior);
        if (exitReflectance < 1.0f) {
            const glm::vec3 leaving = refractDirection(direction, inwardNormal, glass.ior);
            radiance += throughput * ((1.0f - exitReflectance) / (glass.ior * glass.ior)) *
                        (bounce == 0 ? miss.transmitted(origin, leaving, viewDirection) : miss(leaving));
        }
        throughput *= exitReflectance;
        direction = reflectDirection(direction, inwardNormal);
        const float chord = sphereExitDistance(sphere, origin, direction);
        origin += chord * direction;
        throughput *= glm::exp(-absorption * chord);  // Beer-Lambert
    }
    return radiance;
}

// Glass at a point with unit normal `normal` (facing the viewer, who is `viewerDistance` [m]
// away). Seen from outside a sphere, the ray reflects and refracts; the refracted ray crosses the
// sphere, losing e^(−σ·d) over each chord d, and at each exit splits into a ray that leaves
// (seeing the background) and one reflected inside, for kMaxInternalBounces. A viewer inside
// the sphere (normal pointing inwards) starts at that split, after e^(−σ·viewerDistance); beyond
// the critical angle the wall reflects totally, and such a ray circles inside for ever: black.
// On a plane (sphere == nullptr) the glass is a thin pane: the transmitted ray leaves unbent
// through two interfaces, weighted (1 − F)², with no absorption and no reflections inside.
// Radiance is scaled by (η_t/η_i)² at each refraction (radiance/η² is invariant, Veach 1997
// §5.2); for a path that enters and leaves into air the factors cancel exactly.
inline glm::vec3 traceGlass(const GlassInterface& glass, glm::vec3 absorption, const MissRadiance& miss,
                            const SphereGeometry* sphere, glm::vec3 position, glm::vec3 normal,
                            glm::vec3 towardsViewer, float viewerDistance) {
    const glm::vec3 incoming = -towardsViewer;
    if (sphere && glm::dot(normal, position - sphere->center) < 0.0f)
        return traceInsideSphere(glass, absorption, miss, *sphere, position, incoming,
                                 glm::exp(-absorption * viewerDistance), incoming);
    const float entryReflectance = glassReflectance(glass, glm::dot(normal, towardsViewer), glass.ior);
    glm::vec3 radiance = entryReflectance * miss(reflectDirection(incoming, normal));
    if (!sphere) {
        const float paneTransmittance = (1.0f - entryReflectance) * (1.0f - entryReflectance);
        return radiance + paneTransmittance * miss.transmitted(position, incoming, incoming);
    }
    const glm::vec3 refracted = refractDirection(incoming, normal, 1.0f / glass.ior);
    const float chord = sphereExitDistance(*sphere, position, refracted);
    const glm::vec3 throughput = (1.0f - entryReflectance) * glass.ior * glass.ior * glm::exp(-absorption * chord);
    return radiance + traceInsideSphere(glass, absorption, miss, *sphere, position + chord * refracted, refracted,
                                        throughput, incoming);
}

// The specular-transport hook of the model registry (ModelInfo::glslTransport): the radiance
// its traced delta lobes send towards the viewer; zero for models without one.
glm::vec3 traceSpecular(BrdfModel model, std::span<const float> values, const MissRadiance& miss,
                        const SphereGeometry* sphere, glm::vec3 position, glm::vec3 normal, glm::vec3 towardsViewer,
                        float viewerDistance);

}  // namespace glint
