// The screen-space transmission backdrop on the GPU (see transmission_pass.h).
#include "gl/transmission_pass.h"

#include <algorithm>

namespace glint {

Result<std::unique_ptr<TransmissionPass>> TransmissionPass::create(const ShaderSources& sources) {
    auto program = ShaderProgram::build(sources, "fullscreen.vert", "transmission_downsample.frag");
    if (!program) return program.error();
    std::unique_ptr<TransmissionPass> pass(new TransmissionPass());
    pass->downsample_ = std::move(*program);
    return pass;
}

TransmissionPass::~TransmissionPass() {
    if (!levelFramebuffers_.empty()) glDeleteFramebuffers(static_cast<GLsizei>(levelFramebuffers_.size()), levelFramebuffers_.data());
    if (texture_) glDeleteTextures(1, &texture_);
}

void TransmissionPass::allocate(int width, int height) {
    if (texture_ && width == width_ && height == height_) return;
    if (!levelFramebuffers_.empty()) glDeleteFramebuffers(static_cast<GLsizei>(levelFramebuffers_.size()), levelFramebuffers_.data());
    if (texture_) glDeleteTextures(1, &texture_);
    width_ = width, height_ = height;
    int levels = 1;  // GL's full chain: halved (rounded down) until 1×1
    for (int larger = std::max(width, height); larger > 1; larger /= 2) ++levels;
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexStorage2D(GL_TEXTURE_2D, levels, GL_RGBA32F, width, height);  // the radiance targets' format: MSAA resolves into it
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);  // fetched texel by texel
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    levelFramebuffers_.resize(levels);
    glGenFramebuffers(levels, levelFramebuffers_.data());
    for (int level = 0; level < levels; ++level) {
        glBindFramebuffer(GL_FRAMEBUFFER, levelFramebuffers_[level]);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, level);
    }
}

void TransmissionPass::capture(GLuint source, int width, int height, GLuint emptyVertexArray) {
    allocate(width, height);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, levelFramebuffers_[0]);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    // Each level from the one above, read as the texture's only level (no feedback loop).
    glDisable(GL_DEPTH_TEST);
    glUseProgram(downsample_.id());
    glUniform1i(downsample_.uniform("source"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindVertexArray(emptyVertexArray);
    const int levels = static_cast<int>(levelFramebuffers_.size());
    for (int level = 1; level < levels; ++level) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 1);
        glBindFramebuffer(GL_FRAMEBUFFER, levelFramebuffers_[level]);
        glViewport(0, 0, std::max(1, width >> level), std::max(1, height >> level));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    captured_ = true;
}

void TransmissionPass::bind(const ShaderProgram& program) const {
    glActiveTexture(GL_TEXTURE0 + kTransmissionBackdropUnit);
    glBindTexture(GL_TEXTURE_2D, captured_ ? texture_ : 0);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(program.uniform("transmissionBackdrop"), kTransmissionBackdropUnit);
    glUniform1i(program.uniform("transmissionBackdropLevels"), captured_ ? static_cast<GLint>(levelFramebuffers_.size()) : 0);
}

OpaquePassImage TransmissionPass::read() const {
    if (!captured_) return {};
    OpaquePassImage image{width_, height_, std::vector<glm::vec4>(static_cast<size_t>(width_) * height_)};
    std::vector<glm::vec4> bottomUp(image.pixels.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, levelFramebuffers_[0]);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, bottomUp.data());
    for (int y = 0; y < height_; ++y)
        std::copy_n(&bottomUp[static_cast<size_t>(height_ - 1 - y) * width_], width_, &image.pixels[static_cast<size_t>(y) * width_]);
    return image;
}

}  // namespace glint
