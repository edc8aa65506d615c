// What a BRDF model is: one type, declared in its own header core/brdf/<id>.h beside its GLSL twin
// shaders/brdf/<id>.glsl, with
//   id, label, citation          as written in files / shown in the UI / the source
//   reciprocal, energyConserving the physical claims the property tests check
//   params                       its ParamSpec table (param_table.h), and Params, the struct that
//                                unpack<M>() fills from packed values in table order (checked here at
//                                compile time: one field per parameter, each of the kind's type)
//   eval                         f_r(Params, wi, wo, frame) [1/sr]
// and the optional hooks a model may declare, found by the generic code below:
//   ambientReflectance           k_a(Params, wo, frame): GLSL ambientReflectance<Name>
//   environmentResponse          the model has an environment hook (GLSL environmentLighting<Name>,
//                                C++ twin in environment/environment_lighting.cpp); the string says how
//   environmentNote              without that hook: what the environment does to the model, in words
//   tracesDeltaLobes             GLSL transport<Name> traces its delta lobes (C++ twin in
//                                render/specular_transport.cpp)
//   isReciprocal(Params)         a form that breaks the model's reciprocity claim
//   glslTables()                 GLSL the twin needs before its file, computed on the C++ side
//                                (constant tables), so that both twins read the same numbers
//   mtlForm(Params), gltfForm(Params)  the model in .mtl / glTF terms, for the exporters
//                                (export_forms.h); without one, the exporter says it has none
//   gltfOpenPbr                  glTF's own PBR material and its extensions hold the model
//                                whole, textures included (interchange/gltf_openpbr.h)
//   appearance(Params), takeAppearance(AppearanceWriter&)  what the model holds and takes in
//                                terms models share, for switching models (appearance.h)
//   deltaLobeWeights(Params, cos θ_i)  its delta lobes in numbers: reflected and transmitted
//                                fractions and the refractive index (trait_forms.h), for the probe
//                                and the plots
//   onlyDeltaLobes               all its light leaves by delta lobes: what they are, in words
//   transmits(Params)            light passes through it (the transmission backdrop draws it)
//   dispersiveIndex              the parameter the spectral renderer varies with wavelength
//   constantForm                 f_r is one value for all directions, written so ("ρ/π")
//   textbookForm(Params)         the forms the hand-written floor shader draws (trait_forms.h)
//   environmentApproximation(Params)  how the environment hook approximates this form, where the
//                                model's kind of approximation does not say it
//   coatNormalMap                it has a coat whose normal a map can bend
// GLSL names follow from the id by convention: "cook_torrance" -> CookTorrance -> evalCookTorrance.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include <glm/glm.hpp>

#include "brdf/param_table.h"
#include "math/frame.h"

