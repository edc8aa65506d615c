// GL textures for texture images (see texture_cache.h).
#include "gl/texture_cache.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace glint {

// Anisotropic filtering is capped at 16 samples along the footprint's major axis, the common
// hardware limit (and what llvmpipe offers).
constexpr float kAnisotropyCap = 16.0f;

namespace {

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Repeat: return GL_REPEAT;
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

GLint glMinFilter(const MaterialTexture& texture) {
    switch (texture.minFilter) {
        case TextureMinFilter::Default: break;
        case TextureMinFilter::Nearest: return GL_NEAREST;
        case TextureMinFilter::Linear: return GL_LINEAR;
        case TextureMinFilter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
        case TextureMinFilter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
        case TextureMinFilter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
        case TextureMinFilter::LinearMipmapLinear: return GL_LINEAR_MIPMAP_LINEAR;
    }
    if (texture.filter == TextureFilter::Nearest) return GL_NEAREST;
    if (texture.filter == TextureFilter::Bilinear) return GL_LINEAR;  // level 0 only
    return GL_LINEAR_MIPMAP_LINEAR;
}

}  // namespace

TextureCache::~TextureCache() {
    for (auto& [key, texture] : textures_) glDeleteTextures(1, &texture);
    for (auto& [key, sampler] : samplers_) glDeleteSamplers(1, &sampler);
}

float TextureCache::maxAnisotropy() {
    if (maxAnisotropy_ > 0.0f) return maxAnisotropy_;
    maxAnisotropy_ = 1.0f;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
        if (name && (!std::strcmp(name, "GL_ARB_texture_filter_anisotropic") ||
                     !std::strcmp(name, "GL_EXT_texture_filter_anisotropic"))) {
            GLfloat supported = 1.0f;
            glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &supported);
            maxAnisotropy_ = std::clamp(supported, 1.0f, kAnisotropyCap);
            break;
        }
    }
    return maxAnisotropy_;
}

GLuint TextureCache::upload(const TextureImage& image) {
    // A changed file (same path and colour space, another time) replaces its old upload.
    for (auto it = textures_.begin(); it != textures_.end();) {
        if (std::get<0>(it->first) == image.path && std::get<2>(it->first) == image.colorSpace) {
            glDeleteTextures(1, &it->second);
            it = textures_.erase(it);
        } else {
            ++it;
        }
    }
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Rows are bottom-up in TextureImage, as GL expects; float keeps the CPU reference's values.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, image.width, image.height, 0, GL_RGBA, GL_FLOAT, image.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);  // box-filtered chain down to 1×1
    textures_[{image.path, image.modifiedAt, image.colorSpace}] = texture;
    ++uploads_;
    return texture;
}

int TextureCache::maxTextureSize() {
    if (maxTextureSize_ == 0) glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize_);
    return maxTextureSize_;
}

Status TextureCache::bind(GLenum unit, const MaterialTexture& texture) {
    const TextureImage& image = *texture.image;
    glActiveTexture(unit);
    auto found = textures_.find({image.path, image.modifiedAt, image.colorSpace});
    if (found != textures_.end()) {
        glBindTexture(GL_TEXTURE_2D, found->second);
    } else {
        if (image.width > maxTextureSize() || image.height > maxTextureSize())
            return makeError("texture image is " + std::to_string(image.width) + "×" + std::to_string(image.height) +
                                 " texels, larger than this GPU's limit of " + std::to_string(maxTextureSize()) +
                                 " a side (GL_MAX_TEXTURE_SIZE); objects with this texture are not drawn: scale the image down",
                             {image.path});
        upload(image);
    }
    // A sampler object, not the texture's own state: one image may be sampled two ways at once.
    glBindSampler(unit - GL_TEXTURE0, sampler(texture));
    return success();
}

GLuint TextureCache::sampler(const MaterialTexture& texture) {
    const SamplerKey key{texture.filter, texture.minFilter, texture.wrapU, texture.wrapV};
    if (auto found = samplers_.find(key); found != samplers_.end()) return found->second;
    GLuint sampler = 0;
    glGenSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, glMinFilter(texture));
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, texture.filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, glWrap(texture.wrapU));
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, glWrap(texture.wrapV));
    const float anisotropy = maxAnisotropy();
    if (anisotropy > 1.0f)
        glSamplerParameterf(sampler, GL_TEXTURE_MAX_ANISOTROPY, texture.filter == TextureFilter::Anisotropic ? anisotropy : 1.0f);
    samplers_[key] = sampler;
    return sampler;
}

}  // namespace glint
