// The preset library in the material column: the presets of core/brdf/presets.h grouped by
// category, each a swatch on the preview stage (editor/preset_swatches.h) beside its name as
// words; hovering one shows its model and source, clicking it puts it on the selected object's
// material as one undoable edit.
#include <imgui.h>

#include <cstdint>
#include <string>

#include "brdf/presets.h"
#include "editor/panels/panels.h"
#include "util/text.h"

namespace glint {

void drawPresetBrowser(EditorState& state, int materialIndex) {
    if (!ImGui::TreeNodeEx("Preset library", ImGuiTreeNodeFlags_None)) return;
    ImGui::PushStyleVar(ImGuiStyleVar_SelectableTextAlign, ImVec2(0.0f, 0.5f));  // names beside their swatch's middle
    const char* category = "";
    for (const Preset& preset : allPresets()) {
        if (std::string(preset.category) != category) {
            category = preset.category;
            ImGui::TextDisabled("%s", category);
        }
        ImGui::PushID(preset.name);
        // The swatch, two text lines tall, or the room for it while it is being rendered.
        const float side = 2.0f * ImGui::GetTextLineHeightWithSpacing();
        const auto swatch = state.presetSwatches.textures.find(preset.name);
        if (swatch == state.presetSwatches.textures.end()) state.presetSwatches.wanted = true;
        if (swatch != state.presetSwatches.textures.end() && swatch->second != 0)
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(swatch->second)), ImVec2(side, side));
        else
            ImGui::Dummy(ImVec2(side, side));
        ImGui::SameLine();
        const std::string label = readableName(preset.name);
        if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_None, ImVec2(0.0f, side))) {
            state.session.change(std::string("Apply preset ") + preset.name).materials[materialIndex] = preset.material();
            state.session.settle(false);
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n%s", modelInfo(preset.model).label, preset.source);
        ImGui::PopID();
    }
    ImGui::PopStyleVar();
    ImGui::TreePop();
}

}  // namespace glint
