// IOR preset menu (see ior_presets.h). The numbers come from the preset table in
// core/brdf/presets.h (with its sources); this file picks n and κ out of it, and a metal's
// tooltip shows them with the F0 they give and their source.
#include "editor/ior_presets.h"

#include <imgui.h>

#include <cstdio>
#include <string_view>

#include "brdf/fresnel.h"
#include "brdf/presets.h"
#include "interchange/material_values.h"

namespace glint {
namespace {

constexpr const char* kDielectrics[] = {"glass", "water", "ice", "diamond"};
constexpr const char* kMetals[] = {"gold", "silver", "copper", "aluminium", "iron", "chromium"};

// The preset's value for `param`, or nullptr when it sets none.
const glm::vec3* presetValue(const Preset& preset, const char* param) {
    for (const PresetSetting& setting : preset.settings) {
        if (!setting.param) break;
        if (std::string_view(setting.param) == param) return &setting.value;
    }
    return nullptr;
}

}  // namespace

bool applyIorPreset(Material& material, const char* presetName) {
    const Preset* preset = findPreset(presetName);
    if (!preset) return false;
    const auto table = paramTable(material);
    const int iorIndex = findParam(table, "ior");
    const int extinctionIndex = findParam(table, "extinction");
    const glm::vec3* ior = presetValue(*preset, "ior");
    const glm::vec3* extinction = presetValue(*preset, "extinction");
    if (iorIndex < 0 || !ior) return false;
    const bool isMetal = extinction && (extinction->x > 0.0f || extinction->y > 0.0f || extinction->z > 0.0f);
    if (isMetal && extinctionIndex < 0) return false;  // κ cannot be represented
    setParam(material, "ior", *ior);
    if (extinctionIndex >= 0) setParam(material, "extinction", extinction ? *extinction : glm::vec3(0.0f));
    return true;
}

bool drawIorPresetMenu(Material& material) {
    const auto table = paramTable(material);
    const bool hasExtinction = findParam(table, "extinction") >= 0;
    bool applied = false;
    ImGui::SameLine();
    if (ImGui::SmallButton("Presets")) ImGui::OpenPopup("IOR presets");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(hasExtinction ? "Set n (and κ) from a measured material" : "Set n from a measured material");
    if (ImGui::BeginPopup("IOR presets")) {
        ImGui::TextDisabled("Dielectrics (κ = 0)");
        for (const char* name : kDielectrics) {
            const Preset* preset = findPreset(name);
            char label[64];
            std::snprintf(label, sizeof label, "%s  n = %.4g", name, presetValue(*preset, "ior")->x);
            if (ImGui::Selectable(label)) applied |= applyIorPreset(material, name);
        }
        if (hasExtinction) {
            ImGui::Separator();
            ImGui::TextDisabled("Metals (n, κ per channel)");
            for (const char* name : kMetals) {
                if (ImGui::Selectable(name)) applied |= applyIorPreset(material, name);
                if (ImGui::IsItemHovered()) {
                    const Preset* preset = findPreset(name);
                    const glm::vec3 n = *presetValue(*preset, "ior"), k = *presetValue(*preset, "extinction");
                    const glm::vec3 f0 = fresnelF0(n, k);
                    ImGui::BeginTooltip();
                    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
                    ImGui::Text("n = (%.3f, %.3f, %.3f)\nκ = (%.3f, %.3f, %.3f)\nF0 = (%.3f, %.3f, %.3f)", n.x, n.y, n.z, k.x,
                                k.y, k.z, f0.x, f0.y, f0.z);
                    ImGui::TextUnformatted(preset->source);
                    ImGui::PopTextWrapPos();
                    ImGui::EndTooltip();
                }
            }
        }
        ImGui::EndPopup();
    }
    return applied;
}

}  // namespace glint
