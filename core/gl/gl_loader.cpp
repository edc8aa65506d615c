// GL loading and error checks (see gl_loader.h).
#include "gl/gl_loader.h"

#include <glad/gl.h>

#include <mutex>

namespace glint {

Status loadGlFunctions(const GlPlatform& platform) {
    // glad's function pointers are process-global. OSMesa's are the same for every context, so
    // several threads, each with its own context, share one load: the first caller loads, later
    // callers with the same loader reuse it (and never rewrite pointers another thread is using).
    static std::mutex loadMutex;
    static GetProcAddress loadedWith = nullptr;
    static int loadedVersion = 0;
    const std::lock_guard<std::mutex> lock(loadMutex);
    if (loadedWith != platform.procAddressLoader() || loadedVersion == 0) {
        loadedVersion = gladLoadGL(reinterpret_cast<GLADloadfunc>(platform.procAddressLoader()));
        loadedWith = platform.procAddressLoader();
    }
    const int version = loadedVersion;
    if (version == 0) return makeError(std::string("could not load OpenGL functions through ") + platform.name());
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 4 || (major == 4 && minor < 1))
        return makeError("OpenGL 4.1 core is needed; " + std::string(platform.name()) + " gives " +
                         std::to_string(major) + "." + std::to_string(minor));
    return success();
}

std::string glDescription() {
    auto text = [](GLenum name) {
        const GLubyte* value = glGetString(name);
        return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

Status takeGlErrors(const char* where) {
    std::string codes;
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", error);
        codes += std::string(codes.empty() ? "" : ", ") + hex;
    }
    if (codes.empty()) return success();
    return makeError(std::string("OpenGL error ") + codes + " in " + where);
}

}  // namespace glint
