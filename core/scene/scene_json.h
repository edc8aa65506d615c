// Scene and material files: versioned JSON, loaded with located errors and saved atomically.
// The format is documented field by field in docs/scene-format.md.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/environment_json.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// Parses scene JSON text; `file` names it in messages, and relative texture paths are resolved
// against its directory (texture images are decoded while reading: a failing one fails the parse;
// the environment's map too unless `environment` is Later).
Result<Scene> parseScene(const std::string& text, const std::string& file,
                         EnvironmentMapLoading environment = EnvironmentMapLoading::Now);
Result<Scene> loadScene(const std::string& path, EnvironmentMapLoading environment = EnvironmentMapLoading::Now);

// `file`: where the JSON will be written; texture and .brdf paths are made relative to it ("" keeps
// them absolute).
nlohmann::json sceneToJson(const Scene& scene, const std::string& file = "");
Status saveScene(const Scene& scene, const std::string& path);

// A material file holds one material ("format": "glint-material").
Result<Material> parseMaterial(const std::string& text, const std::string& file);
Result<Material> loadMaterial(const std::string& path);
nlohmann::json materialToJson(const Material& material, const std::string& file = "");
Status saveMaterial(const Material& material, const std::string& path);

}  // namespace glint
