// Analytic occlusion of the environment light by spheres: the share of a receiver's
// cosine-weighted hemisphere that a sphere of radius r at distance D covers, cos θ·(r/D)² (the
// projected solid angle of the sphere's cap over π; exact while the sphere lies above the
// receiver's horizon), θ between the normal and the sphere's centre. Each sphere of the scene
// (the first kMaxOccludingSpheres) multiplies the environment term by 1 − that share: the
// preview stage's contact shadow under the ball. A sphere never occludes its own surface
// (cos θ < 0 there). CPU half; the GLSL twin is shaders/common/sphere_occlusion.glsl.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace glint {

inline constexpr int kMaxOccludingSpheres = 8;

// xyz: centre [m], w: radius [m], of the scene's first kMaxOccludingSpheres spheres.
inline std::vector<glm::vec4> occludingSpheres(const Scene& scene) {
    std::vector<glm::vec4> spheres;
    for (const SceneObject& object : scene.objects)
        if (const auto* sphere = std::get_if<SphereShape>(&object.shape); sphere && spheres.size() < kMaxOccludingSpheres)
            spheres.emplace_back(sphere->center, sphere->radius);
    return spheres;
}

// The factor on the environment term at `position` with unit `normal`.
inline float environmentVisibility(const std::vector<glm::vec4>& spheres, glm::vec3 position, glm::vec3 normal) {
    float visibility = 1.0f;
    for (const glm::vec4& sphere : spheres) {
        const glm::vec3 toCentre = glm::vec3(sphere) - position;
        const float distanceSquared = std::max(glm::dot(toCentre, toCentre), sphere.w * sphere.w);
        const float cosTheta = std::max(glm::dot(normal, toCentre) * glm::inversesqrt(distanceSquared), 0.0f);
        visibility *= 1.0f - std::min(cosTheta * sphere.w * sphere.w / distanceSquared, 1.0f);
    }
    return visibility;
}

}  // namespace glint
