// The scene file's "environment" object: read with located errors (an unreadable or invalid
// HDR file is reported at its "file" key) and written back. See docs/scene-format.md.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/environment.h"
#include "scene/json_object_reader.h"

namespace glint {

// Reads root["environment"] if present (a relative "file" is taken from the folder of
// `sceneFile`) and loads its map; throws JsonReadError through the reader on any mistake.
Environment readEnvironment(ObjectReader& root, const std::string& sceneFile);

// The "environment" object, or null for none; its file relative to the folder of `sceneFile`
// (absolute when "": util/referenced_path.h).
nlohmann::json environmentToJson(const Environment& environment, const std::string& sceneFile);

}  // namespace glint
