// BareShadingPass: the yardstick of `glint bench` and of issue 3's figure — one full-screen pass
// that evaluates a material's BRDF for a scene's lights at every pixel (shaders/bare_shading.frag)
// into a float target like the renderer's, with no scene geometry, no background, no display.
// It draws nothing anyone looks at and does not time itself; the caller times draw() + glFinish.
#pragma once

#include <memory>

#include "gl/render_target.h"
#include "gl/renderer.h"
#include "gl/shader_program.h"

namespace glint {

class BareShadingPass {
public:
    // Builds the pass for the model of `material`; the GL context must be current.
    static Result<std::unique_ptr<BareShadingPass>> create(const ShaderSources& sources, const AnalyticMaterial& material);
    ~BareShadingPass();
    BareShadingPass(const BareShadingPass&) = delete;
    BareShadingPass& operator=(const BareShadingPass&) = delete;

    // One pass at width×height: the scene's lights and ambient packed by the renderer's own code
    // (frame_uniforms.h, so the light loop runs as often), the material's values, the scene's
    // first sphere for the traced lobes of mirror and glass. Uploads its uniforms each time, as
    // the renderer does each frame.
    void draw(const Scene& scene, int width, int height);

private:
    BareShadingPass(ShaderProgram program, const AnalyticMaterial& material);

    // Binding points of its own, so that the renderer's (0-2) stay bound to the renderer's buffers.
    static constexpr GLuint kFirstBinding = 8;
    ShaderProgram program_;
    AnalyticMaterial material_;
    GLuint uniformBuffers_[3] = {0, 0, 0};
    GLuint emptyVertexArray_ = 0;
    RenderTarget target_{Renderer::kRadianceFormat, false};
};

}  // namespace glint
