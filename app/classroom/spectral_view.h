// The editor's spectral render window (View ▸ Spectral render): the spectral settings (flat or
// narrow-band emitters, Cauchy's B, wavelength count), a Render button that renders the current
// scene per wavelength on the CPU (core/colour/spectral_render.h), and the image it made.
#pragma once

#include "editor/editor_state.h"

namespace glint {

// Renders the current scene with state.classroom.spectral into state.classroom.spectralImage
// (display-encoded with the scene's display settings); errors go to spectralMessage.
void renderSpectralImage(EditorState& state);
// The window; uploads a new image to its GL texture when one was rendered.
void drawSpectralWindow(EditorState& state);

}  // namespace glint
