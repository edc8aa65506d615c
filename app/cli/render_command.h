// `glint render SCENE -o OUT.png|OUT.exr [--size WxH] [--msaa N] [--reference [--samples N]]`:
// renders a scene file (or a material file, on the preview stage) headless (OSMesa, or the CPU
// reference, whose environment light --samples integrates by Monte-Carlo) and writes the image; `--probe X,Y` prints the surface probe there, `--overlay NAME` draws a
// classroom overlay (cli/render_overlays.h) over the PNG.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 written, 2 bad arguments or input, or failure to render.
void addRenderCommand(CLI::App& glint);

}  // namespace glint
