// The list of BRDF models: each model's id, label, parameter table and the physical claims
// it makes (reciprocity, energy conservation), and dispatch of eval over packed values.
// Adding a model: one header in core/brdf, one GLSL twin, one row here; optionally the two hooks
// below (ambient reflectance, specular transport), each a case in model_registry.cpp.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include <glm/glm.hpp>

#include "brdf/param_table.h"
#include "math/frame.h"

namespace glint {

enum class BrdfModel {
    Lambert, BlinnPhong, OrenNayar, Phong, CookTorrance, GgxAnisotropic, Ward, Retroreflective, Mirror, Glass
};

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
    // Ambient hook: the GLSL function `vec3 f(MaterialParams, vec3 wo, ShadingFrame)` returning
    // the model's ambient reflectance k_a (Hearn-Baker's k_a·I_a, with I_a a uniform radiance
    // L_a): physically the directional albedo ∫ f_r cos θ_i dω_i for wo. Its C++ twin
    // `ambientReflectance<Model>(params, wo, frame)` sits in the model's header and gets a case in
    // ambientReflectance() below. nullptr: the model reflects no ambient light (k_a = 0).
    const char* glslAmbient = nullptr;
    // Specular-transport hook for delta lobes that f_r cannot hold (mirror, glass): the GLSL
    // function `vec3 f(MaterialParams, vec3 position, ShadingFrame, vec3 wo)` tracing them
    // (common/specular_transport.glsl); C++ twin: a case in traceSpecular() in
    // render/specular_transport.cpp. nullptr: none.
    const char* glslTransport = nullptr;
    // Environment hook: the GLSL function `vec3 f(MaterialParams, vec3 wo, ShadingFrame)` giving
    // the radiance the model's non-delta lobes reflect from the environment map (image-based
    // lighting, shaders/common/environment.glsl), at the end of the model's GLSL file; C++ twin: a
    // case in environmentLighting() (environment/environment_lighting.cpp). nullptr: none.
    const char* glslEnvironment = nullptr;
    // How the environment lights the model, in words (shown under the material panel).
    const char* environmentResponse = "not lit by the environment (only its delta lobes see it)";
};

std::span<const ModelInfo> allModels();
const ModelInfo& modelInfo(BrdfModel model);
std::optional<BrdfModel> findModel(std::string_view id);

// Evaluates f_r [1/sr] per channel for packed parameter values (see param_table.h).
// wi points towards the light, wo towards the viewer; both unit length, in world space.
glm::vec3 evalBrdf(BrdfModel model, std::span<const float> values, glm::vec3 wi, glm::vec3 wo,
                   const ShadingFrame& frame);

// Ambient reflectance k_a per channel for packed values (zero for models without the hook):
// the radiance reflected towards wo under a uniform ambient radiance L_a is k_a·L_a.
glm::vec3 ambientReflectance(BrdfModel model, std::span<const float> values, glm::vec3 wo, const ShadingFrame& frame);

// Whether one form of a model breaks a claim its table makes for the model as a whole:
// e.g. the lecture forms of Blinn-Phong and Phong are not reciprocal. Property tests use this.
bool isReciprocal(BrdfModel model, std::span<const float> values);

}  // namespace glint
