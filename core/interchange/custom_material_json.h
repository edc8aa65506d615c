// Materials that use a .brdf file, in scene and material JSON: {"name", "model": "brdf_file",
// "brdf_file": PATH, one key per .brdf parameter}. PATH is relative to the JSON file's folder
// (absolute when the JSON has no file yet). It loads the .brdf; it does not probe or compile it.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/json_object_reader.h"
#include "scene/scene.h"

namespace glint {

inline constexpr const char* kCustomBrdfModelId = "brdf_file";

// Reads the rest of a material object whose "brdf_file" key is present (name already read).
Material readCustomBrdfMaterial(ObjectReader& reader, std::string name);
// The material's body; `savedTo` is the JSON file being written ("" keeps the stored path).
nlohmann::json customBrdfMaterialBody(const Material& material, const std::string& savedTo);

}  // namespace glint
