// Preset swatches (see preset_swatches.h).
#include "editor/preset_swatches.h"

#include <cstdio>

#include <glad/gl.h>

#include "brdf/presets.h"
#include "gl/display_texture.h"
#include "gl/renderer.h"
#include "scene/preview_stage.h"

namespace glint {

bool updatePresetSwatches(PresetSwatches& swatches, Renderer& renderer) {
    if (!swatches.wanted) return false;
    swatches.wanted = false;
    for (const Preset& preset : allPresets()) {
        if (swatches.textures.count(preset.name)) continue;
        const Scene stage = previewStage(preset.material(), kPresetSwatchPixels, kPresetSwatchPixels);
        GLuint texture = 0;
        if (Status status = renderer.renderRadiance(stage, kPresetSwatchPixels, kPresetSwatchPixels); !status) {
            std::fprintf(stderr, "glint: swatch of %s: %s\n", preset.name, status.error().format().c_str());
        } else {
            renderer.displayOffscreen(stage.display);
            texture = uploadDisplayTexture(renderer.readDisplay(), GL_LINEAR);  // drawn at the UI's scale
        }
        swatches.textures[preset.name] = texture;  // 0 (failed): not tried again, the row shows no swatch
        return true;
    }
    return false;
}

}  // namespace glint
