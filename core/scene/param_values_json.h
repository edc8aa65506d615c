// A parameter table's values in JSON: one key per parameter (numbers, [r, g, b] or one grey
// number, booleans, enum ids), read with located errors against the table's valid ranges.
// Shared by built-in materials (scene_json.cpp) and .brdf materials (file_material_json.cpp).
#pragma once

#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdf/param_table.h"
#include "scene/json_object_reader.h"

namespace glint {

// The table's defaults, overridden by the keys present; throws through reader.fail on bad values.
std::vector<float> readParamValues(ObjectReader& reader, std::span<const ParamSpec> table);
void writeParamValues(nlohmann::json& out, std::span<const ParamSpec> table, const std::vector<float>& values);

}  // namespace glint
