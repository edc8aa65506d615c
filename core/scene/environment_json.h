// The scene file's "environment" object: read with located errors (an unreadable or invalid
// HDR file is reported at its "file" key) and written back. See docs/scene-format.md.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/environment.h"
#include "scene/json_object_reader.h"

namespace glint {

// Whether reading a scene makes its environment's map (a file is read and precomputed: seconds for
// a large one) or leaves it null, its file made absolute, for the caller to make (the editor, on a
// worker thread: editor/environment_loading.h).
enum class EnvironmentMapLoading { Now, Later };

// Reads root["environment"] if present (a relative "file" is taken from the folder of the scene
// file, and confined to it: ObjectReader::referencedFile) and, Now, loads its map; throws
// JsonReadError through the reader on any mistake.
Environment readEnvironment(ObjectReader& root, EnvironmentMapLoading loading);

// The "environment" object, or null for none; its file relative to the folder of `sceneFile`
// (absolute when "": util/referenced_path.h).
nlohmann::json environmentToJson(const Environment& environment, const std::string& sceneFile);

}  // namespace glint
