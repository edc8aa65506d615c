// TransmissionPass: the screen-space transmission backdrop on the GPU (three.js's transmission
// render target, Filament's refraction pass). In a frame with transmissive materials the renderer
// draws the opaque objects first, over a clear of zero coverage; this pass copies that radiance and
// coverage (resolving MSAA) into a float texture and makes its mip chain; the renderer draws the
// background, then the transmissive surfaces, which look the backdrop up
// (shaders/common/transmission_backdrop.glsl; CPU twin core/render/transmission_backdrop.h).
// It draws no object itself. Frames without transmission never touch it.
#pragma once

#include <memory>
#include <vector>

#include <glad/gl.h>

#include "gl/shader_program.h"
#include "render/transmission_backdrop.h"

namespace glint {

inline constexpr GLint kTransmissionBackdropUnit = 17;

class TransmissionPass {
public:
    static Result<std::unique_ptr<TransmissionPass>> create(const ShaderSources& sources);
    ~TransmissionPass();
    TransmissionPass(const TransmissionPass&) = delete;
    TransmissionPass& operator=(const TransmissionPass&) = delete;

    // Copies colour attachment 0 of `source` (width×height, single or multisampled) into the
    // backdrop and makes its mip chain. Leaves the framebuffer, viewport, program and scissor
    // changed (scissor off): the caller sets its own again.
    void capture(GLuint source, int width, int height, GLuint emptyVertexArray);
    // A frame that shows no backdrop: transmissive surfaces see the environment or background.
    void forget() { captured_ = false; }
    // Whether transmissive surfaces see a backdrop this frame, and what their programs' prelude
    // then defines (shaders/common/transmission_backdrop.glsl: without it the lookups are not
    // compiled in, and cost nothing).
    bool shows() const { return captured_; }
    static constexpr const char* kProgramDefine = "#define GLINT_TRANSMISSION_BACKDROP 1\n";
    // Whether a captured backdrop of this size is held.
    bool holds(int width, int height) const { return captured_ && width == width_ && height == height_; }
    // Points a surface program's backdrop at the texture (or tells it there is none).
    void bind(const ShaderProgram& program) const;
    // The last capture's base level (empty when none is held).
    OpaquePassImage read() const;

private:
    TransmissionPass() = default;
    void allocate(int width, int height);

    ShaderProgram downsample_;
    GLuint texture_ = 0;
    std::vector<GLuint> levelFramebuffers_;  // one per mip level, its colour attachment
    int width_ = 0, height_ = 0;
    bool captured_ = false;
};

}  // namespace glint
