// The models-and-parameters reference (docs/models.md), written from the models themselves:
// `glint models --markdown` prints it and a test compares it with the committed file.
#pragma once

#include <span>
#include <string>

#include "brdf/model.h"

namespace glint {

std::string modelsMarkdown(std::span<const ModelInfo> models);

}  // namespace glint
