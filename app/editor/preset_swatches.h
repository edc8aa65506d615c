// Swatches for the preset browser: each preset rendered once on the preview stage
// (scene/preview_stage.h), one per editor frame while the browser is open, and kept as a texture
// for the rest of the session. The browser asks (PresetSwatches::wanted); the main loop renders.
#pragma once

#include <map>
#include <string>

namespace glint {

class Renderer;

inline constexpr int kPresetSwatchPixels = 64;  // rendered size, square

struct PresetSwatches {
    std::map<std::string, unsigned int> textures;  // GL texture names, by preset name
    bool wanted = false;  // the browser showed a preset whose swatch is missing
};

// Renders the first missing swatch when one is wanted; true when it used the renderer (the
// viewport must be drawn again).
bool updatePresetSwatches(PresetSwatches& swatches, Renderer& renderer);

}  // namespace glint
