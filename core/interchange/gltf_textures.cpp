// glTF textures ↔ material textures (see gltf_textures.h).
#include "interchange/gltf_textures.h"

#include <cmath>
#include <filesystem>

#include "interchange/base64.h"
#include "texture/texture_image.h"
#include "util/reference_confinement.h"
#include "util/referenced_file_error.h"
#include "util/referenced_path.h"

namespace glint {
namespace {

using nlohmann::json;

// OpenGL enums as glTF samplers write them (glTF 2.0 §5.26).
constexpr int kNearest = 9728, kLinear = 9729, kLinearMipmapLinear = 9987;
// minFilter values in the order of TextureMinFilter after Default.
constexpr int kMinFilters[] = {kNearest, kLinear, 9984, 9985, 9986, kLinearMipmapLinear};
// wrapS/wrapT values in the order of TextureWrap: REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT.
constexpr int kWraps[] = {10497, 33071, 33648};

// RFC 3986 percent-encoding of a relative URI path, and its decoding.
std::string percentEncoded(const std::string& path) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : path) {
        if (std::isalnum(c) || std::string_view("-._~/").find(static_cast<char>(c)) != std::string_view::npos) out += static_cast<char>(c);
        else out += {'%', hex[c >> 4], hex[c & 15]};
    }
    return out;
}

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// The minification filter Glint's `filter` implies (texture_cache.cpp binds the same).
int impliedMinFilter(TextureFilter filter) {
    return filter == TextureFilter::Nearest ? kNearest : filter == TextureFilter::Bilinear ? kLinear : kLinearMipmapLinear;
}

int minFilterOf(const MaterialTexture& texture) {
    return texture.minFilter == TextureMinFilter::Default ? impliedMinFilter(texture.filter)
                                                          : kMinFilters[static_cast<int>(texture.minFilter) - 1];
}

// The index of `value` in `allowed`, or a located error naming the sampler's member.
template <size_t N>
int indexOf(const ObjectReader& reader, const json& sampler, size_t samplerIndex, const char* member, const int (&allowed)[N],
            int fallback) {
    if (!sampler.contains(member)) return fallback;
    for (size_t i = 0; i < N; ++i)
        if (sampler[member].is_number_integer() && sampler[member].get<int>() == allowed[i]) return static_cast<int>(i);
    reader.fail("index", "samplers[" + std::to_string(samplerIndex) + "]." + member + " " + sampler[member].dump() +
                             " is not a value glTF 2.0 allows (§5.26)");
}

// glTF's magFilter and minFilter as Glint's filter (nearest when magnifying by NEAREST, else
// bilinear without mipmaps, trilinear with) and the exact minFilter where it is another one.
void readSampler(const ObjectReader& reader, const json& sampler, size_t samplerIndex, GltfTextureInfo& info) {
    static constexpr int kMagFilters[] = {kNearest, kLinear};
    const bool nearest = indexOf(reader, sampler, samplerIndex, "magFilter", kMagFilters, 1) == 0;
    const int minIndex = indexOf(reader, sampler, samplerIndex, "minFilter", kMinFilters, -1);
    const int minification = minIndex < 0 ? kLinearMipmapLinear : kMinFilters[minIndex];
    info.filter = nearest ? TextureFilter::Nearest
                  : minification == kNearest || minification == kLinear ? TextureFilter::Bilinear
                                                                         : TextureFilter::Trilinear;
    if (minIndex >= 0 && minification != impliedMinFilter(info.filter)) info.minFilter = static_cast<TextureMinFilter>(minIndex + 1);
    info.wrapU = static_cast<TextureWrap>(indexOf(reader, sampler, samplerIndex, "wrapS", kWraps, 0));
    info.wrapV = static_cast<TextureWrap>(indexOf(reader, sampler, samplerIndex, "wrapT", kWraps, 0));
}

// The entry `index` of the root array `name`, or a located error at `reader`'s `key`.
const json& entryOf(const ObjectReader& reader, const std::string& key, const json& root, const char* name, size_t index) {
    if (!root.contains(name) || !root[name].is_array() || index >= root[name].size() || !root[name][index].is_object())
        reader.fail(key, std::string(name) + "[" + std::to_string(index) + "] does not exist");
    return root[name][index];
}

}  // namespace

