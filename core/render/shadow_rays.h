// Hard shadows for the CPU reference: one shadow ray from a surface point towards a delta light
// (directional, point, spot), the exact twin of the GPU's shadow-map visibility term away from
// penumbrae. Every object occludes, whatever its material; no soft shadows, no transmission.
#pragma once

#include "light/light.h"
#include "render/reference_renderer.h"

namespace glint {

// How far along the surface normal a secondary ray leaving `position` starts [m], so that it does
// not hit the surface it leaves: 1e-4 of the point's largest coordinate, at least 1e-4 m.
float rayOriginOffset(glm::vec3 position);

// 1 when nothing lies between the hit and the light (or the light casts no shadows), else 0.
float lightVisibility(const Scene& scene, const Light& light, const SurfaceHit& hit, const LightArrival& arrival);

}  // namespace glint