namespace glint {

template <class... Models>
struct ModelList { static constexpr int size = sizeof...(Models); };

template <class M>
concept BrdfModelType = requires(const typename M::Params& p, glm::vec3 w, const ShadingFrame& frame) {
    { M::id } -> std::convertible_to<const char*>;
    { M::label } -> std::convertible_to<const char*>;
    { M::citation } -> std::convertible_to<const char*>;
    { M::reciprocal } -> std::convertible_to<bool>;
    { M::energyConserving } -> std::convertible_to<bool>;
    { std::span<const ParamSpec>(M::params) };
    { M::eval(p, w, w, frame) } -> std::same_as<glm::vec3>;
};

template <class M>
concept HasAmbient = requires(const typename M::Params& p, glm::vec3 wo, const ShadingFrame& frame) {
    { M::ambientReflectance(p, wo, frame) } -> std::same_as<glm::vec3>;
};
template <class M>
concept HasEnvironment = requires { { M::environmentResponse } -> std::convertible_to<const char*>; };
template <class M>
concept TracesDeltaLobes = requires { requires M::tracesDeltaLobes; };
template <class M>
concept HasGlslTables = requires { { M::glslTables() } -> std::same_as<std::string>; };
struct MtlForm;   // export_forms.h
struct GltfForm;
struct Appearance;  // appearance.h
class AppearanceWriter;
template <class M>
concept HasMtlForm = requires(const typename M::Params& p) { { M::mtlForm(p) } -> std::same_as<MtlForm>; };
template <class M>
concept HasGltfForm = requires(const typename M::Params& p) { { M::gltfForm(p) } -> std::same_as<GltfForm>; };
template <class M>
concept HasAppearance = requires(const typename M::Params& p) { { M::appearance(p) } -> std::same_as<Appearance>; };
template <class M>
concept TakesAppearance = requires(AppearanceWriter& writer) { M::takeAppearance(writer); };
template <class M>
concept IsGltfOpenPbr = requires { requires M::gltfOpenPbr; };
struct DeltaLobeWeights;  // trait_forms.h
struct TextbookForm;
template <class M>
concept HasDeltaLobeWeights = requires(const typename M::Params& p) { { M::deltaLobeWeights(p, 1.0f) } -> std::same_as<DeltaLobeWeights>; };
template <class M>
concept MayTransmit = requires(const typename M::Params& p) { { M::transmits(p) } -> std::same_as<bool>; };
template <class M>
concept HasTextbookForm = requires(const typename M::Params& p) { M::textbookForm(p); };
template <class M>
concept HasEnvironmentApproximation =
    requires(const typename M::Params& p) { { M::environmentApproximation(p) } -> std::convertible_to<const char*>; };
template <class M>
concept HasFormReciprocity = requires(const typename M::Params& p) { { M::isReciprocal(p) } -> std::same_as<bool>; };

// --- unpacking from the table ---------------------------------------------------------------

namespace unpacking {

// One parameter's packed floats, convertible only to the C++ type of its kind: a field of the
// wrong type (or in the wrong order) does not compile.
template <ParamKind Kind>
struct Field {
    const float* v;
    operator glm::vec3() const requires(componentCount(Kind) == 3) { return {v[0], v[1], v[2]}; }
    operator float() const requires(Kind == ParamKind::Scalar) { return v[0]; }
    operator bool() const requires(Kind == ParamKind::Bool) { return v[0] > 0.5f; }
    template <class E> requires(Kind == ParamKind::Enum && std::is_enum_v<E>)
    operator E() const { return static_cast<E>(static_cast<int>(v[0])); }
};

// Converts to anything: counts an aggregate's fields.
struct Any { template <class T> operator T() const; };

template <class M>
constexpr int packedOffset(std::size_t index) {
    int offset = 0;
    for (std::size_t i = 0; i < index; ++i) offset += componentCount(M::params[i].kind);
    return offset;
}

template <class M, std::size_t... I>
typename M::Params unpack(const float* v, std::index_sequence<I...>) {
    return typename M::Params{Field<M::params[I].kind>{v + packedOffset<M>(I)}...};
}

template <class P, std::size_t... I>
constexpr bool takesFields(std::index_sequence<I...>) {
    return requires { P{(static_cast<void>(I), Any{})...}; };
}

}  // namespace unpacking

template <class M>
constexpr std::size_t paramCount() {
    return std::size(M::params);
}

// The model's Params from packed values (param_table.h), in table order.
template <class M>
typename M::Params unpack(const float* values) {
    constexpr std::size_t count = paramCount<M>();
    static_assert(std::is_aggregate_v<typename M::Params>, "Params must be an aggregate");
    static_assert(!unpacking::takesFields<typename M::Params>(std::make_index_sequence<count + 1>()),
                  "Params has more fields than the parameter table");
    return unpacking::unpack<M>(values, std::make_index_sequence<count>());
}

// --- dispatch -------------------------------------------------------------------------------

// Calls f(M{}) for the model at `index` of the list (pbrt-v4's Dispatch); index must be valid.
template <class F, class First, class... Rest>
decltype(auto) dispatch(ModelList<First, Rest...>, int index, F&& f) {
    if constexpr (sizeof...(Rest) == 0) return f(First{});
    else if (index == 0) return f(First{});
    else return dispatch(ModelList<Rest...>{}, index - 1, std::forward<F>(f));
}

// Calls f(M{}) for each model of the list, in order.
template <class F, class... Models>
void forEachModel(ModelList<Models...>, F&& f) {
    (f(Models{}), ...);
}

// --- names by convention and the run-time view ---------------------------------------------

// "cook_torrance" -> "CookTorrance": the suffix of every GLSL hook of the model.
std::string glslModelName(std::string_view id);
// The GLSL constant of an enum option: "<PARAM>_<OPTION>" in upper case, e.g. DISTRIBUTION_GGX
// for option "ggx" of parameter "distribution" (material_glsl.h declares them).
std::string glslOptionConstant(std::string_view param, std::string_view option);

enum class BrdfModel : int;  // a model's position in the list (model_registry.h)

// A model as code that picks it at run time sees it. The GLSL names are derived by convention.
struct ModelInfo {
    BrdfModel model;
    const char* id;
    const char* label;
    const char* glslFile;   // brdf/<id>.glsl, under shaders/
    const char* glslEval;   // eval<Name>
    std::span<const ParamSpec> params;
    bool reciprocal;
    bool energyConserving;
    const char* citation;
    // Hooks, nullptr when the model has none. Ambient: `vec3 ambientReflectance<Name>(MaterialParams,
    // vec3 wo, ShadingFrame)`, k_a (Hearn-Baker's k_a·I_a): the directional albedo ∫ f_r cos θ_i dω_i.
    const char* glslAmbient;
    // Delta lobes f_r cannot hold: `vec3 transport<Name>(MaterialParams, vec3 position, ShadingFrame,
    // vec3 wo)` traces them (common/specular_transport.glsl).
    const char* glslTransport;
    // Image-based lighting of the non-delta lobes: `vec3 environmentLighting<Name>(MaterialParams,
    // vec3 wo, ShadingFrame)`, at the end of the model's GLSL file (common/environment.glsl).
    const char* glslEnvironment;
    const char* environmentResponse;  // how the environment lights the model, in words
    std::string (*glslTables)();      // GLSL put before the model's file (nullptr: none)
    // Traits (nullptr or false when the model has none; see the list at the top).
    const char* onlyDeltaLobes;
    const char* dispersiveIndex;
    const char* constantForm;
    bool coatNormalMap;
};

template <class M>
constexpr const char* onlyDeltaLobesOf() {
    if constexpr (requires { M::onlyDeltaLobes; }) return M::onlyDeltaLobes;
    else return nullptr;
}
template <class M>
constexpr const char* dispersiveIndexOf() {
    if constexpr (requires { M::dispersiveIndex; }) return M::dispersiveIndex;
    else return nullptr;
}
template <class M>
constexpr const char* constantFormOf() {
    if constexpr (requires { M::constantForm; }) return M::constantForm;
    else return nullptr;
}

template <class M>
constexpr auto glslTablesOf() -> std::string (*)() {
    if constexpr (HasGlslTables<M>) return &M::glslTables;
    else return nullptr;
}

template <class M>
ModelInfo describeModel(BrdfModel position) {
    static_assert(BrdfModelType<M>);
    struct Names {
        std::string name = glslModelName(M::id);
        std::string file = "brdf/" + std::string(M::id) + ".glsl", eval = "eval" + name,
                    ambient = "ambientReflectance" + name, transport = "transport" + name,
                    environment = "environmentLighting" + name;
    };
    static const Names names;
    const char* response = "not lit by the environment (only its delta lobes see it)";
    if constexpr (HasEnvironment<M>) response = M::environmentResponse;
    else if constexpr (requires { M::environmentNote; }) response = M::environmentNote;
    return {position, M::id, M::label, names.file.c_str(), names.eval.c_str(), M::params, M::reciprocal,
            M::energyConserving, M::citation, HasAmbient<M> ? names.ambient.c_str() : nullptr,
            TracesDeltaLobes<M> ? names.transport.c_str() : nullptr,
            HasEnvironment<M> ? names.environment.c_str() : nullptr, response,
            glslTablesOf<M>(), onlyDeltaLobesOf<M>(), dispersiveIndexOf<M>(), constantFormOf<M>(),
            requires { requires M::coatNormalMap; }};
}

}  // namespace glint