// glTF: uv'_g = T(b)·R(θ)·S(s)·uv_g with R(θ) = [[c, s], [−s, c]] (the KHR_texture_transform
// matrix), uv_g = F(uv) with F(u, v) = (u, 1 − v). Glint: uv' = F(uv'_g) = D·R(θ)·D·S·uv + D·(R·S·e + b) + e
// with D = diag(1, −1), e = (0, 1); D·R(θ)·D is the counter-clockwise rotation by θ.
void applyGltfUvTransform(MaterialTexture& texture, const GltfUvTransform& transform) {
    const float c = std::cos(transform.rotation), s = std::sin(transform.rotation);
    texture.tiling = transform.scale;
    texture.rotation = transform.rotation;
    texture.offset = {transform.offset.x + s * transform.scale.y, 1.0f - transform.offset.y - c * transform.scale.y};
}

GltfUvTransform gltfUvTransformOf(const MaterialTexture& texture) {
    const float c = std::cos(texture.rotation), s = std::sin(texture.rotation);
    GltfUvTransform transform;
    transform.scale = texture.tiling;
    transform.rotation = texture.rotation;
    transform.offset = {texture.offset.x - s * texture.tiling.y, 1.0f - texture.offset.y - c * texture.tiling.y};
    return transform;
}

std::optional<GltfTextureInfo> readGltfTextureInfo(ObjectReader& parent, const std::string& key, const GltfSource& source) {
    if (!parent.has(key)) return std::nullopt;
    const json& root = source.document.root();
    ObjectReader reader = parent.object(key);
    GltfTextureInfo info;
    info.pointer = reader.pointer();
    if (!reader.has("index")) reader.failHere("a texture needs an \"index\"");
    const int index = reader.integer("index", 0, 0, 1'000'000);
    const json& texture = entryOf(reader, "index", root, "textures", static_cast<size_t>(index));
    if (!texture.contains("source") || !texture["source"].is_number_unsigned())
        reader.fail("index", "texture " + std::to_string(index) + " has no image (\"source\")");
    info.image = static_cast<int>(texture["source"].get<size_t>());
    const json& image = entryOf(reader, "index", root, "images", static_cast<size_t>(info.image));
    info.container = source.file;
    info.embedded = embeddedGltfImage(source, static_cast<size_t>(info.image));
    if (!info.embedded && image.contains("uri")) {
        info.uri = percentDecoded(image["uri"].get<std::string>());
        auto confined = confinedReference(info.uri, {source.file});
        if (confined) info.file = confined->string();
        else info.refusal = confined.error().message;
    }
    if (texture.contains("sampler")) {
        if (!texture["sampler"].is_number_unsigned()) reader.fail("index", "texture " + std::to_string(index) + ": \"sampler\" is not an index");
        const size_t samplerIndex = texture["sampler"].get<size_t>();
        readSampler(reader, entryOf(reader, "index", root, "samplers", samplerIndex), samplerIndex, info);
    }
    info.texCoord = reader.integer("texCoord", 0, 0, 1'000'000);
    if (reader.has("scale")) info.scale = static_cast<float>(reader.number("scale", 1.0));
    if (reader.has("strength")) info.scale = static_cast<float>(reader.number("strength", 1.0, Bounds::between(0, 1)));
    if (reader.has("extensions")) {
        ObjectReader extensions = reader.object("extensions");
        if (extensions.has("KHR_texture_transform")) {
            ObjectReader transform = extensions.object("KHR_texture_transform");
            info.transform.offset = transform.vec2("offset", info.transform.offset);
            info.transform.scale = transform.vec2("scale", info.transform.scale);
            info.transform.rotation = static_cast<float>(transform.number("rotation", 0.0));
            info.texCoord = transform.integer("texCoord", info.texCoord, 0, 1'000'000);
            rejectUnknownGltfKeys(transform);
        }
        rejectUnknownGltfKeys(extensions);
    }
    rejectUnknownGltfKeys(reader);
    return info;
}

