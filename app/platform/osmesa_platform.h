// OsMesaPlatform: an offscreen OpenGL 4.1 core context from Mesa's OSMesa (llvmpipe), needing no
// X server. The renderer draws into its own framebuffers; OSMesa's buffer is a 1×1 placeholder.
#pragma once

#include <memory>

#include "gl/platform.h"
#include "util/diagnostic.h"

namespace glint {

class OsMesaPlatform final : public GlPlatform {
public:
    static Result<std::unique_ptr<OsMesaPlatform>> create();
    ~OsMesaPlatform() override;

    GetProcAddress procAddressLoader() const override;
    void makeCurrent() override;
    glm::ivec2 framebufferSize() const override { return {1, 1}; }
    void present() override {}
    const char* name() const override { return "OSMesa (offscreen)"; }

private:
    OsMesaPlatform() = default;
    void* context_ = nullptr;  // OSMesaContext
    unsigned char placeholder_[4] = {0, 0, 0, 0};
};

}  // namespace glint
