// The preset library in the material column: the presets of core/brdf/presets.h grouped by
// category; hovering one shows its model and source, clicking it puts it on the selected
// object's material as one undoable edit.
#include <imgui.h>

#include <string>

#include "brdf/presets.h"
#include "editor/panels/panels.h"

namespace glint {

void drawPresetBrowser(EditorState& state, int materialIndex) {
    if (!ImGui::TreeNodeEx("Preset library", ImGuiTreeNodeFlags_None)) return;
    const char* category = "";
    for (const Preset& preset : allPresets()) {
        if (std::string(preset.category) != category) {
            category = preset.category;
            ImGui::TextDisabled("%s", category);
        }
        ImGui::PushID(preset.name);
        if (ImGui::Selectable(preset.name)) {
            state.session.change(std::string("Apply preset ") + preset.name).materials[materialIndex] = preset.material();
            state.session.settle(false);
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n%s", modelInfo(preset.model).label, preset.source);
        ImGui::PopID();
    }
    ImGui::TreePop();
}

}  // namespace glint
