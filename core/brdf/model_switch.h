// Switching a material from one BRDF model to another while keeping what the two share:
// diffuse colour (albedo, base colour), roughness (linear α, perceptual r = √α, Blinn-Phong
// exponents, Ward slopes), the complex index n + iκ, metalness ↔ a conductor's n and κ, and
// glass's index and absorption; and saying what was dropped. Pure data: the editor makes the
// switch one undo step, the MaterialX writer uses it to convert to OpenPBR.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace glint {

struct ModelSwitch {
    Material material;                  // in the target model; untouched parameters at their defaults
    std::vector<std::string> kept;      // "albedo → base_color", "roughness α → specular_roughness r = √α"
    std::vector<std::string> dropped;   // source parameters (away from their defaults) with no counterpart
    // "kept …; dropped …" for the editor and the exporters' warnings.
    std::string summary() const;
};

// `source` in `target`'s model, keeping its name, its normal map and the textures of parameters
// copied unchanged. A .brdf (custom) material keeps nothing; a measured one its directional albedo
// at normal viewing as the diffuse colour; one already in `target` is returned as it is.
ModelSwitch switchModel(const Material& source, BrdfModel target);

}  // namespace glint
