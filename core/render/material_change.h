// Which pixels a change of material values reaches, so that a frame held in the renderer's
// targets is redrawn only there (the editor, while a material slider moves; gl/renderer.h).
// A material's values reach only the pixels of the objects drawn with it: no light, shadow map or
// sphere occlusion depends on them, and reflected rays see only the environment or background
// (render/specular_transport.h). A transmissive object sees the other objects through its
// backdrop, so a scene with one is redrawn whole.
#pragma once

#include <optional>
#include <vector>

#include "render/visibility.h"
#include "scene/scene.h"

namespace glint {

// What a change of material values reaches in a width × height frame.
struct MaterialChange {
    PixelRegion rect;  // the covered rectangle of the changed materials' objects; empty when none is in the frame
    std::vector<bool> materials;  // by material index: whether its values changed
};

// How a frame of `after` may differ from one of `before`: the covered rectangle (render/visibility.h)
// of every object whose material's values changed. None when the scenes differ in anything else (as
// the scene file writes them, or the environment map) or not at all, when any material has textures,
// a .brdf shader or a measured table (files that may change under the same scene), or when the
// scene has a transmissive object.
std::optional<MaterialChange> materialChange(const Scene& before, const Scene& after, int width, int height);

}  // namespace glint
