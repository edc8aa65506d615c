// The material panel's texture controls (see texture_panel.h).
#include "editor/texture_panel.h"

#include <imgui.h>

#include <cmath>
#include <filesystem>

#include "editor/color_space.h"
#include "editor/panels/typed_numbers.h"
#include "interchange/gltf_images.h"
#include "texture/texture_edit.h"

namespace glint {
namespace {

constexpr const char* kKindLabels[] = {"Image", "Checker", "Marble", "Wood"};  // order of TextureKind
constexpr const char* kFilterLabels[] = {"Nearest", "Bilinear", "Trilinear (mipmaps)", "Anisotropic"};
constexpr const char* kWrapLabels[] = {"Repeat", "Clamp to edge", "Mirrored repeat"};  // order of TextureWrap
constexpr const char* kChannelLabels[] = {"R", "G", "B", "A"};
constexpr const char* kSpaceLabels[] = {"sRGB", "Linear"};

template <class Enum, size_t N>
bool combo(const char* label, Enum& value, const char* const (&labels)[N]) {
    int selected = static_cast<int>(value);
    if (!ImGui::Combo(label, &selected, labels, static_cast<int>(N))) return false;
    value = static_cast<Enum>(selected);
    return true;
}

// One of the two values of a procedural texture: an sRGB picker for colours, a slider for scalars.
bool drawValue(const char* label, glm::vec3& value, const ParamSpec& spec, std::string& refusal) {
    if (spec.kind == ParamKind::Color) {
        float encoded[3] = {encodeSrgb(value.r), encodeSrgb(value.g), encodeSrgb(value.b)};
        if (!editNumbers(label, encoded, 3, [&](float* typed) { return ImGui::ColorEdit3(label, typed, ImGuiColorEditFlags_Float); }))
            return false;
        value = {decodeSrgb(encoded[0]), decodeSrgb(encoded[1]), decodeSrgb(encoded[2])};
        return true;
    }
    float edited = value.x;
    const ImGuiSliderFlags flags = spec.scale == ParamScale::Log ? ImGuiSliderFlags_Logarithmic : 0;
    if (!editNumbers(label, &edited, 1, [&](float* typed) { return ImGui::SliderFloat(label, typed, spec.sliderMin, spec.sliderMax, "%.4g", flags); }))
        return false;
    if (!spec.accepts(edited)) {
        refusal = std::string(spec.label) + " texture: " + std::to_string(edited) + " is outside the valid range";
        return false;
    }
    value = glm::vec3(edited);
    return true;
}

bool drawPositive(const char* label, glm::vec2& value, std::string& refusal) {
    glm::vec2 edited = value;
    if (!editNumbers(label, &edited.x, 2, [&](float* typed) { return ImGui::DragFloat2(label, typed, 0.05f, 0.0f, 0.0f, "%.3g"); }))
        return false;
    if (!(edited.x > 0.0f && edited.y > 0.0f)) {
        refusal = std::string(label) + " must be greater than 0";
        return false;
    }
    value = edited;
    return true;
}

bool drawImageSettings(MaterialTexture& texture, const ParamSpec* spec, std::string& refusal) {
    bool changed = false;
    ImGui::TextDisabled("%s", std::filesystem::path(texture.file).filename().string().c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%d×%d)", texture.file.c_str(), texture.image->width, texture.image->height);
    TextureColorSpace space = texture.colorSpace;
    if (combo("Encoding", space, kSpaceLabels)) {
        // Decoded again with the other curve; a file that no longer loads keeps the old decoding.
        auto image = loadMaterialTextureImage(texture.file, texture.gltfImage, space);
        if (image) texture.colorSpace = space, texture.image = *image, changed = true;
        else refusal = image.error().format();
    }
    changed |= combo("Filter", texture.filter, kFilterLabels);
    changed |= combo("Wrap u", texture.wrapU, kWrapLabels);
    changed |= combo("Wrap v", texture.wrapV, kWrapLabels);
    changed |= drawPositive("Tiling", texture.tiling, refusal);
    if (spec && spec->kind == ParamKind::Scalar) {
        changed |= combo("Channel", texture.channel, kChannelLabels);
        glm::vec3 low(texture.range.x), high(texture.range.y);
        if (drawValue("Value at 0", low, *spec, refusal)) texture.range.x = low.x, changed = true;
        if (drawValue("Value at 1", high, *spec, refusal)) texture.range.y = high.x, changed = true;
    }
    return changed;
}

bool drawProceduralSettings(MaterialTexture& texture, const ParamSpec& spec, std::string& refusal) {
    bool changed = drawValue("A", texture.valueA, spec, refusal);
    changed |= drawValue("B", texture.valueB, spec, refusal);
    if (texture.kind == TextureKind::Checker) return changed | drawPositive("Squares (u, v)", texture.tiling, refusal);
    float frequency = texture.frequency;
    if (editNumbers("Frequency 1/m", &frequency, 1, [&](float* typed) { return ImGui::DragFloat("Frequency 1/m", typed, 0.02f, 0.0f, 0.0f, "%.3g"); })) {
        if (frequency > 0.0f) texture.frequency = frequency, changed = true;
        else refusal = "Frequency must be greater than 0";
    }
    changed |= editNumbers("Turbulence", &texture.turbulence, 1, [](float* typed) { return ImGui::SliderFloat("Turbulence", typed, 0.0f, 20.0f, "%.3g"); });
    changed |= ImGui::SliderInt("Octaves", &texture.octaves, 1, 12);
    return changed;
}

}  // namespace

const char* textureButtonLabel(const AnalyticMaterial& material, const std::string& parameter) {
    const MaterialTexture* texture = findTexture(material, parameter);
    return texture ? kKindLabels[static_cast<int>(texture->kind)] : "Tex";
}

bool drawTextureControls(AnalyticMaterial& material, const std::string& parameter, const ParamSpec* spec,
                         std::string& fileRequest, std::string& refusal) {
    bool changed = false;
    ImGui::PushID(("texture " + parameter).c_str());
    const MaterialTexture* current = findTexture(material, parameter);
    const bool textured = current != nullptr;
    const TextureKind currentKind = textured ? current->kind : TextureKind::Image;
    if (ImGui::SmallButton(textureButtonLabel(material, parameter))) ImGui::OpenPopup("texture menu");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drive %s by a texture", parameter.c_str());
    if (ImGui::BeginPopup("texture menu")) {
        if (ImGui::Selectable("None", !textured) && textured) removeTexture(material, parameter), changed = true;
        if (ImGui::Selectable("Image file…")) fileRequest = parameter;
        for (TextureKind kind : {TextureKind::Checker, TextureKind::Marble, TextureKind::Wood}) {
            if (!spec) break;  // the normal map is an image only
            if (ImGui::Selectable(kKindLabels[static_cast<int>(kind)], textured && currentKind == kind)) {
                putTexture(material, defaultTexture(parameter, spec, kind));
                changed = true;
            }
        }
        ImGui::EndPopup();
    }
    if (MaterialTexture* texture = findTexture(material, parameter)) {
        ImGui::Indent();
        if (texture->kind == TextureKind::Image) changed |= drawImageSettings(*texture, spec, refusal);
        else changed |= drawProceduralSettings(*texture, *spec, refusal);
        ImGui::Unindent();
    }
    ImGui::PopID();
    return changed;
}

void openTextureFile(EditorState& state, const std::string& path) {
    const Scene& scene = state.session.scene();
    if (state.textureMaterialIndex < 0 || state.textureMaterialIndex >= static_cast<int>(scene.materials.size())) return;
    Material edited = scene.materials[state.textureMaterialIndex];
    if (!edited.analytic()) return;  // no longer a built-in model's material: nothing takes the texture
    if (Status loaded = setTextureImage(*edited.analytic(), state.textureParameter, path); !loaded) {
        state.errorMessage = "Could not use the texture; the material is unchanged.\n\n" + loaded.error().format();
        return;
    }
    state.session.change("Texture " + state.textureParameter).materials[state.textureMaterialIndex] = std::move(edited);
    state.session.settle(false);
    state.statusMessage = "Texture " + path;
}

}  // namespace glint
