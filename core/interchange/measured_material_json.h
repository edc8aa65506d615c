// Materials that use a MERL measured BRDF, in scene and material JSON: {"name", "model": "merl",
// "merl_file": PATH}. PATH is relative to the JSON file's folder (absolute when the JSON has no
// file yet). Reading loads and validates the table; no other keys are accepted.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/json_object_reader.h"
#include "scene/scene.h"

namespace glint {

inline constexpr const char* kMeasuredModelId = "merl";

// Reads the rest of a material object whose "merl_file" key is present (name already read).
Material readMeasuredMaterial(ObjectReader& reader, std::string name);
// The material's body; `savedTo` is the JSON file being written ("" keeps the stored path).
nlohmann::json measuredMaterialBody(const Material& material, const std::string& savedTo);

}  // namespace glint
