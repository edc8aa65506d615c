// Loads the GL 4.1 core functions through the platform's get-proc-address (glad) and checks
// the context's version. The only place that calls gladLoadGL.
#pragma once

#include <string>

#include "gl/platform.h"
#include "util/diagnostic.h"

namespace glint {

Status loadGlFunctions(const GlPlatform& platform);
// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6", for logs and the UI.
std::string glDescription();
// Any pending GL errors as one Diagnostic (GL_NO_ERROR gives success).
Status takeGlErrors(const char* where);

}  // namespace glint
