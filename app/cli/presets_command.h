// `glint presets [NAME -o FILE.json]`: lists the material presets (name, category, model,
// source), or writes one as a material file. The table itself lives in core/brdf/presets.h.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Returns the process exit code: 0 listed or written, 2 unknown preset, bad arguments or write failure.
int runPresetsCommand(const std::vector<std::string>& arguments);

}  // namespace glint
