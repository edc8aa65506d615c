// Model switching through the quantities models share (see model_switch.h, appearance.h): each
// model says what it holds and what it takes, in its own header; a pair needs no code of its own.
#include "brdf/model_switch.h"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "brdf/appearance.h"
#include "brdf/fresnel.h"
#include "brdf/model_registry.h"
#include "interchange/material_values.h"
#include "interchange/measured_brdf.h"
#include "util/diagnostic.h"

namespace glint {

std::string joinedNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

namespace {

// The reflectance at normal incidence the appearance implies (a lobe's colour, or F0 of n + iκ).
std::optional<glm::vec3> normalReflectance(const Appearance& a) {
    if (a.specular) return *a.specular;
    if (a.ior) return fresnelF0(*a.ior, a.extinction ? *a.extinction : glm::vec3(0.0f));
    return std::nullopt;
}
const std::vector<std::string>& reflectanceSources(const Appearance& a) { return a.specular ? a.specular.from : a.ior.from; }

// A reflectance as a complex index: grey → a dielectric (κ = 0), coloured → a conductor (n = 1).
std::pair<glm::vec3, glm::vec3> indexForReflectance(glm::vec3 f0) {
    const bool grey = std::abs(f0.r - f0.g) < 1e-3f && std::abs(f0.g - f0.b) < 1e-3f;
    if (grey) return {glm::vec3(dielectricIorFromF0(f0.g)), glm::vec3(0.0f)};
    return {glm::vec3(1.0f), glm::vec3(conductorExtinctionFromF0(f0.r), conductorExtinctionFromF0(f0.g), conductorExtinctionFromF0(f0.b))};
}

}  // namespace

float AppearanceWriter::isotropicAlpha() const {
    return source_.alpha ? std::sqrt((*source_.alpha).x * (*source_.alpha).y) : 0.0f;
}
bool AppearanceWriter::metal() const { return source_.extinction && glm::length(*source_.extinction) > 0.1f; }

void AppearanceWriter::set(const char* name, glm::vec3 value) {
    const int index = findParam(table_, name);
    GLINT_CHECK(index >= 0);
    const ParamSpec& spec = table_[index];
    value = glm::clamp(value, glm::vec3(spec.validMin), glm::vec3(spec.validMax));
    for (int c = 0; c < componentCount(spec.kind); ++c) values_[packedOffset(table_, index) + c] = value[c];
}

void AppearanceWriter::diffuseTo(const char* name) {
    const Appearance& a = source_;
    if (!a.diffuse) return;
    set(name, *a.diffuse);
    use(a.diffuse, joinedNames(a.diffuse.from) + " → " + name);
    if (a.diffuse.from.size() == 1) unchanged[a.diffuse.from.front()] = name;
}

void AppearanceWriter::indexTo(const char* iorName, const char* extinctionName) {
    const Appearance& a = source_;
    if (a.ior) {
        set(iorName, *a.ior);
        use(a.ior, joinedNames(a.ior.from) + " → " + iorName);
        if (a.extinction) set(extinctionName, *a.extinction), use(a.extinction, joinedNames(a.extinction.from) + " → " + extinctionName);
    } else if (a.glassIor) {
        set(iorName, *a.glassIor);
        use(a.glassIor, joinedNames(a.glassIor.from) + " → " + iorName);
    } else if (a.specular) {
        const auto [n, k] = indexForReflectance(*a.specular);
        set(iorName, n), set(extinctionName, k);
        use(a.specular, joinedNames(a.specular.from) + " → " + iorName + ", " + extinctionName + " (same F0)");
    }
}

void AppearanceWriter::reflectanceTo(const char* name) {
    const Appearance& a = source_;
    const auto f0 = normalReflectance(a);
    if (!f0) return;
    set(name, *f0);
    if (a.specular) use(a.specular, joinedNames(a.specular.from) + " → " + name);
    else use(a.ior, joinedNames(reflectanceSources(a)) + " → " + name + " (F0 of n + iκ)"), use(a.extinction, "");
}

void AppearanceWriter::alphaTo(const char* name, float alpha, const std::string& how) {
    if (!source_.alpha) return;
    set(name, alpha);
    use(source_.alpha, joinedNames(source_.alpha.from) + " → " + name + how);
}

void AppearanceWriter::anisotropicAlphaTo(const char* nameX, const char* nameY) {
    if (source_.alpha) set(nameX, (*source_.alpha).x);
    alphaTo(nameY, source_.alpha ? (*source_.alpha).y : 0.0f, std::string(" and ") + nameX);
}

std::string ModelSwitch::summary() const {
    std::string text = kept.empty() ? "kept nothing" : "kept " + joinedNames(kept);
    if (!dropped.empty()) text += "; dropped " + joinedNames(dropped);
    return text;
}

ModelSwitch switchModel(const Material& source, BrdfModel target) {
    if (const AnalyticMaterial* analytic = source.analytic(); analytic && analytic->model == target) return {source, {}, {}};
    ModelSwitch result;
    result.material = Material::withDefaults(source.name, target);
    AnalyticMaterial& switched = *result.material.analytic();
    const Appearance appearance = std::visit(
        Overloaded{[](const AnalyticMaterial& analytic) {
                       return dispatch(analytic.model, [&](auto model) {
                           using M = decltype(model);
                           if constexpr (HasAppearance<M>) return M::appearance(unpack<M>(analytic.values.data()));
                           else return Appearance{};
                       });
                   },
                   [&](const CustomMaterial&) {
                       result.dropped.push_back("the .brdf shader and its parameters");
                       return Appearance{};
                   },
                   [](const MeasuredMaterial& measured) {
                       // The table's directional albedo at normal viewing, within [0, 1], as the diffuse colour.
                       const glm::vec3 albedo = glm::clamp(measuredDirectionalAlbedo(*measured.brdf, 1.0f), 0.0f, 1.0f);
                       return Appearance{.diffuse = {albedo, {"measured albedo"}}};
                   }},
        source.kind);
    AppearanceWriter writer(appearance, modelInfo(target).params, switched.values);
    dispatch(target, [&](auto model) {
        if constexpr (TakesAppearance<decltype(model)>) decltype(model)::takeAppearance(writer);
    });
    std::erase(writer.kept, std::string());
    result.kept = std::move(writer.kept);
    const AnalyticMaterial* analytic = source.analytic();
    if (!analytic) return result;
    // Textures follow the parameter they drove where it was copied unchanged; the normal and
    // occlusion maps always.
    for (const MaterialTexture& texture : analytic->textures) {
        const auto copied = writer.unchanged.find(texture.parameter);
        if (!isSurfaceMapKey(texture.parameter) && copied == writer.unchanged.end()) {
            result.dropped.push_back("the texture on " + texture.parameter);
            continue;
        }
        switched.textures.push_back(texture);
        if (!isSurfaceMapKey(texture.parameter)) switched.textures.back().parameter = copied->second;
    }
    const auto table = modelInfo(analytic->model).params;
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& spec = table[i];
        if (writer.used.count(spec.name)) continue;
        const glm::vec3 value = paramValue(source, spec.name);
        const glm::vec3 standard(spec.defaultValue[0], componentCount(spec.kind) == 3 ? spec.defaultValue[1] : spec.defaultValue[0],
                                 componentCount(spec.kind) == 3 ? spec.defaultValue[2] : spec.defaultValue[0]);
        if (value != standard) result.dropped.push_back(spec.name);
    }
    return result;
}

}  // namespace glint
