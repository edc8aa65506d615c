// The "textures" object of a material (see texture_json.h).
#include "texture/texture_json.h"

#include "interchange/gltf_images.h"
#include "scene/json_vectors.h"
#include "texture/texture_edit.h"
#include "util/referenced_file_error.h"
#include "util/referenced_path.h"

namespace glint {
namespace {

using nlohmann::json;

constexpr const char* kKinds[] = {"image", "checker", "marble", "wood"};  // order of TextureKind
constexpr const char* kColorSpaces[] = {"srgb", "linear"};
constexpr const char* kFilters[] = {"nearest", "bilinear", "trilinear", "anisotropic"};
constexpr const char* kChannels[] = {"r", "g", "b", "a"};
constexpr const char* kWraps[] = {"repeat", "clamp_to_edge", "mirrored_repeat"};  // order of TextureWrap
// TextureMinFilter after Default, in order.
constexpr const char* kMinFilters[] = {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                                       "nearest_mipmap_linear", "linear_mipmap_linear"};

// One of the two values of a procedural texture: a number (scalars, or grey for colours) or
// [r, g, b] for colours, inside the parameter's valid range.
glm::vec3 readValue(ObjectReader& reader, const char* key, glm::vec3 fallback, const ParamSpec* spec) {
    if (!reader.has(key)) return fallback;
    Bounds bounds = Bounds::between(0.0, 1.0);
    if (spec) {
        bounds = Bounds::between(spec->validMin, spec->validMax == kUnbounded ? std::numeric_limits<double>::max() : spec->validMax);
        bounds.minExclusive = spec->validMinExclusive;
    }
    if (spec && spec->kind == ParamKind::Color && reader.has(key) && reader.take(key).is_array())
        return reader.vec3(key, fallback, bounds);
    return glm::vec3(static_cast<float>(reader.number(key, fallback.x, bounds)));
}

MaterialTexture readTexture(ObjectReader& reader, const std::string& parameter, const ParamSpec* spec) {
    if (!reader.has("type")) reader.failHere("a texture needs the key 'type' (image, checker, marble or wood)");
    const auto kind = static_cast<TextureKind>(reader.choice("type", kKinds, 0));
    if (!spec && kind != TextureKind::Image) reader.fail("type", "the normal map must be an image");
    MaterialTexture texture = defaultTexture(parameter, spec, kind);
    if (kind == TextureKind::Image) {
        const std::string file = reader.requiredString("file");
        texture.file = reader.referencedFile("file").string();
        texture.gltfImage = reader.integer("gltf_image", -1, 0, 1'000'000);
        texture.colorSpace = static_cast<TextureColorSpace>(reader.choice("color_space", kColorSpaces, static_cast<int>(texture.colorSpace)));
        texture.filter = static_cast<TextureFilter>(reader.choice("filter", kFilters, static_cast<int>(texture.filter)));
        if (reader.has("min_filter")) texture.minFilter = static_cast<TextureMinFilter>(reader.choice("min_filter", kMinFilters, 0) + 1);
        texture.wrapU = static_cast<TextureWrap>(reader.choice("wrap_u", kWraps, static_cast<int>(texture.wrapU)));
        texture.wrapV = static_cast<TextureWrap>(reader.choice("wrap_v", kWraps, static_cast<int>(texture.wrapV)));
        texture.tiling = reader.vec2("tiling", texture.tiling);  // negative mirrors (glTF's texture transform allows it)
        texture.offset = reader.vec2("offset", texture.offset);
        texture.rotation = static_cast<float>(reader.number("rotation", texture.rotation));
        if (spec && spec->kind == ParamKind::Color) texture.colorFactor = reader.vec3("factor", texture.colorFactor, Bounds::nonNegative());
        if (!spec) texture.normalScale = static_cast<float>(reader.number("scale", texture.normalScale));
        if (spec && spec->kind == ParamKind::Scalar) {
            // value = mix(min, max, texel)
            texture.channel = static_cast<TextureChannel>(reader.choice("channel", kChannels, 0));
            texture.range.x = readValue(reader, "min", glm::vec3(texture.range.x), spec).x;
            texture.range.y = readValue(reader, "max", glm::vec3(texture.range.y), spec).x;
        }
        auto image = loadMaterialTextureImage(texture.file, texture.gltfImage, texture.colorSpace);
        if (!image) reader.fail("file", "texture '" + file + "' for '" + parameter + "': " + referencedFileProblem(texture.file, image.error(), "image"));
        if (Status inRange = checkTexelRange(**image, texture, spec); !inRange)
            reader.fail("file", "texture '" + file + "' for '" + parameter + "': " + inRange.error().format() +
                                    "; texture values must lie in [0, 1]");
        texture.image = *image;
    } else {
        texture.valueA = readValue(reader, "a", texture.valueA, spec);
        texture.valueB = readValue(reader, "b", texture.valueB, spec);
        if (kind == TextureKind::Checker) {
            texture.tiling = reader.vec2("tiling", texture.tiling, Bounds::positive());
        } else {
            texture.frequency = static_cast<float>(reader.number("frequency", texture.frequency, Bounds::positive()));
            texture.turbulence = static_cast<float>(reader.number("turbulence", texture.turbulence, Bounds::between(0, 1000)));
            texture.octaves = reader.integer("octaves", texture.octaves, 1, 12);
        }
    }
    reader.rejectUnknownKeys();
    return texture;
}

}  // namespace

void readMaterialTextures(ObjectReader& materialReader, AnalyticMaterial& material) {
    if (!materialReader.has("textures")) return;
    const json& node = materialReader.take("textures");
    if (!node.is_object()) materialReader.fail("textures", "must be an object keyed by parameter name");
    ObjectReader textures = materialReader.object("textures");
    material.textures.clear();
    for (const auto& [parameter, value] : node.items()) {
        std::string error;
        const ParamSpec* spec = texturableParam(material.model, parameter, error);
        if (!error.empty()) textures.fail(parameter, error);
        if (!value.is_object()) textures.fail(parameter, "a texture is an object with a 'type'");
        ObjectReader reader = textures.object(parameter);
        putTexture(material, readTexture(reader, parameter, spec));  // table order
    }
    if (material.textures.size() > static_cast<size_t>(kMaxMaterialTextures))
        materialReader.fail("textures", "at most " + std::to_string(kMaxMaterialTextures) + " textures per material");
}

json materialTexturesToJson(const AnalyticMaterial& material, const std::string& targetFile) {
    if (material.textures.empty()) return nullptr;
    const auto table = modelInfo(material.model).params;
    json out = json::object();
    for (const MaterialTexture& texture : material.textures) {
        const int index = findParam(table, texture.parameter);
        const bool color = index >= 0 && table[index].kind == ParamKind::Color;
        const bool scalar = index >= 0 ? table[index].kind == ParamKind::Scalar : texture.parameter == kOcclusionMapKey;
        const auto value = [&](glm::vec3 v) { return color ? json{v.x, v.y, v.z} : json(v.x); };
        json entry = {{"type", kKinds[static_cast<int>(texture.kind)]}};
        switch (texture.kind) {
            case TextureKind::Image: {
                entry["file"] = referencedPathFor(texture.file, targetFile);
                if (texture.gltfImage >= 0) entry["gltf_image"] = texture.gltfImage;
                entry["color_space"] = kColorSpaces[static_cast<int>(texture.colorSpace)];
                entry["filter"] = kFilters[static_cast<int>(texture.filter)];
                if (texture.minFilter != TextureMinFilter::Default) entry["min_filter"] = kMinFilters[static_cast<int>(texture.minFilter) - 1];
                if (texture.wrapU != TextureWrap::Repeat) entry["wrap_u"] = kWraps[static_cast<int>(texture.wrapU)];
                if (texture.wrapV != TextureWrap::Repeat) entry["wrap_v"] = kWraps[static_cast<int>(texture.wrapV)];
                entry["tiling"] = {texture.tiling.x, texture.tiling.y};
                if (texture.offset != glm::vec2(0.0f)) entry["offset"] = {texture.offset.x, texture.offset.y};
                if (texture.rotation != 0.0f) entry["rotation"] = texture.rotation;
                if (color && texture.colorFactor != glm::vec3(1.0f)) entry["factor"] = vec3Json(texture.colorFactor);
                if (isNormalMapKey(texture.parameter) && texture.normalScale != 1.0f) entry["scale"] = texture.normalScale;
                if (scalar) {
                    entry["channel"] = kChannels[static_cast<int>(texture.channel)];
                    entry["min"] = texture.range.x;
                    entry["max"] = texture.range.y;
                }
                break;
            }
            case TextureKind::Checker:
                entry["a"] = value(texture.valueA), entry["b"] = value(texture.valueB);
                entry["tiling"] = {texture.tiling.x, texture.tiling.y};
                break;
            case TextureKind::Marble:
            case TextureKind::Wood:
                entry["a"] = value(texture.valueA), entry["b"] = value(texture.valueB);
                entry["frequency"] = texture.frequency;
                entry["turbulence"] = texture.turbulence;
                entry["octaves"] = texture.octaves;
                break;
        }
        out[texture.parameter] = entry;
    }
    return out;
}

}  // namespace glint
