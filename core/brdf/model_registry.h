// Glint's BRDF models: the one list of model types (brdf/model.h says what a model declares),
// the BrdfModel ids it derives, and the run-time view of each model (ModelInfo) for the code that
// picks a model by id: the panel, the files, the GLSL generator.
// Adding a model: its header core/brdf/<id>.h, its GLSL twin shaders/brdf/<id>.glsl, one line in
// GLINT_BRDF_MODELS below (appended: a model's position is its BrdfModel id).
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include <glm/glm.hpp>

#include "brdf/blinn_phong.h"
#include "brdf/cook_torrance.h"
#include "brdf/ggx_anisotropic.h"
#include "brdf/glass.h"
#include "brdf/lambert.h"
#include "brdf/mirror.h"
#include "brdf/model.h"
#include "brdf/openpbr.h"
#include "brdf/oren_nayar.h"
#include "brdf/phong.h"
#include "brdf/retroreflective.h"
#include "brdf/ward.h"
#include "math/frame.h"

namespace glint {

#define GLINT_BRDF_MODELS(X)                                                                              \
    X(Lambert), X(BlinnPhong), X(OrenNayar), X(Phong), X(CookTorrance), X(GgxAnisotropic), X(Ward), \
        X(Retroreflective), X(Mirror), X(Glass), X(OpenPbr)
#define GLINT_MODEL_NAME(Model) Model
enum class BrdfModel : int { GLINT_BRDF_MODELS(GLINT_MODEL_NAME) };
using Models = ModelList<GLINT_BRDF_MODELS(GLINT_MODEL_NAME)>;
#undef GLINT_MODEL_NAME

// Calls f(M{}) with the type of `model`.
template <class F>
decltype(auto) dispatch(BrdfModel model, F&& f) {
    return dispatch(Models{}, static_cast<int>(model), std::forward<F>(f));
}

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