Result<MaterialTexture> gltfImageTexture(const GltfTextureInfo& info, const std::string& parameter, TextureColorSpace colorSpace) {
    if (!info.refusal.empty()) return makeError(info.pointer + ": " + info.refusal);
    MaterialTexture texture;
    texture.parameter = parameter;
    texture.kind = TextureKind::Image;
    texture.file = info.embedded ? std::filesystem::absolute(info.container).lexically_normal().string() : info.file;
    texture.gltfImage = info.embedded ? info.image : -1;
    texture.colorSpace = colorSpace;
    texture.filter = info.filter;
    texture.minFilter = info.minFilter;
    texture.wrapU = info.wrapU;
    texture.wrapV = info.wrapV;
    applyGltfUvTransform(texture, info.transform);
    auto image = info.embedded ? decodeEmbeddedGltfImage(*info.embedded, info.container, info.image, colorSpace)
                               : loadTextureImage(texture.file, colorSpace);
    if (!image)
        return makeError(info.pointer + ": " + (info.embedded ? image.error().message : referencedFileProblem(texture.file, image.error(), "image")));
    texture.image = *image;
    return texture;
}

int GltfTextureWriter::textureIndex(const std::string& uri, const MaterialTexture& sampling) {
    int image = -1;
    for (size_t i = 0; i < images_.size(); ++i)
        if (images_[i]["uri"] == uri) image = static_cast<int>(i);
    if (image < 0) {
        images_.push_back({{"uri", uri}});
        image = static_cast<int>(images_.size()) - 1;
    }
    json sampler = {{"magFilter", sampling.filter == TextureFilter::Nearest ? kNearest : kLinear}, {"minFilter", minFilterOf(sampling)}};
    if (sampling.wrapU != TextureWrap::Repeat) sampler["wrapS"] = kWraps[static_cast<int>(sampling.wrapU)];
    if (sampling.wrapV != TextureWrap::Repeat) sampler["wrapT"] = kWraps[static_cast<int>(sampling.wrapV)];
    int samplerIndex = -1;
    for (size_t i = 0; i < samplers_.size(); ++i)
        if (samplers_[i] == sampler) samplerIndex = static_cast<int>(i);
    if (samplerIndex < 0) {
        samplers_.push_back(sampler);
        samplerIndex = static_cast<int>(samplers_.size()) - 1;
    }
    const json entry = {{"source", image}, {"sampler", samplerIndex}};
    for (size_t i = 0; i < textures_.size(); ++i)
        if (textures_[i] == entry) return static_cast<int>(i);
    textures_.push_back(entry);
    return static_cast<int>(textures_.size()) - 1;
}

Result<json> GltfTextureWriter::textureInfo(const MaterialTexture& texture, std::vector<std::string>& extensionsUsed) {
    std::string uri = percentEncoded(referencedPathFor(texture.file, targetFile_));
    if (texture.gltfImage >= 0) {
        auto embedded = readGltfImage(texture.file, texture.gltfImage);
        if (!embedded) return embedded.error();
        uri = "data:" + embedded->mimeType + ";base64," + encodeBase64(embedded->bytes);
    }
    json info = {{"index", textureIndex(uri, texture)}};
    if (texture.tiling != glm::vec2(1.0f) || texture.rotation != 0.0f || texture.offset != glm::vec2(0.0f)) {
        const GltfUvTransform transform = gltfUvTransformOf(texture);
        json values = json::object();
        if (transform.offset != glm::vec2(0.0f)) values["offset"] = {transform.offset.x, transform.offset.y};
        if (transform.rotation != 0.0f) values["rotation"] = transform.rotation;
        if (transform.scale != glm::vec2(1.0f)) values["scale"] = {transform.scale.x, transform.scale.y};
        info["extensions"] = {{"KHR_texture_transform", values}};
        extensionsUsed.push_back("KHR_texture_transform");
    }
    return info;
}

json GltfTextureWriter::keptTextureInfo(const std::string& fileOrUri, json members) {
    const std::string uri = fileOrUri.rfind("data:", 0) == 0 ? fileOrUri : percentEncoded(referencedPathFor(fileOrUri, targetFile_));
    members["index"] = textureIndex(uri, MaterialTexture{});
    return members;
}

void GltfTextureWriter::writeInto(json& gltf) const {
    if (textures_.empty()) return;
    gltf["images"] = images_;
    gltf["samplers"] = samplers_;
    gltf["textures"] = textures_;
}

}  // namespace glint
