// `glint info FILE`: what a file holds, for every format Glint reads (interchange files'
// materials, lights and meshes with their names; a mesh's counts; a .brdf's or .bparam's
// parameters; a scene's materials, objects and lights), and the warnings opening it gives.
// Reading only; nothing is rendered.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 listed, 2 bad arguments or a file that does not load.
void addInfoCommand(CLI::App& glint);

}  // namespace glint
