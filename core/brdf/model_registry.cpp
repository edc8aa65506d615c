// The model registry's table and eval dispatch (see model_registry.h).
#include "brdf/model_registry.h"

#include "brdf/blinn_phong.h"
#include "brdf/glass.h"
#include "brdf/lambert.h"
#include "brdf/mirror.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

constexpr ModelInfo kModels[] = {
    {BrdfModel::Lambert, "lambert", "Lambert", "brdf/lambert.glsl", "evalLambert", kLambertTable,
     true, true, "J. H. Lambert, Photometria, 1760", "ambientReflectanceLambert"},
    {BrdfModel::BlinnPhong, "blinn_phong", "Blinn-Phong", "brdf/blinn_phong.glsl", "evalBlinnPhong",
     kBlinnPhongTable, true, false,
     "J. F. Blinn, Models of Light Reflection for Computer Synthesized Pictures, SIGGRAPH 1977",
     "ambientReflectanceBlinnPhong"},
    {BrdfModel::Mirror, "mirror", "Mirror (conductor Fresnel)", "brdf/mirror.glsl", "evalMirror", kMirrorTable,
     true, false, "A. Fresnel (1823); complex index after Born & Wolf, Principles of Optics, §14.2",
     "ambientReflectanceMirror", "transportMirror"},
    {BrdfModel::Glass, "glass", "Glass (dielectric)", "brdf/glass.glsl", "evalGlass", kGlassTable, true, true,
     "Snell's law and Fresnel (1823); transparency after Hearn & Baker, Computer Graphics, §14.5", nullptr,
     "transportGlass"},
};

}  // namespace

std::span<const ModelInfo> allModels() { return kModels; }

const ModelInfo& modelInfo(BrdfModel model) {
    for (const ModelInfo& info : kModels)
        if (info.model == model) return info;
    GLINT_CHECK(false && "model missing from the registry");
    return kModels[0];
}

std::optional<BrdfModel> findModel(std::string_view id) {
    for (const ModelInfo& info : kModels)
        if (id == info.id) return info.model;
    return std::nullopt;
}

glm::vec3 evalBrdf(BrdfModel model, std::span<const float> values, glm::vec3 wi, glm::vec3 wo,
                   const ShadingFrame& frame) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(modelInfo(model).params));
    switch (model) {
        case BrdfModel::Lambert: return evalLambert(unpackLambert(values.data()), wi, wo, frame);
        case BrdfModel::BlinnPhong: return evalBlinnPhong(unpackBlinnPhong(values.data()), wi, wo, frame);
        case BrdfModel::Mirror: return evalMirror(unpackMirror(values.data()), wi, wo, frame);
        case BrdfModel::Glass: return evalGlass(unpackGlass(values.data()), wi, wo, frame);
    }
    return glm::vec3(0.0f);
}

glm::vec3 ambientReflectance(BrdfModel model, std::span<const float> values, glm::vec3 wo, const ShadingFrame& frame) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(modelInfo(model).params));
    switch (model) {
        case BrdfModel::Lambert: return ambientReflectanceLambert(unpackLambert(values.data()), wo, frame);
        case BrdfModel::BlinnPhong: return ambientReflectanceBlinnPhong(unpackBlinnPhong(values.data()), wo, frame);
        case BrdfModel::Mirror: return ambientReflectanceMirror(unpackMirror(values.data()), wo, frame);
        default: return glm::vec3(0.0f);  // no ambient hook (ModelInfo::glslAmbient == nullptr)
    }
}

bool isReciprocal(BrdfModel model, std::span<const float> values) {
    if (model == BrdfModel::BlinnPhong)
        return unpackBlinnPhong(values.data()).form != BlinnForm::Lecture;
    return modelInfo(model).reciprocal;
}

}  // namespace glint
