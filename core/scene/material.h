// Material: a name and one of three kinds: an analytic BRDF model with its packed parameter
// values and textures, a custom .brdf program with its values, or a measured table. Plain data;
// scene.h holds the scene's list of them. Code that treats the kinds differently visits `kind`
// (Overloaded) or asks for the one it handles (analytic(), custom(), measured()).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "brdf/model_registry.h"
#include "texture/material_texture.h"

namespace glint {

struct CustomBrdf;  // interchange/custom_brdf.h
struct MeasuredBrdf;  // interchange/measured_brdf.h

struct AnalyticMaterial {
    BrdfModel model = BrdfModel::Lambert;
    std::vector<float> values;  // packed per the model's parameter table
    std::vector<MaterialTexture> textures;  // parameters driven by textures (texture/), table order
};

// A BRDF Explorer .brdf file (GPU only); its values are packed per brdf->table.
struct CustomMaterial {
    std::shared_ptr<const CustomBrdf> brdf;
    std::vector<float> values;
};

// A MERL measured BRDF (.binary): the table is all there is, no parameters.
struct MeasuredMaterial {
    std::shared_ptr<const MeasuredBrdf> brdf;
};

struct Material {
    std::string name;
    std::variant<AnalyticMaterial, CustomMaterial, MeasuredMaterial> kind;

    static Material withDefaults(std::string name, BrdfModel model);
    // The material as that kind, or nullptr when it is another.
    AnalyticMaterial* analytic() { return std::get_if<AnalyticMaterial>(&kind); }
    const AnalyticMaterial* analytic() const { return std::get_if<AnalyticMaterial>(&kind); }
    CustomMaterial* custom() { return std::get_if<CustomMaterial>(&kind); }
    const CustomMaterial* custom() const { return std::get_if<CustomMaterial>(&kind); }
    const MeasuredMaterial* measured() const { return std::get_if<MeasuredMaterial>(&kind); }
};

// The parameters a material's values follow: its model's table, its .brdf file's, or none (a
// measured table); and those values, packed per that table.
std::span<const ParamSpec> paramTable(const Material& material);
std::span<float> paramValues(Material& material);
std::span<const float> paramValues(const Material& material);

// std::visit(Overloaded{[](const AnalyticMaterial&) {…}, …}, material.kind)
template <class... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <class... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;  // clang 14 does not deduce aggregates

}  // namespace glint
