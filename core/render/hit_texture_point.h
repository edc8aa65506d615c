// Where a ray's hit lies on its object's textures: the shape's analytic (u, v), or for shapes
// drawn from triangles the vertex UV interpolated at the hit. Shared by the reference renderer
// and the path tracer; the texture evaluation itself is texture/texture_eval.h's.
#pragma once

#include <optional>

#include "render/reference_renderer.h"
#include "texture/texture_eval.h"

namespace glint {

inline TexturePoint hitTexturePoint(const Scene& scene, const SurfaceHit& hit) {
    std::optional<glm::vec2> triangleUv;
    if (hit.triangle)
        triangleUv = hit.triangle->barycentric[0] * hit.triangle->vertices[0].uv +
                     hit.triangle->barycentric[1] * hit.triangle->vertices[1].uv +
                     hit.triangle->barycentric[2] * hit.triangle->vertices[2].uv;
    return texturePointOn(scene.objects.at(hit.objectIndex).shape, hit.position, triangleUv);
}

}  // namespace glint
