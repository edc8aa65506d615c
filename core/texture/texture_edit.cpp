// Edits of a material's textures (see texture_edit.h).
#include "texture/texture_edit.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "texture/texture_image.h"

namespace glint {

namespace {

// The occlusion map's value: 1 (unoccluded) by default, read from a linear channel.
constexpr ParamSpec kOcclusionSpec{.name = kOcclusionMapKey, .label = "Ambient occlusion", .unit = "", .kind = ParamKind::Scalar,
                                   .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {1.0f, 0, 0},
                                   .help = "Scales the ambient and environment light only (glTF's occlusionTexture)"};

}  // namespace

const ParamSpec* texturableParam(BrdfModel model, const std::string& parameter, std::string& error) {
    error.clear();
    if (isNormalMapKey(parameter)) return nullptr;  // the coat's is read by models with a coat only
    if (parameter == kOcclusionMapKey) return &kOcclusionSpec;
    const auto table = modelInfo(model).params;
    const int index = findParam(table, parameter);
    if (index < 0) {
        std::string list;
        for (const ParamSpec& candidate : table)
            if (candidate.kind == ParamKind::Scalar || candidate.kind == ParamKind::Color)
                list += std::string(list.empty() ? "" : ", ") + candidate.name;
        error = "'" + parameter + "' is not a parameter of the model '" + modelInfo(model).id +
                "' (textures can drive: " + list + (list.empty() ? "" : ", ") + kOcclusionMapKey + ", " + kNormalMapKey + ", " + kCoatNormalMapKey + ")";
        return nullptr;
    }
    const ParamSpec& spec = table[index];
    if (spec.kind != ParamKind::Scalar && spec.kind != ParamKind::Color) {
        const char* kind = spec.kind == ParamKind::Enum ? "a choice" : spec.kind == ParamKind::Bool ? "a yes/no switch"
                                                                                                  : "a per-channel quantity";
        error = "'" + parameter + "' is " + kind + "; only scalar and colour parameters can be textured";
        return nullptr;
    }
    return &spec;
}

MaterialTexture defaultTexture(const std::string& parameter, const ParamSpec* spec, TextureKind kind) {
    MaterialTexture texture;
    texture.parameter = parameter;
    texture.kind = kind;
    const bool color = spec && spec->kind == ParamKind::Color;
    texture.colorSpace = color ? TextureColorSpace::Srgb : TextureColorSpace::Linear;
    if (spec) {
        const glm::vec3 fallback{spec->defaultValue[0], spec->defaultValue[1], spec->defaultValue[2]};
        texture.valueB = fallback;
        texture.valueA = 0.2f * fallback;
        if (spec->validMinExclusive || spec->validMin > 0.0f) texture.valueA = glm::max(texture.valueA, glm::vec3(spec->validMin));
        if (spec->validMinExclusive && texture.valueA.x <= spec->validMin) texture.valueA = fallback;
        texture.range = {std::max(spec->validMin, 0.0f), std::min(spec->validMax, 1.0f)};
    }
    if (kind == TextureKind::Checker) texture.tiling = {8.0f, 8.0f};
    return texture;
}

const MaterialTexture* findTexture(const AnalyticMaterial& material, const std::string& parameter) {
    for (const MaterialTexture& texture : material.textures)
        if (texture.parameter == parameter) return &texture;
    return nullptr;
}

MaterialTexture* findTexture(AnalyticMaterial& material, const std::string& parameter) {
    return const_cast<MaterialTexture*>(findTexture(std::as_const(material), parameter));
}

void putTexture(AnalyticMaterial& material, MaterialTexture texture) {
    removeTexture(material, texture.parameter);
    const auto table = modelInfo(material.model).params;
    const auto order = [&](const MaterialTexture& t) {
        const int index = findParam(table, t.parameter);
        if (index >= 0) return index;
        // After the table: the coat normal map, the occlusion map, the normal map (material_glsl.h's bits).
        return static_cast<int>(table.size()) + (t.parameter == kCoatNormalMapKey ? 0 : t.parameter == kOcclusionMapKey ? 1 : 2);
    };
    const auto at = std::upper_bound(material.textures.begin(), material.textures.end(), texture,
                                     [&](const auto& a, const auto& b) { return order(a) < order(b); });
    material.textures.insert(at, std::move(texture));
}

void removeTexture(AnalyticMaterial& material, const std::string& parameter) {
    std::erase_if(material.textures, [&](const MaterialTexture& t) { return t.parameter == parameter; });
}

Status checkTexelRange(const TextureImage& image, const MaterialTexture& texture, const ParamSpec* spec) {
    const bool scalar = spec && spec->kind == ParamKind::Scalar;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
        for (int c = 0; c < (scalar ? 1 : 3); ++c) {
            const float value = image.rgba[i + (scalar ? static_cast<int>(texture.channel) : c)];
            if (value < 0.0f || value > 1.0f)
                return makeError("texture value " + std::to_string(value) + " at texel (" + std::to_string(i / 4 % image.width) +
                                     ", " + std::to_string(i / 4 / image.width) + ") is outside [0, 1]", {image.path});
        }
    return success();
}

Status setTextureImage(AnalyticMaterial& material, const std::string& parameter, const std::string& path) {
    std::string error;
    const ParamSpec* spec = texturableParam(material.model, parameter, error);
    if (!error.empty()) return makeError(error);
    const MaterialTexture* existing = findTexture(material, parameter);
    MaterialTexture texture = existing && existing->kind == TextureKind::Image
                                  ? *existing
                                  : defaultTexture(parameter, spec, TextureKind::Image);
    texture.file = std::filesystem::absolute(path).lexically_normal().string();
    texture.gltfImage = -1;
    auto image = loadTextureImage(texture.file, texture.colorSpace);
    if (!image) return image.error();
    if (Status inRange = checkTexelRange(**image, texture, spec); !inRange) return inRange.error();
    texture.image = *image;
    putTexture(material, std::move(texture));
    return success();
}

}  // namespace glint
