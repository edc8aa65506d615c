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

std::span<float> paramValues(Material& material) {
    return std::visit(Overloaded{[](AnalyticMaterial& analytic) { return std::span<float>(analytic.values); },
                                 [](CustomMaterial& custom) { return std::span<float>(custom.values); },
                                 [](const MeasuredMaterial&) { return std::span<float>(); }},
                      material.kind);
}

std::span<const float> paramValues(const Material& material) { return paramValues(const_cast<Material&>(material)); }

}  // namespace glint
