// BrdfSampler: f_r of a custom BRDF (.brdf GLSL) at a list of direction pairs, evaluated by its own
// shader in one offscreen pass (shaders/brdf_sampler.frag, the wrapper of custom_brdf_program.h)
// and read back as floats: how the classroom plots see a BRDF that has no CPU twin. It does not
// prove that the shader finishes (app/runtime/brdf_probe.h): hand it only BRDFs that passed the probe.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "gl/custom_brdf_program.h"
#include "gl/render_target.h"

namespace glint {

class BrdfSampler {
public:
    explicit BrdfSampler(ShaderSources sources);
    ~BrdfSampler();
    BrdfSampler(const BrdfSampler&) = delete;
    BrdfSampler& operator=(const BrdfSampler&) = delete;

    // Compiles the sampling program of `brdf` (cached): its compile error, located in the .brdf
    // file, or success. sample() needs this to have succeeded.
    Status prepare(const CustomBrdf& brdf);
    // f_r [1/sr] per channel at each (incident[k], outgoing[k]) in the local frame (tangent x,
    // bitangent y, normal z), with `values` packed per brdf.table. Needs a current GL context (the
    // same each call); leaves the framebuffer, program, viewport and texture bindings as it found
    // them. Errors: prepare()'s, or a GL error.
    Result<std::vector<glm::vec3>> sample(const CustomBrdf& brdf, const std::vector<float>& values,
                                          std::span<const glm::vec3> incident, std::span<const glm::vec3> outgoing);

private:
    // Pairs per row of the direction and result textures.
    static constexpr int kRowLength = 512;
    // Texture units for the two direction textures, clear of the renderer's (material 1..,
    // measured 16, environment 13-15, shadows 24-31).
    static constexpr GLint kIncidentUnit = 20, kOutgoingUnit = 21;

    ShaderSources sources_;
    CustomBrdfPrograms programs_;
    std::uint64_t calls_ = 0;  // prepare() and sample() calls: the programs' "frames"
    GLuint directionTextures_[2] = {0, 0}, emptyVertexArray_ = 0;
    int width_ = 0, height_ = 0;  // the direction textures' size (0: not made yet)
    RenderTarget result_{GL_RGBA32F, false};  // f_r per pair
};

}  // namespace glint
