// The camera section: projection (perspective / orthographic), vertical field of view or view
// height, and the frame-selected and reset actions. Every change is an undoable edit.
#include <imgui.h>

#include <cmath>

#include "editor/camera_actions.h"
#include "editor/panels/panels.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"

namespace glint {

void drawCameraSection(EditorState& state) {
    Camera camera = state.session.scene().camera;
    bool changed = false;
    int projection = camera.projection == Projection::Perspective ? 0 : 1;
    if (comboBox("Projection", &projection, "perspective\0orthographic\0")) {
        toggleProjection(state);
        return;
    }
    if (camera.projection == Projection::Perspective) {
        float fov = camera.verticalFovDegrees;
        if (editNumbers("Field of view", &fov, 1, [](float* typed) { return ImGui::SliderFloat("Field of view", typed, 5.0f, 120.0f, "%.1f°"); })) {
            if (fov > 0.0f && fov < 180.0f) camera.verticalFovDegrees = fov, changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Vertical field of view");
    } else {
        float height = camera.orthoHeight;
        if (editNumbers("View height", &height, 1, [](float* typed) { return ImGui::DragFloat("View height", typed, 0.02f, 0.01f, 1000.0f, "%.2f m"); })) {
            if (height > 0.0f && std::isfinite(height)) camera.orthoHeight = height, changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Height of the orthographic view [m]");
    }
    if (changed) state.session.change("Edit camera").camera = camera;
    if (ImGui::Button("Frame selected (F)")) frameSelected(state);
    sameLineIfFits(buttonWidth("Reset view (Home)"));
    if (ImGui::Button("Reset view (Home)")) resetView(state);
}

}  // namespace glint
