// The pixels a change of material values reaches (see material_change.h).
#include "render/material_change.h"

#include <algorithm>
#include <vector>

#include "geometry/shape_mesh.h"
#include "render/transmission_backdrop.h"
#include "scene/scene_json.h"

namespace glint {

std::optional<PixelRegion> materialChangeRect(const Scene& before, const Scene& after, int width, int height) {
    if (before.materials.size() != after.materials.size() || before.environment.map != after.environment.map) return std::nullopt;
    Scene valuesAsAfter = before;  // everything else must be the same
    std::vector<bool> changed(after.materials.size(), false);
    for (size_t i = 0; i < after.materials.size(); ++i) {
        const Material& was = before.materials[i];
        const Material& is = after.materials[i];
        if (was.values == is.values) continue;
        if (!is.textures.empty() || is.custom || is.measured || transmitsLight(was) || transmitsLight(is)) return std::nullopt;
        changed[i] = true;
        valuesAsAfter.materials[i].values = is.values;
    }
    if (std::none_of(changed.begin(), changed.end(), [](bool c) { return c; })) return std::nullopt;
    if (drawsTransmissionBackdrop(after) || sceneToJson(valuesAsAfter) != sceneToJson(after)) return std::nullopt;
    int left = width, bottom = height, right = 0, top = 0;
    for (const SceneObject& object : after.objects) {
        if (!changed[object.materialIndex]) continue;
        const PixelRegion rect = coveredRect(after.camera, boundingSphere(object.shape), width, height);
        if (rect.width == 0 || rect.height == 0) continue;
        left = std::min(left, rect.x), bottom = std::min(bottom, rect.y);
        right = std::max(right, rect.x + rect.width), top = std::max(top, rect.y + rect.height);
    }
    if (right <= left || top <= bottom) return PixelRegion{};  // no changed object is in the frame
    return PixelRegion{left, bottom, right - left, top - bottom};
}

}  // namespace glint
