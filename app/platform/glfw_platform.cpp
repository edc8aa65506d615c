// GLFW window platform (see glfw_platform.h).
#include "platform/glfw_platform.h"

#include <GLFW/glfw3.h>

#include <algorithm>

#include "platform/x11_errors.h"

// GLFW's X11 and GLX handles (GLFW/glfw3native.h, declared here without the X11 headers it needs).
extern "C" struct _XDisplay* glfwGetX11Display();
extern "C" unsigned long glfwGetGLXWindow(GLFWwindow* window);

namespace glint {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

void requestCoreContext() {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
}

// The size asked for, made to fit the primary screen's work area (a classroom projector at
// 1024×768): a window manager may not shrink a larger window, and without one the right column
// would lie off the screen.
void fitToWorkArea(int& width, int& height) {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return;
    int x = 0, y = 0, areaWidth = 0, areaHeight = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &areaWidth, &areaHeight);
    if (areaWidth > 0 && areaHeight > 0) width = std::min(width, areaWidth), height = std::min(height, areaHeight);
}

// The hidden window's context, current on the worker thread.
class GlfwWorkerContext final : public GlWorkerContext {
public:
    explicit GlfwWorkerContext(GLFWwindow* window) : window_(window) {}
    ~GlfwWorkerContext() override { glfwDestroyWindow(window_); }
    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    void release() override { glfwMakeContextCurrent(nullptr); }

private:
    GLFWwindow* window_;
};

}  // namespace

Result<std::unique_ptr<GlfwPlatform>> GlfwPlatform::create(int width, int height, const std::string& title) {
    if (!glfwInit()) return makeError("cannot open a window: " + lastGlfwError());
    requestCoreContext();
    fitToWorkArea(width, height);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        return makeError("cannot open an OpenGL 4.1 core window: " + reason);
    }
    std::unique_ptr<GlfwPlatform> platform(new GlfwPlatform());
    platform->window_ = window;
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (glfwExtensionSupported("GLX_MESA_copy_sub_buffer"))
        platform->copySubBuffer_ = reinterpret_cast<decltype(copySubBuffer_)>(glfwGetProcAddress("glXCopySubBufferMESA"));
    return platform;
}

GlfwPlatform::~GlfwPlatform() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::unique_ptr<GlWorkerContext> GlfwPlatform::createWorkerContext() {
    glfwDefaultWindowHints();
    requestCoreContext();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* hidden = glfwCreateWindow(1, 1, "glint worker", nullptr, window_);
    glfwDefaultWindowHints();
    if (!hidden) return nullptr;
    return std::make_unique<GlfwWorkerContext>(hidden);
}

GetProcAddress GlfwPlatform::procAddressLoader() const { return reinterpret_cast<GetProcAddress>(&glfwGetProcAddress); }

void GlfwPlatform::makeCurrent() {
    if (glfwGetCurrentContext() != window_) glfwMakeContextCurrent(window_);
}

glm::ivec2 GlfwPlatform::framebufferSize() const {
    glm::ivec2 size;
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

void GlfwPlatform::present() {
    keepXErrorsNonFatal();
    glfwSwapBuffers(window_);
}

void GlfwPlatform::presentRegion(int x, int y, int width, int height) {
    keepXErrorsNonFatal();
    copySubBuffer_(glfwGetX11Display(), glfwGetGLXWindow(window_), x, y, width, height);  // flushes first
}

}  // namespace glint
