// Named materials whose numbers come from published measurements (complex indices of metals,
// indices of dielectrics, broadband albedos), each with its source. A table and two look-ups;
// no UI here (the CLI lists and writes them: app/cli/presets_command.cpp).
#pragma once

#include <span>
#include <string_view>

#include <glm/glm.hpp>

#include "brdf/model_registry.h"
#include "scene/scene.h"

namespace glint {

struct PresetSetting {
    const char* param = nullptr;  // a name in the model's parameter table; nullptr ends the list
    glm::vec3 value{0.0f};        // scalars and enum indices use .x
};

struct Preset {
    const char* name;      // as typed on the command line: "gold"
    const char* category;  // "metal", "dielectric", "plastic", "natural", "layered"
    BrdfModel model;
    PresetSetting settings[8];  // over the model's defaults
    const char* source;         // where the numbers come from

    // The preset as a material named after it, with every other parameter at its default.
    Material material() const;
};

std::span<const Preset> allPresets();
const Preset* findPreset(std::string_view name);

}  // namespace glint
