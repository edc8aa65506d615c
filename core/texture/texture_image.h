// Image textures through OpenImageIO (PNG, JPEG, EXR, HDR, TIFF, ...), from a file or from bytes in
// memory: decoded to linear RGBA floats, validated (unreadable, truncated, zero size, non-finite
// texels), cached so that an image is decoded once. No GPU work here.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
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

// Decodes an encoded image held in memory (an image inside a glTF): `format` is its file
// extension ("png", "jpg"), `name` identifies it in messages and to the GPU's texture cache (which
// also keys on `modifiedAt`, the time its file was modified). Cached by name, modification time,
// colour space and the bytes, so that the textures of one glTF image decode it once.
Result<std::shared_ptr<const TextureImage>> decodeTextureImage(std::span<const uint8_t> encoded, const std::string& format,
                                                               const std::string& name, long long modifiedAt,
                                                               TextureColorSpace colorSpace);

}  // namespace glint
