// GL textures for texture images (see texture_cache.h).
#include "gl/texture_cache.h"

#include <algorithm>
#include <cstring>

namespace glint {

// Anisotropic filtering is capped at 16 samples along the footprint's major axis, the common
// hardware limit (and what llvmpipe offers).
constexpr float kAnisotropyCap = 16.0f;

TextureCache::~TextureCache() {
    for (auto& [key, texture] : textures_) glDeleteTextures(1, &texture);
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
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    textures_[{image.path, image.modifiedAt, image.colorSpace}] = texture;
    ++uploads_;
    return texture;
}

void TextureCache::bind(GLenum unit, const MaterialTexture& texture) {
    const TextureImage& image = *texture.image;
    glActiveTexture(unit);
    auto found = textures_.find({image.path, image.modifiedAt, image.colorSpace});
    if (found != textures_.end()) glBindTexture(GL_TEXTURE_2D, found->second);
    else upload(image);
    GLint minFilter = GL_LINEAR_MIPMAP_LINEAR, magFilter = GL_LINEAR;
    if (texture.filter == TextureFilter::Nearest) minFilter = magFilter = GL_NEAREST;
    if (texture.filter == TextureFilter::Bilinear) minFilter = GL_LINEAR;  // level 0 only
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, magFilter);
    const float anisotropy = maxAnisotropy();
    if (anisotropy > 1.0f)
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY,
                        texture.filter == TextureFilter::Anisotropic ? anisotropy : 1.0f);
}

}  // namespace glint
