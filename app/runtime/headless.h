// Headless rendering: an OSMesa context and a Renderer, and the one call that turns a scene
// into radiance and display images. Used by `glint render` and the editor's no-display
// fallback; one context serves any number of renders.
#pragma once

#include <memory>

#include "gl/renderer.h"
#include "platform/osmesa_platform.h"

namespace glint {

struct RenderedImages {
    RadianceImage radiance;
    DisplayImage display;
};

class HeadlessRenderer {
public:
    static Result<std::unique_ptr<HeadlessRenderer>> create();
    // withRadiance = false: only the display image (a PNG render), its radiance left empty; the
    // float image is then not even drawn (RendererOptions::keepRadiance).
    Result<RenderedImages> render(const Scene& scene, int width, int height, bool withRadiance = true);
    Renderer& renderer() { return *renderer_; }

private:
    std::unique_ptr<OsMesaPlatform> platform_;
    std::unique_ptr<Renderer> renderer_;
};

// Writes EXR (linear radiance) or an 8-bit format (display-encoded), chosen by extension.
Status writeRenderedImage(const RenderedImages& images, const std::string& path);

}  // namespace glint
