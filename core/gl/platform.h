// GlPlatform: what the renderer is handed instead of creating a context itself: a way to look
// up GL functions, to make the context current, the framebuffer size, and present. Two
// implementations live in app/platform: a GLFW window and OSMesa offscreen.
#pragma once

#include <memory>

#include <glm/glm.hpp>

namespace glint {

using GlProc = void (*)();
using GetProcAddress = GlProc (*)(const char* name);

// A second GL context that shares objects (programs) with the platform's, for a worker thread
// (gl/program_compiler.h). Made current on the worker, released there before it ends; destroyed
// on the thread that created it.
class GlWorkerContext {
public:
    virtual ~GlWorkerContext() = default;
    virtual void makeCurrent() = 0;
    virtual void release() = 0;  // no context current on the calling thread
};

class GlPlatform {
public:
    virtual ~GlPlatform() = default;
    virtual GetProcAddress procAddressLoader() const = 0;
    virtual void makeCurrent() = 0;
    virtual glm::ivec2 framebufferSize() const = 0;  // of the default framebuffer, in pixels
    virtual void present() = 0;                      // swap buffers; nothing offscreen
    virtual const char* name() const = 0;            // for the status bar and logs
    // A context for a worker thread sharing this one's objects; null where there is none
    // (offscreen renders compile where they draw).
    virtual std::unique_ptr<GlWorkerContext> createWorkerContext() { return nullptr; }
};

}  // namespace glint
