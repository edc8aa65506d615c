// `glint export IN -o OUT.mtl|OUT.gltf`: writes Glint materials (from a material file, a scene,
// or another interchange file) as a Wavefront .mtl library or a self-contained glTF 2.0 file.
// Conversion only; nothing is rendered.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Returns the process exit code: 0 written, 2 bad arguments or input, or failure to write.
int runExportCommand(const std::vector<std::string>& arguments);

}  // namespace glint
