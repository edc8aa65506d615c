// The object and material section: pick the object, see its material, edit it through the
// table-driven material widgets (editor/material_panel.h) on a copy that is written back
// through the edit API, so a slider drag is one undo step.
#include <imgui.h>

#include "editor/material_panel.h"
#include "editor/panels/panels.h"

namespace glint {

void drawObjectSection(EditorState& state) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) {
        ImGui::TextWrapped("The scene has no objects.");
        return;
    }
    state.selectedObject = std::clamp(state.selectedObject, 0, static_cast<int>(scene.objects.size()) - 1);
    if (ImGui::BeginCombo("Object", scene.objects[state.selectedObject].name.c_str())) {
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (ImGui::Selectable(scene.objects[i].name.c_str(), state.selectedObject == static_cast<int>(i)))
                state.selectedObject = static_cast<int>(i);
        ImGui::EndCombo();
    }
    const int materialIndex = scene.objects[state.selectedObject].materialIndex;
    Material edited = scene.materials[materialIndex];
    ImGui::Text("Material: %s", edited.name.c_str());
    ImGui::Separator();
    if (drawMaterialPanel(edited, state.materialPanelMessage))
        state.session.change("Edit " + edited.name).materials[materialIndex] = std::move(edited);
    if (!state.materialPanelMessage.empty()) {
        ImGui::PushTextWrapPos();
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", state.materialPanelMessage.c_str());
        ImGui::PopTextWrapPos();
    }
}

}  // namespace glint
