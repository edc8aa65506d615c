// TextureCache: GL textures for decoded texture images, uploaded once per (path, modification
// time, colour space) as linear RGBA32F with a full mipmap chain, and one sampler object per
// sampler state: the texture's filter (nearest, bilinear, trilinear, anisotropic where the context
// offers GL_ARB/EXT_texture_filter_anisotropic; trilinear otherwise), its minification filter and
// its wrap modes along u and v. Decoding is core/texture.
#pragma once

#include <map>
#include <string>
#include <tuple>

#include <glad/gl.h>

#include "texture/material_texture.h"
#include "util/diagnostic.h"

namespace glint {

class TextureCache {
public:
    TextureCache() = default;
    ~TextureCache();  // the context must be current
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    // Binds the texture's image to `unit` with its sampler state. An image whose file changed
    // since it was uploaded replaces the old upload. Error: the image is larger than the context's
    // GL_MAX_TEXTURE_SIZE (then nothing is bound).
    Status bind(GLenum unit, const MaterialTexture& texture);

    // Largest texture side the context takes (GL_MAX_TEXTURE_SIZE); queried on first use.
    int maxTextureSize();
    // Largest anisotropy the context supports (1 when the extension is absent); queried on first use.
    float maxAnisotropy();
    // Images uploaded so far (the same image twice counts once).
    int uploads() const { return uploads_; }

private:
    using Key = std::tuple<std::string, long long, TextureColorSpace>;
    using SamplerKey = std::tuple<TextureFilter, TextureMinFilter, TextureWrap, TextureWrap>;
    GLuint upload(const TextureImage& image);
    GLuint sampler(const MaterialTexture& texture);

    std::map<Key, GLuint> textures_;
    std::map<SamplerKey, GLuint> samplers_;
    int uploads_ = 0;
    float maxAnisotropy_ = 0.0f;  // 0: not queried yet
    int maxTextureSize_ = 0;  // 0: not queried yet
};

}  // namespace glint
