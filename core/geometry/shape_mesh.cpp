// Shape → triangles and bounding spheres (see shape_mesh.h).
#include "geometry/shape_mesh.h"

#include <cmath>

namespace glint {

MeshPlacement placementOf(const Shape& shape) {
    if (const auto* mesh = std::get_if<MeshShape>(&shape)) return {mesh->center, mesh->scale};
    return {};
}

Mesh proceduralMesh(const Shape& shape) {
    if (const auto* sphere = std::get_if<SphereShape>(&shape))
        return makeUvSphere(sphere->center, sphere->radius, sphere->segments, sphere->rings);
    if (const auto* plane = std::get_if<PlaneShape>(&shape)) return makePlane(plane->center, plane->normal, plane->size);
    if (const auto* cube = std::get_if<CubeShape>(&shape)) {
        Mesh mesh = makeCube(cube->center, cube->size);
        rotateMesh(mesh, cube->center, cube->rotationDegrees);
        return mesh;
    }
    if (const auto* torus = std::get_if<TorusShape>(&shape)) {
        Mesh mesh = makeTorus(torus->center, torus->majorRadius, torus->minorRadius, torus->segments, torus->rings);
        rotateMesh(mesh, torus->center, torus->rotationDegrees);
        return mesh;
    }
    const auto& mesh = std::get<MeshShape>(shape);
    return mesh.mesh ? *mesh.mesh : Mesh{};
}

Mesh worldMesh(const Shape& shape) {
    Mesh mesh = proceduralMesh(shape);
    const MeshPlacement placement = placementOf(shape);
    for (Vertex& vertex : mesh.vertices) vertex.position = placement.offset + placement.scale * vertex.position;
    return mesh;
}

BoundingSphere boundingSphere(const Shape& shape) {
    if (const auto* sphere = std::get_if<SphereShape>(&shape)) return {sphere->center, sphere->radius};
    if (const auto* plane = std::get_if<PlaneShape>(&shape)) return {plane->center, 0.5f * glm::length(plane->size)};
    if (const auto* cube = std::get_if<CubeShape>(&shape)) return {cube->center, 0.5f * std::sqrt(3.0f) * cube->size};
    if (const auto* torus = std::get_if<TorusShape>(&shape)) return {torus->center, torus->majorRadius + torus->minorRadius};
    const auto& mesh = std::get<MeshShape>(shape);
    return {mesh.center, mesh.scale};  // the importer scales meshes into the unit sphere
}

}  // namespace glint
