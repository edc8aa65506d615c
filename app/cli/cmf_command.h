// `glint cmf -o OUT.png [--size WxH]`: the plot of the CIE 1931 colour matching functions
// (app/classroom/cmf_plot.h), drawn headless through the overlay canvas, as the editor's
// View ▸ Colour matching functions window shows it. Arguments and output only.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Returns the process exit code: 0 written, 2 bad arguments, no GL context or failure to write.
int runCmfCommand(const std::vector<std::string>& arguments);

}  // namespace glint
