// The "textures" object of a material in scene and material files (docs/scene-format.md):
// reading it with located errors (unknown parameter, a parameter that cannot be textured, a
// missing or unreadable image) and writing it back with paths relative to the file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/json_object_reader.h"
#include "scene/scene.h"

namespace glint {

// Reads material["textures"] into material.textures (its model already set); image files
// are resolved against the directory of the JSON file, confined to it
// (ObjectReader::referencedFile) and decoded. Throws JsonReadError through `materialReader`, as
// every reader of the file format does.
void readMaterialTextures(ObjectReader& materialReader, AnalyticMaterial& material);

// The "textures" object, or null when the material has none. Image paths are written relative
// to the directory of `targetFile` (absolute when it is empty).
nlohmann::json materialTexturesToJson(const AnalyticMaterial& material, const std::string& targetFile);

}  // namespace glint
