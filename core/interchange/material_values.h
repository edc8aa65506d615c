// Reading and writing one named parameter of a Material's packed values, for the importers and
// exporters that map other formats onto Glint's parameter tables. No validation: callers check
// ranges against the table (checkMaterialRanges) before handing a material out.
#pragma once

#include <string>
#include <optional>
#include <string_view>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// The value of parameter `name` as RGB (a scalar or enum is repeated in all three).
glm::vec3 paramValue(const Material& material, std::string_view name);
float paramScalar(const Material& material, std::string_view name);
void setParam(Material& material, std::string_view name, glm::vec3 value);
void setParam(Material& material, std::string_view name, float value);

// The first parameter outside its table's valid range, as a message naming it and the range
// (e.g. "'exponent': -1 is out of range: must be at least 0"), or nothing when all are valid.
std::optional<std::string> findOutOfRange(const Material& material);

}  // namespace glint
