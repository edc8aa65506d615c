// RenderTarget: a framebuffer object with one colour attachment (and optionally depth), single
// or multisampled, resized on demand. Owns its GL objects.
#pragma once

#include <glad/gl.h>

namespace glint {

class RenderTarget {
public:
    RenderTarget(GLenum colorFormat, bool withDepth) : colorFormat_(colorFormat), withDepth_(withDepth) {}
    ~RenderTarget() { release(); }
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // (Re)allocates when the size or sample count changes. samples = 1: textures (colour, and depth
    // for the overlay pass to read); else renderbuffers.
    void ensure(int width, int height, int samples);
    GLuint framebuffer() const { return framebuffer_; }
    GLuint colorTexture() const { return colorTexture_; }  // single-sample only
    GLuint depthTexture() const { return depthTexture_; }  // single-sample with depth only
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }  // as asked
    int allocatedSamples() const { return allocatedSamples_; }  // as allocated (GL_SAMPLES), ≥ samples()

private:
    void release();

    GLenum colorFormat_;
    bool withDepth_;
    GLuint framebuffer_ = 0, colorTexture_ = 0, colorRenderbuffer_ = 0, depthRenderbuffer_ = 0, depthTexture_ = 0;
    int width_ = 0, height_ = 0, samples_ = 0, allocatedSamples_ = 0;
};

}  // namespace glint
