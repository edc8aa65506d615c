// Hard shadows for the CPU reference: one shadow ray from a surface point towards a delta light
// (directional, point, spot), the exact twin of the GPU's shadow-map visibility term away from
// penumbrae. Every object occludes, whatever its material; no soft shadows, no transmission.
#pragma once

#include "light/light.h"
#include "render/reference_renderer.h"

namespace glint {

// Offset of a shadow ray's origin along the surface normal [m], relative to the point's scale,
// so that the ray does not hit the surface it leaves.
inline constexpr float kShadowRayOffset = 1e-4f;

// 1 when nothing lies between the hit and the light (or the light casts no shadows), else 0.
float lightVisibility(const Scene& scene, const Light& light, const SurfaceHit& hit, const LightArrival& arrival);

}  // namespace glint
