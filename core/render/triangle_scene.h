// The CPU reference's triangles: every object the GPU draws from triangles (geometry/
// shape_mesh.h), in world space, under one BVH; the hit's surface by barycentric interpolation
// (Phong: normal, flat: face normal) and Gouraud's per-vertex shading. Analytic shapes (exact
// spheres, planes not in Gouraud mode) stay with reference_renderer.cpp.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/mesh.h"
#include "render/reference_renderer.h"
#include "render/triangle_bvh.h"
#include "scene/scene.h"

namespace glint {

// Whether the reference intersects this object's triangles (else its analytic surface; a
// plane's flat, Phong and exact pictures are all the analytic plane's).
bool tracedAsTriangles(const SceneObject& object);

class TriangleScene {
public:
    explicit TriangleScene(const Scene& scene);

    // The nearest triangle hit closer than maxDistance, as a SurfaceHit (normal facing the ray).
    std::optional<SurfaceHit> intersect(const Scene& scene, const Ray& ray, float maxDistance) const;
    size_t triangleCount() const { return bvh_.triangleCount(); }

private:
    std::vector<Mesh> meshes_;           // per object, world space (empty when analytic)
    std::vector<int> firstTriangle_;     // per object: index of its first triangle in the BVH
    std::vector<int> objectOfTriangle_;  // per BVH triangle
    TriangleBvh bvh_;
};

// The scene's TriangleScene, built once and reused while the triangle objects stay the same
// (the reference asks per pixel). Thread-safe.
std::shared_ptr<const TriangleScene> triangleSceneFor(const Scene& scene);

// Gouraud: the hit's triangle corners as hits of their own (each with its own normal turned to
// the viewer) and each corner's direction towards the viewer; the reference shades them and
// interpolates with the hit's barycentrics (perspective-correct, as the GPU interpolates).
// Twin of surface.vert's GLINT_GOURAUD. The hit must carry a triangle.
std::array<std::pair<SurfaceHit, glm::vec3>, 3> gouraudCorners(const Scene& scene, const SurfaceHit& hit);

}  // namespace glint
