// Material kinds and their parameters (see material.h).
#include "scene/material.h"

#include "interchange/custom_brdf.h"

namespace glint {

Material Material::withDefaults(std::string name, BrdfModel model) {
    return Material{std::move(name), AnalyticMaterial{model, defaultValues(modelInfo(model).params), {}}};
}

std::span<const ParamSpec> paramTable(const Material& material) {
    return std::visit(Overloaded{[](const AnalyticMaterial& analytic) { return modelInfo(analytic.model).params; },
                                 [](const CustomMaterial& custom) { return std::span<const ParamSpec>(custom.brdf->table); },
                                 [](const MeasuredMaterial&) { return std::span<const ParamSpec>(); }},
                      material.kind);
}

namespace {

// The values of the kinds that hold them, none for a measured table; `Values` is std::span<float>
// or std::span<const float>, as `material` is const or not.
template <class Values, class AnyMaterial>
Values valuesOf(AnyMaterial& material) {
    return std::visit(
        [](auto& kind) {
            if constexpr (requires { kind.values; }) return Values(kind.values);
            else return Values();
        },
        material.kind);
}

}  // namespace

std::span<float> paramValues(Material& material) { return valuesOf<std::span<float>>(material); }

std::span<const float> paramValues(const Material& material) { return valuesOf<std::span<const float>>(material); }

}  // namespace glint
