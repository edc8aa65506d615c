// `glint export IN -o OUT.mtl|OUT.gltf`: writes Glint materials (from a material file, a scene,
// or another interchange file) as a Wavefront .mtl library or a self-contained glTF 2.0 file.
// Conversion only; nothing is rendered.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 written, 2 bad arguments or input, or failure to write.
void addExportCommand(CLI::App& glint);

}  // namespace glint
