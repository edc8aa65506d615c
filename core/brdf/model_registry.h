// The list of BRDF models: each model's id, label, parameter table and the physical claims
// it makes (reciprocity, energy conservation), and dispatch of eval over packed values.
// Adding a model: one header in core/brdf, one GLSL twin, one row here.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include <glm/glm.hpp>

#include "brdf/param_table.h"
#include "math/frame.h"

namespace glint {

enum class BrdfModel { Lambert, BlinnPhong, OrenNayar, Phong, CookTorrance, GgxAnisotropic, Ward, Retroreflective };

struct ModelInfo {
    BrdfModel model;
    const char* id;         // as written in files
    const char* label;      // as shown in the UI
    const char* glslFile;   // the GLSL twin, under shaders/
    const char* glslEval;   // its eval function
    std::span<const ParamSpec> params;
    bool reciprocal;        // f(wi, wo) == f(wo, wi) for every parameter set
    bool energyConserving;  // directional albedo <= 1 over the whole valid range
    const char* citation;
};

std::span<const ModelInfo> allModels();
const ModelInfo& modelInfo(BrdfModel model);
std::optional<BrdfModel> findModel(std::string_view id);

// Evaluates f_r [1/sr] per channel for packed parameter values (see param_table.h).
// wi points towards the light, wo towards the viewer; both unit length, in world space.
glm::vec3 evalBrdf(BrdfModel model, std::span<const float> values, glm::vec3 wi, glm::vec3 wo,
                   const ShadingFrame& frame);

// Whether one form of a model breaks a claim its table makes for the model as a whole:
// e.g. the lecture forms of Blinn-Phong and Phong are not reciprocal. Property tests use this.
bool isReciprocal(BrdfModel model, std::span<const float> values);

}  // namespace glint
