// Generates "generated/material.glsl" for one BRDF model from its parameter table: the
// MaterialParams struct (one field per parameter, named as in the table), loadMaterialParams()
// that unpacks MaterialBlock in table order, the model's GLSL twin and GLINT_EVAL_BRDF.
// This is the table's "uniform packing" use; the C++ side packs with the same offsets.
#pragma once

#include <string>

#include "brdf/model_registry.h"

namespace glint {

std::string generateMaterialGlsl(const ModelInfo& model);

}  // namespace glint
