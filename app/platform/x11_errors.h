// X11 protocol errors made non-fatal. Xlib's default handler prints an error and exits the
// process; Mesa's software presentation can meet one (a put-image refused while the window is
// being resized), and a lost frame must not cost the user's session. Not for errors GLFW traps
// itself (it installs its own handler around its calls, then restores Xlib's default).
#pragma once

namespace glint {

// Installs the handler that prints each X error and counts it; cheap, so it is installed again
// before each present, after GLFW may have put back the default.
void keepXErrorsNonFatal();
// X errors since the last call (the editor then draws the whole window again).
int takeXErrors();

}  // namespace glint
