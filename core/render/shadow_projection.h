// Where a light's shadow map looks: the scene's bounding sphere, and for each delta light the
// projection of its map (orthographic fitted to the bounds for directional lights, perspective
// over the cone for spot lights, six 90° faces for point lights and very wide spots).
// Pure maths for core/gl/shadow_maps.cpp; it renders nothing.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "geometry/bounding_sphere.h"
#include "scene/scene.h"

namespace glint {

// A sphere around every object of the scene (the box around them, circumscribed).
BoundingSphere sceneBounds(const Scene& scene);

enum class ShadowMapKind { Orthographic = 0, Perspective = 1, Cube = 2 };

// Spot cones wider than this half angle get a cube map, as a point light: one perspective map
// cannot cover a cone near 90°.
inline constexpr float kWidestPerspectiveSpotDegrees = 80.0f;

struct ShadowProjection {
    ShadowMapKind kind = ShadowMapKind::Orthographic;
    glm::mat4 viewProjection{1.0f};  // world → clip of the 2D map (orthographic, perspective)
    glm::vec3 lightPosition{0.0f};   // perspective and cube
    float nearPlane = 0.0f, farPlane = 1.0f;  // [m] from the light (cube: far also scales the stored distance)
    // World size of the map's side per unit of clip w: 2R (orthographic, w = 1), 2·tan(fov/2)
    // (perspective, w = depth along the axis), 2 (a cube face, at its major-axis distance).
    float sideScale = 2.0f;
};

// The projection of a delta light's shadow map over `bounds`; nothing for ambient lights.
std::optional<ShadowProjection> shadowProjection(const Light& light, const BoundingSphere& bounds);

// World → clip for cube face `face` (GL order +X, −X, +Y, −Y, +Z, −Z) of a cube projection.
glm::mat4 cubeFaceViewProjection(const ShadowProjection& projection, int face);

}  // namespace glint
