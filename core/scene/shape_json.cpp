// Shape JSON (see shape_json.h).
#include "scene/shape_json.h"

#include "geometry/mesh_import.h"
#include "scene/json_vectors.h"
#include "util/referenced_file_error.h"
#include "util/referenced_path.h"

namespace glint {
namespace {

using nlohmann::json;

// "rotation": [x, y, z] in degrees, turned about x, then y, then z, about the shape's centre.
glm::vec3 readRotation(ObjectReader& reader) { return reader.vec3("rotation", glm::vec3(0.0f), Bounds::between(-3600.0, 3600.0)); }

MeshShape readMeshShape(ObjectReader& reader) {
    MeshShape mesh;
    mesh.path = reader.requiredString("path");
    if (mesh.path.empty()) reader.fail("path", "must name a mesh file");
    mesh.resolvedPath = reader.referencedFile("path").string();
    mesh.center = reader.vec3("center", mesh.center);
    mesh.scale = static_cast<float>(reader.number("scale", mesh.scale, Bounds::positive()));
    mesh.smoothingAngleDegrees = static_cast<float>(
        reader.number("smoothing_angle_degrees", mesh.smoothingAngleDegrees, Bounds::between(0.0, 180.0)));
    const std::string up = reader.string("up", "y");
    if (up != "y" && up != "z") reader.fail("up", "expected \"y\" or \"z\" (the file's axis that points up)");
    mesh.upAxis = up == "z" ? MeshUpAxis::Z : MeshUpAxis::Y;
    mesh.rotationDegrees = readRotation(reader);
    mesh.part = reader.integer("part", mesh.part, -1, 1'000'000);
    const MeshImportOptions options{mesh.smoothingAngleDegrees, mesh.upAxis};
    auto imported = mesh.part < 0 ? importMesh(mesh.resolvedPath, options) : importMeshPart(mesh.resolvedPath, options, mesh.part);
    if (!imported) reader.fail("path", referencedFileProblem(mesh.resolvedPath, imported.error(), "mesh"));
    if (mesh.rotationDegrees != glm::vec3(0.0f)) {  // about the mesh's centre, the origin of its unit sphere
        Mesh turned = *imported->mesh;
        rotateMesh(turned, glm::vec3(0.0f), mesh.rotationDegrees);
        imported->mesh = std::make_shared<const Mesh>(std::move(turned));
    }
    mesh.mesh = imported->mesh;
    mesh.statistics = imported->statistics;
    return mesh;
}

}  // namespace

SphereShape readSphereShape(ObjectReader& reader) {
    SphereShape sphere;
    sphere.center = reader.vec3("center", sphere.center);
    sphere.radius = static_cast<float>(reader.number("radius", sphere.radius, Bounds::positive()));
    sphere.segments = reader.integer("segments", sphere.segments, 3, 1024);
    sphere.rings = reader.integer("rings", sphere.rings, 2, 512);
    return sphere;
}

PlaneShape readPlaneShape(ObjectReader& reader) {
    PlaneShape plane;
    plane.center = reader.vec3("center", plane.center);
    plane.normal = reader.vec3("normal", plane.normal);
    if (glm::length(plane.normal) < 1e-6f) reader.fail("normal", "must not be the zero vector");
    plane.normal = glm::normalize(plane.normal);
    plane.size = reader.vec2("size", plane.size, Bounds::positive());
    plane.edgeFade = static_cast<float>(reader.number("edge_fade", plane.edgeFade, Bounds::between(0.0, 1.0)));
    return plane;
}

Shape readMeshLikeShape(ObjectReader& reader, int shapeIndex) {
    if (shapeIndex == 2) {
        CubeShape cube;
        cube.center = reader.vec3("center", cube.center);
        cube.size = static_cast<float>(reader.number("size", cube.size, Bounds::positive()));
        cube.rotationDegrees = readRotation(reader);
        return cube;
    }
    if (shapeIndex == 3) {
        TorusShape torus;
        torus.center = reader.vec3("center", torus.center);
        torus.majorRadius = static_cast<float>(reader.number("major_radius", torus.majorRadius, Bounds::positive()));
        torus.minorRadius = static_cast<float>(reader.number("minor_radius", torus.minorRadius, Bounds::positive()));
        torus.segments = reader.integer("segments", torus.segments, 3, 1024);
        torus.rings = reader.integer("rings", torus.rings, 3, 512);
        torus.rotationDegrees = readRotation(reader);
        return torus;
    }
    return readMeshShape(reader);
}

json shapeToJson(const Shape& shape, const std::string& sceneFile) {
    if (const auto* sphere = std::get_if<SphereShape>(&shape))
        return {{"center", vec3Json(sphere->center)}, {"radius", sphere->radius}, {"segments", sphere->segments},
                {"rings", sphere->rings}};
    if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        json out = {{"center", vec3Json(plane->center)}, {"normal", vec3Json(plane->normal)}, {"size", {plane->size.x, plane->size.y}}};
        if (plane->edgeFade > 0.0f) out["edge_fade"] = plane->edgeFade;  // absent: a hard edge
        return out;
    }
    json out;
    if (const auto* cube = std::get_if<CubeShape>(&shape)) {
        out = {{"center", vec3Json(cube->center)}, {"size", cube->size}};
        if (cube->rotationDegrees != glm::vec3(0.0f)) out["rotation"] = vec3Json(cube->rotationDegrees);
        return out;
    }
    if (const auto* torus = std::get_if<TorusShape>(&shape)) {
        out = {{"center", vec3Json(torus->center)}, {"major_radius", torus->majorRadius}, {"minor_radius", torus->minorRadius},
               {"segments", torus->segments}, {"rings", torus->rings}};
        if (torus->rotationDegrees != glm::vec3(0.0f)) out["rotation"] = vec3Json(torus->rotationDegrees);
        return out;
    }
    const auto& mesh = std::get<MeshShape>(shape);
    const std::string& file = mesh.resolvedPath.empty() ? mesh.path : mesh.resolvedPath;
    out = {{"path", referencedPathFor(file, sceneFile)}, {"center", vec3Json(mesh.center)}, {"scale", mesh.scale},
           {"smoothing_angle_degrees", mesh.smoothingAngleDegrees}};
    if (mesh.part >= 0) out["part"] = mesh.part;
    if (mesh.upAxis == MeshUpAxis::Z) out["up"] = "z";
    if (mesh.rotationDegrees != glm::vec3(0.0f)) out["rotation"] = vec3Json(mesh.rotationDegrees);
    return out;
}

}  // namespace glint
