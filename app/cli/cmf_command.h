// `glint cmf -o OUT.png [--size WxH]`: the plot of the CIE 1931 colour matching functions
// (app/classroom/cmf_plot.h), drawn headless through the overlay canvas, as the editor's
// View ▸ Colour matching functions window shows it. Arguments and output only.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 written, 2 bad arguments, no GL context or failure to write.
void addCmfCommand(CLI::App& glint);

}  // namespace glint
