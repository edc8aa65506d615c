// glTF 2.0 textures ↔ Glint's material textures (texture/material_texture.h): reading a
// textureInfo ({"index", "texCoord", "scale"/"strength", KHR_texture_transform}) through
// textures → images/samplers to an image file or an image inside the glTF (gltf_images.h), and
// writing images, textures and samplers back.
// glTF's UV has v down (the image's top row at v = 0), Glint's v up: KHR_texture_transform's
// uv' = T·R·S·uv is converted to MaterialTexture's tiling, rotation and offset exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "interchange/gltf_images.h"
#include "scene/json_object_reader.h"
#include "texture/material_texture.h"
#include "util/diagnostic.h"

namespace glint {

// Refuses the keys of a glTF object nobody read, "extras" (free for any application) aside.
inline void rejectUnknownGltfKeys(ObjectReader& reader) {
    reader.expect({"extras"});
    reader.rejectUnknownKeys();
}

// KHR_texture_transform's values (glTF UV, v down; rotation in radians).
struct GltfUvTransform {
    glm::vec2 offset{0.0f}, scale{1.0f};
    float rotation = 0.0f;
};
// Sets `texture`'s tiling, rotation and offset to the same mapping in Glint's UV (v up).
void applyGltfUvTransform(MaterialTexture& texture, const GltfUvTransform& transform);
GltfUvTransform gltfUvTransformOf(const MaterialTexture& texture);

// A textureInfo read from a material: where its image is and how it is sampled.
struct GltfTextureInfo {
    std::string pointer;    // JSON pointer of the textureInfo, for messages
    std::string uri;        // the image's URI as written (percent-decoded); empty for a bufferView image
    std::string file;       // absolute path of a file URI; empty for data URIs and bufferViews
    int image = 0;          // the index of the image in "images"
    std::optional<EmbeddedImage> embedded;  // the image's bytes when the glTF holds them (data URI, bufferView)
    std::string container;  // the .gltf or .glb, which holds an embedded image
    TextureFilter filter = TextureFilter::Trilinear;
    TextureMinFilter minFilter = TextureMinFilter::Default;
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;  // wrapS, wrapT
    int texCoord = 0;
    GltfUvTransform transform;
    float scale = 1.0f;     // normalTexture.scale / occlusionTexture.strength
    std::string refusal;    // why the image file outside the glTF's folder is not read; empty when it is not refused
};

// Reads the textureInfo at `key` of `parent` (nothing when absent) in `source`, whose folder
// confines its image files (util/reference_confinement.h). Malformed indices and values, and an
// image inside the glTF that cannot be read out of it (gltf_images.h), throw a located JsonReadError.
std::optional<GltfTextureInfo> readGltfTextureInfo(ObjectReader& parent, const std::string& key, const GltfSource& source);

// A MaterialTexture on `parameter` from the texture's image (decoded; an error names the file or
// the image inside the glTF, and the textureInfo), with its sampler state and UV transform.
Result<MaterialTexture> gltfImageTexture(const GltfTextureInfo& info, const std::string& parameter, TextureColorSpace colorSpace);

// Collects a written glTF's images, samplers and textures (one each per distinct image and
// sampler state) and writes textureInfo objects that use them.
class GltfTextureWriter {
public:
    // `targetFile`: where the .gltf goes; image URIs are written relative to its folder.
    explicit GltfTextureWriter(std::string targetFile) : targetFile_(std::move(targetFile)) {}
    // A textureInfo for a Glint image texture: {"index"} plus KHR_texture_transform when it is not
    // the identity (and `extensionsUsed` then names it). An image inside a glTF is written as a
    // data URI of its bytes; an error says why they cannot be read again.
    Result<nlohmann::json> textureInfo(const MaterialTexture& texture, std::vector<std::string>& extensionsUsed);
    // A textureInfo for an image URI or absolute file kept from an import, with its other members.
    nlohmann::json keptTextureInfo(const std::string& fileOrUri, nlohmann::json members);
    // Puts "images", "samplers" and "textures" into `gltf` when any were used.
    void writeInto(nlohmann::json& gltf) const;

private:
    int textureIndex(const std::string& uri, const MaterialTexture& sampling);
    std::string targetFile_;
    nlohmann::json images_ = nlohmann::json::array(), samplers_ = nlohmann::json::array(), textures_ = nlohmann::json::array();
};

}  // namespace glint
