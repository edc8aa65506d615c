// The material panel: a model picker and one widget per entry of the model's parameter table
// (slider with unit and range, log slider, sRGB colour picker storing linear, checkbox, combo),
// each with reset-to-default. A free function over a Material; returns true when it changed.
// A typed value outside the table's valid range is refused and `refusal` says why; a model switch
// keeps what the two models share (brdf/model_switch.h) and `refusal` says what was kept and dropped.
#pragma once

#include <string>

#include "scene/scene.h"

namespace glint {

// Scalar and colour parameters and the normal map carry texture controls (texture_panel.h);
// `textureFileRequest` is set to the parameter whose image file the user wants to choose.
bool drawMaterialPanel(Material& material, std::string& refusal, std::string& textureFileRequest);

}  // namespace glint
