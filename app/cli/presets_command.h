// `glint presets [NAME -o FILE.json]`: lists the material presets (name, category, model,
// source), or writes one as a material file. The table itself lives in core/brdf/presets.h.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 listed or written, 2 unknown preset, bad arguments or write failure.
void addPresetsCommand(CLI::App& glint);

}  // namespace glint
