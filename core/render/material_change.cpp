// The pixels a change of material values reaches (see material_change.h).
#include "render/material_change.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "geometry/shape_mesh.h"
#include "render/transmission_backdrop.h"
#include "scene/scene_json.h"

namespace glint {

std::optional<MaterialChange> materialChange(const Scene& before, const Scene& after, int width, int height) {
    if (before.materials.size() != after.materials.size() || before.environment.map != after.environment.map) return std::nullopt;
    Scene valuesAsAfter = before;  // everything else must be the same
    std::vector<bool> changed(after.materials.size(), false);
    for (size_t i = 0; i < after.materials.size(); ++i) {
        // Only plain analytic materials: a texture file or a .brdf reloaded from disk changes the
        // picture without changing the scene.
        const AnalyticMaterial* was = before.materials[i].analytic();
        const AnalyticMaterial* is = after.materials[i].analytic();
        if (!was || !is || !is->textures.empty()) return std::nullopt;
        if (was->values == is->values) continue;
        if (transmitsLight(before.materials[i]) || transmitsLight(after.materials[i])) return std::nullopt;
        changed[i] = true;
        std::get<AnalyticMaterial>(valuesAsAfter.materials[i].kind).values = is->values;
    }
    if (std::none_of(changed.begin(), changed.end(), [](bool c) { return c; })) return std::nullopt;
    if (drawsTransmissionBackdrop(after) || sceneToJson(valuesAsAfter) != sceneToJson(after)) return std::nullopt;
    MaterialChange change{{}, std::move(changed)};
    for (const SceneObject& object : after.objects)
        if (change.materials[object.materialIndex])
            change.rect = boundsOf(change.rect, coveredRect(after.camera, boundingSphere(object.shape), width, height));
    return change;
}

}  // namespace glint
