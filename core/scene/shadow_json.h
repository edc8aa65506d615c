// The shadow keys of a light in a scene file: "casts_shadows" and the optional "shadow" object
// (map_resolution, depth_bias, normal_offset, filter_radius), read with located errors and
// written back. Documented in docs/scene-format.md; it knows nothing else of the file.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "light/light.h"
#include "scene/json_object_reader.h"

namespace glint {

// Reads the shadow keys of one light (refused on ambient lights, which cast no shadows).
void readLightShadows(ObjectReader& reader, Light& light);
// Refuses more than kMaxShadowedLights lights with castsShadows, located at the "lights" key.
void checkShadowedLightCount(ObjectReader& root, const std::vector<Light>& lights);
// Writes "casts_shadows" when on and "shadow" when any setting differs from its default.
void writeLightShadows(const Light& light, nlohmann::json& out);

}  // namespace glint
