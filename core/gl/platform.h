// GlPlatform: what the renderer is handed instead of creating a context itself: a way to look
// up GL functions, to make the context current, the framebuffer size, and present. Two
// implementations live in app/platform: a GLFW window and OSMesa offscreen.
#pragma once

#include <glm/glm.hpp>

namespace glint {

using GlProc = void (*)();
using GetProcAddress = GlProc (*)(const char* name);

class GlPlatform {
public:
    virtual ~GlPlatform() = default;
    virtual GetProcAddress procAddressLoader() const = 0;
    virtual void makeCurrent() = 0;
    virtual glm::ivec2 framebufferSize() const = 0;  // of the default framebuffer, in pixels
    virtual void present() = 0;                      // swap buffers; nothing offscreen
    virtual const char* name() const = 0;            // for the status bar and logs
};

}  // namespace glint
