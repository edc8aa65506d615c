// Headless rendering through OSMesa (see headless.h).
#include "runtime/headless.h"

#include "image/image_io.h"

namespace glint {

Result<std::unique_ptr<HeadlessRenderer>> HeadlessRenderer::create() {
    auto platform = OsMesaPlatform::create();
    if (!platform) return platform.error();
    auto renderer = Renderer::create(**platform, defaultShaderSources());
    if (!renderer) return renderer.error();
    auto headless = std::make_unique<HeadlessRenderer>();
    headless->platform_ = std::move(*platform);
    headless->renderer_ = std::move(*renderer);
    headless->renderer_->options().fuseDisplay = true;  // render() needs the display image of the scene's settings
    return headless;
}

Result<RenderedImages> HeadlessRenderer::render(const Scene& scene, int width, int height, bool withRadiance) {
    renderer_->options().keepRadiance = withRadiance;
    if (Status status = renderer_->renderRadiance(scene, width, height); !status) return status.error();
    renderer_->displayOffscreen(scene.display);
    return RenderedImages{withRadiance ? renderer_->readRadiance() : RadianceImage(), renderer_->readDisplay()};
}

Status writeRenderedImage(const RenderedImages& images, const std::string& path) {
    return isFloatImagePath(path) ? writeRadianceImage(images.radiance, path) : writeDisplayImage(images.display, path);
}

}  // namespace glint
