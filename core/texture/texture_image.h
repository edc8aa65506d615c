// Image textures through OpenImageIO (PNG, JPEG, EXR, HDR, TIFF, ...): decoded to linear RGBA
// floats, validated (unreadable, truncated, zero size, non-finite texels), cached by path,
// modification time and colour space so that a file is decoded once. No GPU work here.
#pragma once

#include <memory>
#include <string>

#include "texture/material_texture.h"
#include "util/diagnostic.h"

namespace glint {

// Largest side accepted [texels]: the least GL_MAX_TEXTURE_SIZE that OpenGL 4.1 allows, so every
// GPU Glint runs on takes it (gl/texture_cache.h checks the context's own limit too). A larger
// image is refused, not downscaled: the CPU reference and the GPU would otherwise see other texels.
inline constexpr int kMaxTextureSize = 16384;

// Decodes `path` (sRGB-encoded values are decoded to linear, decodeSrgb() of display_chain.h).
// Errors carry the file name and say what is wrong with it.
Result<std::shared_ptr<const TextureImage>> loadTextureImage(const std::string& path, TextureColorSpace colorSpace);

}  // namespace glint
