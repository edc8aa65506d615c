// Material: a named BRDF model with its packed parameter values and textures, or a custom
// .brdf program, or a measured table. Plain data; scene.h holds the scene's list of them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "brdf/model_registry.h"
#include "texture/material_texture.h"

namespace glint {

struct CustomBrdf;  // interchange/custom_brdf.h
struct MeasuredBrdf;  // interchange/measured_brdf.h

struct Material {
    std::string name;
    BrdfModel model = BrdfModel::Lambert;
    std::vector<float> values;  // packed per the model's parameter table
    std::vector<MaterialTexture> textures;  // parameters driven by textures (texture/), table order
    // A BRDF Explorer .brdf file (GPU only). When set, `model` is unused and `values` are packed
    // per custom->table.
    std::shared_ptr<const CustomBrdf> custom;
    // A MERL measured BRDF (.binary). When set, it is what renders; `model` and `values` hold a
    // Lambert stand-in for code that knows only analytic models (measured_brdf.h).
    std::shared_ptr<const MeasuredBrdf> measured;

    static Material withDefaults(std::string name, BrdfModel model);
};

}  // namespace glint
