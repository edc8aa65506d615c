// What the delta-lobe models leave out, said where it applies (see model_limits.h).
#include "editor/model_limits.h"

#include <algorithm>

namespace glint {

std::vector<std::string> modelLimitNotes(const Scene& scene, int objectIndex) {
    std::vector<std::string> notes;
    if (objectIndex < 0 || objectIndex >= static_cast<int>(scene.objects.size())) return notes;
    const AnalyticMaterial* material = scene.materials.at(scene.objects[objectIndex].materialIndex).analytic();
    if (!material) return notes;
    const char* onlyDeltaLobes = modelInfo(material->model).onlyDeltaLobes;
    if (!onlyDeltaLobes) return notes;
    const std::string what = onlyDeltaLobes;
    const bool deltaLight = std::ranges::any_of(scene.lights, [](const Light& light) {
        return light.enabled && light.type != LightType::Ambient;
    });
    if (deltaLight)
        notes.push_back(what + " shows no highlight of the point, spot or directional lights: a light of no size "
                               "has a reflection of no area. An environment map shows bright spots it can reflect.");
    if (scene.objects.size() > 1)
        notes.push_back(what + " shows the " + (scene.environment.kind != EnvironmentKind::None ? "environment" : "background") +
                        ", not the other objects in the scene (no ray tracing between objects).");
    return notes;
}

}  // namespace glint
