// Framebuffer objects (see render_target.h).
#include "gl/render_target.h"

#include "util/diagnostic.h"

namespace glint {

void RenderTarget::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (colorTexture_) glDeleteTextures(1, &colorTexture_);
    if (colorRenderbuffer_) glDeleteRenderbuffers(1, &colorRenderbuffer_);
    if (depthRenderbuffer_) glDeleteRenderbuffers(1, &depthRenderbuffer_);
    if (depthTexture_) glDeleteTextures(1, &depthTexture_);
    framebuffer_ = colorTexture_ = colorRenderbuffer_ = depthRenderbuffer_ = depthTexture_ = 0;
}

namespace {

// A single-sample texture of `format` attached to the bound framebuffer at `attachment`.
GLuint attachTexture(GLenum format, GLenum attachment, int width, int height) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
    return texture;
}

// A multisample renderbuffer of `format` attached to the bound framebuffer at `attachment`.
GLuint attachRenderbuffer(GLenum format, GLenum attachment, int width, int height, int samples) {
    GLuint renderbuffer = 0;
    glGenRenderbuffers(1, &renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer);
    return renderbuffer;
}

}  // namespace

void RenderTarget::ensure(int width, int height, int samples) {
    if (framebuffer_ && width == width_ && height == height_ && samples == samples_) return;
    release();
    width_ = width, height_ = height, samples_ = samples;
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    if (samples == 1) colorTexture_ = attachTexture(colorFormat_, GL_COLOR_ATTACHMENT0, width, height);
    else colorRenderbuffer_ = attachRenderbuffer(colorFormat_, GL_COLOR_ATTACHMENT0, width, height, samples);
    if (withDepth_ && samples == 1)
        depthTexture_ = attachTexture(GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT, width, height);
    else if (withDepth_)
        depthRenderbuffer_ = attachRenderbuffer(GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT, width, height, samples);
    GLINT_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    allocatedSamples_ = samples;
    if (samples > 1) glGetIntegerv(GL_SAMPLES, &allocatedSamples_);
}

}  // namespace glint
