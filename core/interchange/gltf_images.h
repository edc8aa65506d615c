// Images stored inside a glTF 2.0 file (glTF 2.0 §3.6.1, §5.18 "image"): an image's bytes from a
// base64 `data:` URI, or from a bufferView of a buffer (a .glb's BIN chunk, a `data:` URI, or a
// .bin file beside the glTF), with the MIME type that says how they are encoded (PNG or JPEG).
// Image files beside the glTF are gltf_textures.h's; decoding is texture/texture_image.h's.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/json_document.h"
#include "texture/material_texture.h"
#include "util/diagnostic.h"

namespace glint {

// The glTF being read: its JSON, the file itself (a .gltf, or a .glb whose JSON chunk `document`
// is) and a .glb's BIN chunk (buffer 0; empty for a .gltf).
struct GltfSource {
    const JsonDocument& document;
    std::string file;
    std::string_view bin;
};

// An image's encoded bytes and their MIME type ("image/png" or "image/jpeg").
struct EmbeddedImage {
    std::vector<uint8_t> bytes;
    std::string mimeType;
};

// The bytes of images[index] when the glTF holds them (nothing when its "uri" names a file).
// Malformed base64, a bufferView or buffer that does not exist or lies outside its buffer, a
// missing or unknown MIME type: a JsonReadError located at the image, naming its index.
std::optional<EmbeddedImage> embeddedGltfImage(const GltfSource& source, size_t index);

// Decodes `image` (images[index] of `file`, which name it in messages and caches).
Result<std::shared_ptr<const TextureImage>> decodeEmbeddedGltfImage(const EmbeddedImage& image, const std::string& file,
                                                                    int index, TextureColorSpace colorSpace);

// The bytes of images[index] inside the .gltf or .glb `file` (a scene file's texture names it so,
// see MaterialTexture::gltfImage), and that image decoded. Errors name the file and the image.
Result<EmbeddedImage> readGltfImage(const std::string& file, int index);
Result<std::shared_ptr<const TextureImage>> loadGltfImage(const std::string& file, int index, TextureColorSpace colorSpace);

// The image a material texture reads: its file, or images[gltfImage] of it when gltfImage ≥ 0.
Result<std::shared_ptr<const TextureImage>> loadMaterialTextureImage(const std::string& file, int gltfImage,
                                                                     TextureColorSpace colorSpace);

}  // namespace glint
