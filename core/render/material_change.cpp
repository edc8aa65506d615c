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
    PixelRegion region;  // empty when no changed object is in the frame
    for (const SceneObject& object : after.objects)
        if (changed[object.materialIndex]) region = boundsOf(region, coveredRect(after.camera, boundingSphere(object.shape), width, height));
    return region;
}

}  // namespace glint
