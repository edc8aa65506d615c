// GlfwPlatform: a window with an OpenGL 4.1 core context from GLFW (GLX under X11/Xvfb).
// It owns the window; the editor asks it for input and events through window().
#pragma once

#include <memory>
#include <string>

#include "gl/platform.h"
#include "util/diagnostic.h"

struct GLFWwindow;

namespace glint {

class GlfwPlatform final : public GlPlatform {
public:
    // Fails (with GLFW's reason) when there is no display or no GL 4.1 core.
    static Result<std::unique_ptr<GlfwPlatform>> create(int width, int height, const std::string& title);
    ~GlfwPlatform() override;

    GetProcAddress procAddressLoader() const override;
    void makeCurrent() override;
    glm::ivec2 framebufferSize() const override;
    void present() override;
    // Whether presentRegion() is offered (GLX_MESA_copy_sub_buffer, as Mesa's llvmpipe has). An editor
    // that presents only regions never swaps, so the back buffer keeps every pixel it was given.
    bool presentsRegions() const { return copySubBuffer_ != nullptr; }
    // Puts the back buffer's rectangle (pixels, lower-left origin) on screen.
    void presentRegion(int x, int y, int width, int height);
    const char* name() const override { return "GLFW window"; }
    // A hidden window whose context shares the editor window's objects (programs built in the
    // background, gl/program_compiler.h); null when GLFW refuses one.
    std::unique_ptr<GlWorkerContext> createWorkerContext() override;

    GLFWwindow* window() const { return window_; }

private:
    GlfwPlatform() = default;
    GLFWwindow* window_ = nullptr;
    void (*copySubBuffer_)(void* display, unsigned long drawable, int x, int y, int width, int height) = nullptr;
};

}  // namespace glint
