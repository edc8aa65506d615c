// `glint spectral SCENE.json -o OUT.png|OUT.exr [--size WxH] [--band NM,FWHM] [--cauchy-b B]
// [--wavelengths N]`: the scene rendered per wavelength on the CPU and converted to RGB through
// the CIE 1931 matching functions (core/colour/spectral_render.h). Arguments only; no rendering here.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 written, 2 bad arguments, bad input or failure to write.
void addSpectralCommand(CLI::App& glint);

}  // namespace glint
