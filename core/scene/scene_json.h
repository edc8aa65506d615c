// Scene and material files: versioned JSON, loaded with located errors and saved atomically.
// The format is documented field by field in docs/scene-format.md.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// Parses scene JSON text; `file` names it in messages.
Result<Scene> parseScene(const std::string& text, const std::string& file);
Result<Scene> loadScene(const std::string& path);

// `savedTo`: the file being written, so that .brdf paths are written relative to its folder.
nlohmann::json sceneToJson(const Scene& scene, const std::string& savedTo = "");
Status saveScene(const Scene& scene, const std::string& path);

// A material file holds one material ("format": "glint-material").
Result<Material> parseMaterial(const std::string& text, const std::string& file);
Result<Material> loadMaterial(const std::string& path);
nlohmann::json materialToJson(const Material& material, const std::string& savedTo = "");
Status saveMaterial(const Material& material, const std::string& path);

}  // namespace glint
