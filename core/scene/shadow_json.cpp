// Shadow keys of a light in scene files (see shadow_json.h).
#include "scene/shadow_json.h"

#include <algorithm>
#include <string>

namespace glint {

void readLightShadows(ObjectReader& reader, Light& light) {
    reader.expect({"casts_shadows", "shadow"});
    if (light.type == LightType::Ambient) {
        if (reader.has("casts_shadows")) reader.fail("casts_shadows", "ambient lights cast no shadows");
        if (reader.has("shadow")) reader.fail("shadow", "ambient lights cast no shadows");
        return;
    }
    light.castsShadows = reader.boolean("casts_shadows", false);
    if (!reader.has("shadow")) return;
    ObjectReader shadow = reader.object("shadow");
    ShadowSettings& settings = light.shadow;
    settings.mapResolution = shadow.integer("map_resolution", settings.mapResolution, kMinShadowMapResolution, kMaxShadowMapResolution);
    settings.depthBias = static_cast<float>(shadow.number("depth_bias", settings.depthBias, Bounds::between(0, kMaxShadowBiasTexels)));
    settings.normalOffset = static_cast<float>(shadow.number("normal_offset", settings.normalOffset, Bounds::between(0, kMaxShadowBiasTexels)));
    settings.filterRadius = static_cast<float>(
        shadow.number("filter_radius", settings.filterRadius, Bounds::between(0, kMaxShadowFilterRadiusTexels)));
    shadow.rejectUnknownKeys();
}

void checkShadowedLightCount(ObjectReader& root, const std::vector<Light>& lights) {
    const auto shadowed = std::count_if(lights.begin(), lights.end(), [](const Light& light) { return light.castsShadows; });
    if (shadowed > kMaxShadowedLights)
        root.fail("lights", "at most " + std::to_string(kMaxShadowedLights) + " lights can cast shadows (" +
                                std::to_string(shadowed) + " have \"casts_shadows\": true)");
}

void writeLightShadows(const Light& light, nlohmann::json& out) {
    if (light.type == LightType::Ambient) return;
    if (light.castsShadows) out["casts_shadows"] = true;
    const ShadowSettings defaults;
    const ShadowSettings& settings = light.shadow;
    if (settings.mapResolution == defaults.mapResolution && settings.depthBias == defaults.depthBias &&
        settings.normalOffset == defaults.normalOffset && settings.filterRadius == defaults.filterRadius)
        return;
    out["shadow"] = {{"map_resolution", settings.mapResolution},
                     {"depth_bias", settings.depthBias},
                     {"normal_offset", settings.normalOffset},
                     {"filter_radius", settings.filterRadius}};
}

}  // namespace glint
