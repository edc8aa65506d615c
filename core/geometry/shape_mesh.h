// The triangles Glint draws for a scene object's shape (UV sphere at its tessellation, plane,
// cube, torus, a placed imported mesh) and each shape's bounding sphere. Used by the GL renderer
// and the CPU reference alike, so both see the same triangles. It does not intersect anything.
#pragma once

#include "geometry/bounding_sphere.h"
#include "geometry/mesh.h"
#include "scene/scene.h"

namespace glint {

// An imported mesh's placement: world = center + scale · (mesh-space position), a uniform scale
// (normals need no change). Procedural shapes are built in world space (identity placement).
struct MeshPlacement {
    glm::vec3 offset{0.0f};
    float scale = 1.0f;
};

MeshPlacement placementOf(const Shape& shape);

// The shape's triangles before placement: procedural shapes in world space; a MeshShape's
// unit-sphere mesh as loaded (an empty mesh when none is loaded).
Mesh proceduralMesh(const Shape& shape);

// The shape's triangles in world space (placement applied).
Mesh worldMesh(const Shape& shape);

BoundingSphere boundingSphere(const Shape& shape);

}  // namespace glint
