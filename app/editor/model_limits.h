// Notes for what a material's model leaves out where a user would expect something: a mirror's
// or glass's delta lobe shows no highlight of point, spot or directional lights (a light of no
// size has a reflection of no area), and their reflections and refractions see the environment or
// background, never the other objects (render/specular_transport.h). Only the notes that apply
// to the scene as it is. Pure: the material panel shows them (panels/object_panel.cpp).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace glint {

std::vector<std::string> modelLimitNotes(const Scene& scene, int objectIndex);

}  // namespace glint
