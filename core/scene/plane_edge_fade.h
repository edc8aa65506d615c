// A plane's edge fade: how much of what lies behind the plane (the primary miss radiance) shows
// through at a point on it. 0 out to (1 − edgeFade)·R from the centre, smoothstep to 1 at R, half
// the smaller side, so that the corners and edges vanish (the preview stage's floor). CPU half; the
// GLSL twin is shaders/common/plane_edge_fade.glsl.
#pragma once

#include <algorithm>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace glint {

// The radii [m] where the fade starts and ends; none (0, 0) when the plane has no fade.
inline glm::vec2 planeEdgeFadeRadii(const PlaneShape& plane) {
    if (plane.edgeFade <= 0.0f) return glm::vec2(0.0f);
    const float outer = 0.5f * std::min(plane.size.x, plane.size.y);
    return {(1.0f - plane.edgeFade) * outer, outer};
}

// 0: the plane's own radiance, 1: the background's. `position` lies on the plane.
inline float planeEdgeFade(glm::vec3 center, glm::vec2 radii, glm::vec3 position) {
    if (radii.y <= 0.0f) return 0.0f;
    const float t = std::clamp((glm::length(position - center) - radii.x) / std::max(radii.y - radii.x, 1e-6f), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace glint
