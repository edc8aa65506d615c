// The JSON of each shape of a scene object (sphere, plane, cube, torus, mesh): located reads,
// writes, and mesh paths kept relative to the scene file. The object's common keys (name,
// shape, interpolation, material) are read by scene_json.cpp.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/json_object_reader.h"
#include "scene/scene.h"

namespace glint {

SphereShape readSphereShape(ObjectReader& reader);
PlaneShape readPlaneShape(ObjectReader& reader);
// `shapeIndex` is 2 cube, 3 torus, 4 mesh (Shape's alternatives). A mesh is imported here, its
// path resolved against the folder of the scene file and confined to it
// (ObjectReader::referencedFile); an import error fails at the "path" key.
Shape readMeshLikeShape(ObjectReader& reader, int shapeIndex);

// The shape's own keys (not "shape" itself). A mesh's path is written relative to the folder of
// `sceneFile`, or absolute when it is "" (util/referenced_path.h).
nlohmann::json shapeToJson(const Shape& shape, const std::string& sceneFile);

}  // namespace glint
