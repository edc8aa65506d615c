// The terms of the CPU reference's shadeHit() kept one by one (per light, ambient, environment,
// traced delta lobes), for the classroom surface probe. Computed by the reference renderer's own
// code (reference_renderer.cpp), never a second copy of it; it adds no shading of its own.
#pragma once

#include <vector>

#include "light/light.h"
#include "math/frame.h"
#include "render/reference_renderer.h"

namespace glint {

// The terms of shadeHit at one hit, for the classroom surface probe (classroom/surface_probe.h):
// the same computation, kept term by term. It ignores Gouraud interpolation (it evaluates the
// terms at the hit itself); shadeHit interpolates the corners' radiance for Gouraud surfaces.
struct DirectLightTerm {
    int lightIndex;          // into Scene::lights (enabled delta lights only)
    LightArrival arrival;    // L, distance, E⊥
    float cosTheta;          // N·L in the shading frame; ≤ 0: the light is behind the surface
    float visibility;        // shadow ray: 1 lit, 0 shadowed (0 too when behind the surface)
    glm::vec3 brdf;          // f_r(L, V) [1/sr]
    glm::vec3 radiance;      // f_r·E⊥·cos θ·V [W/(sr·m²)]
};
struct ShadingBreakdown {
    ShadingFrame frame;                 // after normal mapping
    std::vector<float> values;          // the material's values at the point (after textures)
    std::vector<DirectLightTerm> lights;
    glm::vec3 ambientReflectance{0.0f};  // k_a
    glm::vec3 ambientRadiance{0.0f};     // Σ L_a of the ambient lights [W/(sr·m²)]
    glm::vec3 environment{0.0f};         // the environment light's reflected radiance
    glm::vec3 specular{0.0f};            // the traced delta lobes (mirror, glass)
    glm::vec3 total{0.0f};               // the sum: shadeHit's value away from Gouraud surfaces
};
ShadingBreakdown shadingBreakdown(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer,
                                  const ReferenceOptions& options = {}, uint32_t pixelSeed = 0);

}  // namespace glint
