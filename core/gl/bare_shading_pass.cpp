// The bare shading pass (see bare_shading_pass.h).
#include "gl/bare_shading_pass.h"

#include <algorithm>

#include "gl/environment_textures.h"
#include "gl/frame_uniforms.h"
#include "gl/material_glsl.h"
#include "gl/shadow_maps.h"
#include "gl/uniform_blocks.h"

namespace glint {

Result<std::unique_ptr<BareShadingPass>> BareShadingPass::create(const ShaderSources& sources, const AnalyticMaterial& material) {
    const GeneratedShaderFiles generated = {{"generated/material.glsl", generateMaterialGlsl(modelInfo(material.model))}};
    auto program = ShaderProgram::build(sources, "fullscreen.vert", "bare_shading.frag", "", generated);
    if (!program) return program.error();
    program->bindBlock("FrameBlock", kFirstBinding + 0);
    program->bindBlock("LightBlock", kFirstBinding + 1);
    program->bindBlock("MaterialBlock", kFirstBinding + 2);
    // The environment and shadow maps are the renderer's, as its last frame of the same scene left
    // them bound: the bare pass evaluates the same lighting code on the same data.
    EnvironmentTextures::connect(*program);
    return std::unique_ptr<BareShadingPass>(new BareShadingPass(std::move(*program), material));
}

BareShadingPass::BareShadingPass(ShaderProgram program, const AnalyticMaterial& material)
    : program_(std::move(program)), material_(material) {
    glGenBuffers(3, uniformBuffers_);
    glGenVertexArrays(1, &emptyVertexArray_);
}

BareShadingPass::~BareShadingPass() {
    glDeleteBuffers(3, uniformBuffers_);
    glDeleteVertexArrays(1, &emptyVertexArray_);
}

void BareShadingPass::draw(const Scene& scene, int width, int height) {
    target_.ensure(width, height, 1);
    const FrameUniforms uniforms = packFrameUniforms(scene, width, height);
    MaterialBlockStd140 material{};
    std::copy_n(material_.values.begin(), std::min<size_t>(material_.values.size(), kMaterialBlockFloats), material.values);
    const void* blocks[3] = {&uniforms.frame, &uniforms.lights, &material};
    const GLsizeiptr sizes[3] = {sizeof uniforms.frame, sizeof uniforms.lights, sizeof material};
    for (GLuint i = 0; i < 3; ++i) {
        glBindBufferBase(GL_UNIFORM_BUFFER, kFirstBinding + i, uniformBuffers_[i]);
        glBufferData(GL_UNIFORM_BUFFER, sizes[i], blocks[i], GL_STREAM_DRAW);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    assignShadowSamplerUnits(program_);  // sets uniforms of the program in use
    SphereShape sphere;
    for (const SceneObject& object : scene.objects)
        if (const auto* found = std::get_if<SphereShape>(&object.shape)) {
            sphere = *found;
            break;
        }
    glUniform1i(program_.uniform("shapeKind"), 1);
    glUniform4f(program_.uniform("sphere"), sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius);
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace glint
