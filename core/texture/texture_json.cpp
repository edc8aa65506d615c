// The "textures" object of a material (see texture_json.h).
#include "texture/texture_json.h"

#include <filesystem>

#include "texture/texture_image.h"

namespace glint {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr const char* kKinds[] = {"image", "checker", "marble", "wood"};  // order of TextureKind
constexpr const char* kColorSpaces[] = {"srgb", "linear"};
constexpr const char* kFilters[] = {"nearest", "bilinear", "trilinear", "anisotropic"};
constexpr const char* kChannels[] = {"r", "g", "b", "a"};

const char* kindName(ParamKind kind) {
    switch (kind) {
        case ParamKind::Scalar: return "a scalar";
        case ParamKind::Color: return "a colour";
        case ParamKind::PerChannel: return "a per-channel quantity";
        case ParamKind::Bool: return "a yes/no switch";
        case ParamKind::Enum: return "a choice";
    }
    return "";
}

// One of the two values of a procedural texture: a number (scalars, or grey for colours) or
// [r, g, b] for colours, inside the parameter's valid range.
glm::vec3 readValue(ObjectReader& reader, const char* key, glm::vec3 fallback, const ParamSpec* spec) {
    Bounds bounds = Bounds::between(0.0, 1.0);
    if (spec) {
        bounds = Bounds::between(spec->validMin, spec->validMax == kUnbounded ? std::numeric_limits<double>::max() : spec->validMax);
        bounds.minExclusive = spec->validMinExclusive;
    }
    if (spec && spec->kind == ParamKind::Color && reader.has(key) && reader.take(key).is_array())
        return reader.vec3(key, fallback, bounds);
    return glm::vec3(static_cast<float>(reader.number(key, fallback.x, bounds)));
}

std::string resolve(const std::string& file, const std::string& referencingFile) {
    fs::path path(file);
    if (path.is_relative() && !referencingFile.empty()) path = fs::absolute(referencingFile).parent_path() / path;
    return fs::absolute(path).lexically_normal().string();
}

MaterialTexture readTexture(ObjectReader& reader, const std::string& parameter, const ParamSpec* spec,
                            const std::string& referencingFile) {
    MaterialTexture texture;
    texture.parameter = parameter;
    if (!reader.has("type")) reader.failHere("a texture needs the key 'type' (image, checker, marble or wood)");
    texture.kind = static_cast<TextureKind>(reader.choice("type", kKinds, 0));
    if (!spec && texture.kind != TextureKind::Image) reader.fail("type", "the normal map must be an image");
    const bool scalar = spec && spec->kind == ParamKind::Scalar;
    if (texture.kind == TextureKind::Image) {
        const std::string file = reader.requiredString("file");
        texture.file = resolve(file, referencingFile);
        const TextureColorSpace defaultSpace = spec && spec->kind == ParamKind::Color ? TextureColorSpace::Srgb
                                                                                      : TextureColorSpace::Linear;
        texture.colorSpace = static_cast<TextureColorSpace>(reader.choice("color_space", kColorSpaces, static_cast<int>(defaultSpace)));
        texture.filter = static_cast<TextureFilter>(reader.choice("filter", kFilters, static_cast<int>(TextureFilter::Trilinear)));
        texture.tiling = reader.vec2("tiling", texture.tiling, Bounds::positive());
        if (scalar) {
            texture.channel = static_cast<TextureChannel>(reader.choice("channel", kChannels, 0));
            // value = mix(min, max, texel); by default the texel itself where the range allows.
            texture.range.x = readValue(reader, "min", glm::vec3(std::max(spec->validMin, 0.0f)), spec).x;
            texture.range.y = readValue(reader, "max", glm::vec3(std::min(spec->validMax, 1.0f)), spec).x;
        }
        auto image = loadTextureImage(texture.file, texture.colorSpace);
        if (!image) reader.fail("file", "texture '" + file + "' for '" + parameter + "': " + image.error().format());
        texture.image = *image;
        // Texels drive reflectances and blend weights: they must lie in [0, 1].
        const int channels = spec && spec->kind == ParamKind::Scalar ? 1 : 3;
        for (size_t i = 0; i < texture.image->rgba.size(); i += 4)
            for (int c = 0; c < channels; ++c) {
                const float value = texture.image->rgba[i + (channels == 1 ? static_cast<int>(texture.channel) : c)];
                if (value < 0.0f || value > 1.0f)
                    reader.fail("file", "texture '" + file + "' for '" + parameter + "' has the value " + std::to_string(value) +
                                            " at texel " + std::to_string(i / 4) + "; texture values must lie in [0, 1]");
            }
    } else {
        const bool checker = texture.kind == TextureKind::Checker;
        texture.valueA = readValue(reader, "a", glm::vec3(spec->defaultValue[0], spec->defaultValue[1], spec->defaultValue[2]) * 0.2f, spec);
        texture.valueB = readValue(reader, "b", glm::vec3(spec->defaultValue[0], spec->defaultValue[1], spec->defaultValue[2]), spec);
        if (checker) {
            texture.tiling = reader.vec2("tiling", {8.0f, 8.0f}, Bounds::positive());
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

void readMaterialTextures(ObjectReader& materialReader, Material& material, const std::string& referencingFile) {
    if (!materialReader.has("textures")) return;
    const json& node = materialReader.take("textures");
    if (!node.is_object()) materialReader.fail("textures", "must be an object keyed by parameter name");
    ObjectReader textures = materialReader.object("textures");
    const auto table = modelInfo(material.model).params;
    std::vector<MaterialTexture> read;
    for (const auto& [parameter, value] : node.items()) {
        const ParamSpec* spec = nullptr;
        if (parameter != kNormalMapKey) {
            const int index = findParam(table, parameter);
            if (index < 0) {
                std::string list;
                for (const ParamSpec& candidate : table)
                    if (candidate.kind == ParamKind::Scalar || candidate.kind == ParamKind::Color)
                        list += std::string(list.empty() ? "" : ", ") + candidate.name;
                textures.fail(parameter, "'" + parameter + "' is not a parameter of the model '" + modelInfo(material.model).id +
                                             "' (textures can drive: " + list + (list.empty() ? "" : ", ") + "normal)");
            }
            spec = &table[index];
            if (spec->kind != ParamKind::Scalar && spec->kind != ParamKind::Color)
                textures.fail(parameter, "'" + parameter + "' is " + kindName(spec->kind) +
                                             "; only scalar and colour parameters can be textured");
        }
        if (!value.is_object()) textures.fail(parameter, "a texture is an object with a 'type'");
        ObjectReader reader = textures.object(parameter);
        read.push_back(readTexture(reader, parameter, spec, referencingFile));
    }
    if (read.size() > static_cast<size_t>(kMaxMaterialTextures))
        materialReader.fail("textures", "at most " + std::to_string(kMaxMaterialTextures) + " textures per material");
    // Table order (the normal map last), so that equal materials list their textures alike.
    const auto order = [&](const MaterialTexture& texture) {
        const int index = findParam(table, texture.parameter);
        return index < 0 ? static_cast<int>(table.size()) : index;
    };
    std::stable_sort(read.begin(), read.end(), [&](const auto& a, const auto& b) { return order(a) < order(b); });
    material.textures = std::move(read);
}

json materialTexturesToJson(const Material& material, const std::string& targetFile) {
    if (material.textures.empty()) return nullptr;
    const auto table = modelInfo(material.model).params;
    json out = json::object();
    for (const MaterialTexture& texture : material.textures) {
        const int index = findParam(table, texture.parameter);
        const bool color = index >= 0 && table[index].kind == ParamKind::Color;
        const auto value = [&](glm::vec3 v) { return color ? json{v.x, v.y, v.z} : json(v.x); };
        json entry = {{"type", kKinds[static_cast<int>(texture.kind)]}};
        switch (texture.kind) {
            case TextureKind::Image: {
                std::string file = texture.file;
                if (!targetFile.empty()) file = fs::path(file).lexically_relative(fs::absolute(targetFile).parent_path()).generic_string();
                entry["file"] = file;
                entry["color_space"] = kColorSpaces[static_cast<int>(texture.colorSpace)];
                entry["filter"] = kFilters[static_cast<int>(texture.filter)];
                entry["tiling"] = {texture.tiling.x, texture.tiling.y};
                if (index >= 0 && !color) {
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
