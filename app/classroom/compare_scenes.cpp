// The compare panes' scene copies (see compare_scenes.h).
#include "classroom/compare_scenes.h"

#include "brdf/model_registry.h"

namespace glint {

Result<size_t> compareSubject(const Scene& scene) {
    if (scene.objects.empty()) return Diagnostic{{}, "the scene has no object to compare materials on"};
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (!std::holds_alternative<PlaneShape>(scene.objects[i].shape)) return i;
    return size_t{0};
}

Scene withSubjectMaterial(const Scene& scene, size_t subject, const Material& material) {
    Scene copy = scene;
    copy.materials.push_back(material);
    copy.objects.at(subject).materialIndex = static_cast<int>(copy.materials.size() - 1);
    return copy;
}

Material withModel(const Material& material, BrdfModel model) {
    const ModelInfo& target = modelInfo(model);
    Material result = Material::withDefaults(material.name + " as " + target.label, model);
    // Nothing carries over from a .brdf file's parameters or a measured table.
    if (material.analytic()) result.analytic()->values = carriedValues(paramTable(material), paramValues(material), target.params);
    return result;
}

Scene withSubjectInterpolation(const Scene& scene, size_t subject, SurfaceInterpolation interpolation,
                               const std::optional<Tessellation>& tessellation) {
    Scene copy = scene;
    SceneObject& object = copy.objects.at(subject);
    object.interpolation = interpolation;
    if (tessellation) {
        if (auto* sphere = std::get_if<SphereShape>(&object.shape)) sphere->segments = tessellation->segments, sphere->rings = tessellation->rings;
        if (auto* torus = std::get_if<TorusShape>(&object.shape)) torus->segments = tessellation->segments, torus->rings = tessellation->rings;
    }
    return copy;
}

}  // namespace glint
