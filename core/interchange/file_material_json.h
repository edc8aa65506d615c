// Materials whose BRDF lives in a file of its own, in scene and material JSON:
//   a .brdf program:  {"name", "model": "brdf_file", "brdf_file": PATH, one key per .brdf parameter}
//   a MERL table:     {"name", "model": "merl", "merl_file": PATH} (no other keys)
// PATH is relative to the JSON file's folder (absolute when the JSON has no file yet). Reading
// loads and validates the file; it does not probe or compile a .brdf.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/json_object_reader.h"
#include "scene/scene.h"

namespace glint {

inline constexpr const char* kCustomBrdfModelId = "brdf_file";
inline constexpr const char* kMeasuredModelId = "merl";

// Read the rest of a material object whose "brdf_file" (or "merl_file") key is present (name already read).
Material readCustomBrdfMaterial(ObjectReader& reader, std::string name);
Material readMeasuredMaterial(ObjectReader& reader, std::string name);
// The material's body; `savedTo` is the JSON file being written ("" keeps the stored path).
nlohmann::json customBrdfMaterialBody(const std::string& name, const CustomMaterial& material, const std::string& savedTo);
nlohmann::json measuredMaterialBody(const std::string& name, const MeasuredMaterial& material, const std::string& savedTo);

}  // namespace glint
