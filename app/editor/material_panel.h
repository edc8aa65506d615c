// The material panel: a model picker and one widget per entry of the model's parameter table
// (slider with unit and range, log slider, sRGB colour picker storing linear, checkbox, combo),
// each with reset-to-default. A free function over a Material; returns true when it changed.
#pragma once

#include "scene/scene.h"

namespace glint {

bool drawMaterialPanel(Material& material);

}  // namespace glint
