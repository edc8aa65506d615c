// The two side columns the viewport shows between: the scene column on the left (lights,
// display, camera) and the material column on the right (object, material). Both are fixed to the
// window edge, resizable by their inner edge and collapsible (title bar arrow or View menu).
#include <imgui.h>

#include "editor/panels/panels.h"

namespace glint {
namespace {

constexpr ImGuiWindowFlags kColumnFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;

void pushPanelItemWidth() { ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.5f); }

}  // namespace

void drawScenePanel(EditorState& state, float top, float height) {
    if (!state.showLeftPanel) return;
    ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(state.leftPanelWidth, height), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(220, 0), ImVec2(900, 1e6f));
    if (ImGui::Begin("Scene", &state.showLeftPanel, kColumnFlags)) {
        state.leftPanelWidth = ImGui::GetWindowWidth();
        pushPanelItemWidth();
        if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) drawLightsSection(state);
        if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) drawDisplaySection(state);
        if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) drawCameraSection(state);
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

void drawMaterialColumn(EditorState& state, float top, float height, float windowWidth) {
    if (!state.showRightPanel) return;
    ImGui::SetNextWindowPos(ImVec2(windowWidth - state.rightPanelWidth, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(state.rightPanelWidth, height), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(240, 0), ImVec2(900, 1e6f));
    if (ImGui::Begin("Material", &state.showRightPanel, kColumnFlags)) {
        state.rightPanelWidth = ImGui::GetWindowWidth();
        pushPanelItemWidth();
        drawObjectSection(state);
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

}  // namespace glint
