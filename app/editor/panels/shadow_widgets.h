// The selected light's shadow widgets in the lights section: the "Casts shadows" checkbox and,
// when on, its map resolution, depth bias, normal offset and PCF filter radius. It edits a copy
// of the light; lights_panel.cpp commits the copy as one undo step.
#pragma once

#include <string>

#include "scene/scene.h"

namespace glint {

// Draws the widgets for `light` (none for ambient lights); `otherShadowedLights` counts the
// scene's other lights that cast shadows (the checkbox is refused past kMaxShadowedLights).
// Returns true when the copy changed and is valid; a refused value goes to `refusal`.
bool drawShadowSettings(Light& light, int otherShadowedLights, std::string& refusal);

// How many lights of the scene other than `except` cast shadows.
int shadowedLightsOtherThan(const Scene& scene, int except);

}  // namespace glint
