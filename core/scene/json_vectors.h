// GLM vectors as JSON arrays ([x, y, z]), shared by the scene writer and the glTF exporter.
// Reading them back, with located errors, is json_object_reader.h's job.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace glint {

inline nlohmann::json vec3Json(glm::vec3 v) { return {v.x, v.y, v.z}; }

}  // namespace glint
