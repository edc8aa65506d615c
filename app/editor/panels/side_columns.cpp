// The two side columns the viewport shows between: the scene column on the left (lights,
// display, camera) and the material column on the right (object, material). Both are fixed to the
// window edge, resizable by their inner edge and collapsible (title bar arrow or View menu).
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "classroom/presentation.h"
#include "editor/panels/panels.h"

namespace glint {
namespace {

constexpr ImGuiWindowFlags kColumnFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;

void pushPanelItemWidth() { ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.5f); }

float columnScreenWidth(float widthAtScaleOne, const EditorState& state) {
    return std::min(widthAtScaleOne * effectiveUiScale(state.settings, ImGui::GetIO().DisplaySize.y), columnWidthLimit(state.settings));
}

// How far the user may drag a column's inner edge [px]: 160 up to 40 % of the window (26 % while presenting).
void setColumnSizeConstraints(const EditorState& state) {
    const float limit = columnWidthLimit(state.settings);
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(160.0f, limit), 0.0f), ImVec2(std::max(std::min(160.0f, limit), limit), 1e6f));
}

// After the user dragged the column's inner edge: its new width back in scale-1 units. Untouched
// otherwise, so the 40 % limit of a small window never shrinks the stored width.
void keepDraggedWidth(float& widthAtScaleOne, float shownWidth, const EditorState& state) {
    const float now = ImGui::GetWindowWidth();
    if (std::abs(now - shownWidth) > 0.5f) widthAtScaleOne = now / effectiveUiScale(state.settings, ImGui::GetIO().DisplaySize.y);
}

}  // namespace

float leftColumnScreenWidth(const EditorState& state) { return columnScreenWidth(state.leftPanelWidth, state); }
float rightColumnScreenWidth(const EditorState& state) { return columnScreenWidth(state.rightPanelWidth, state); }

void drawScenePanel(EditorState& state, float top, float height) {
    if (!state.showLeftPanel) return;
    ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
    const float shownWidth = leftColumnScreenWidth(state);
    ImGui::SetNextWindowSize(ImVec2(shownWidth, height), ImGuiCond_Always);
    setColumnSizeConstraints(state);
    if (ImGui::Begin("Scene", &state.showLeftPanel, kColumnFlags)) {
        keepDraggedWidth(state.leftPanelWidth, shownWidth, state);
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
    const float shownWidth = rightColumnScreenWidth(state);
    ImGui::SetNextWindowPos(ImVec2(windowWidth - shownWidth, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(shownWidth, height), ImGuiCond_Always);
    setColumnSizeConstraints(state);
    if (ImGui::Begin("Material", &state.showRightPanel, kColumnFlags)) {
        keepDraggedWidth(state.rightPanelWidth, shownWidth, state);
        pushPanelItemWidth();
        drawObjectSection(state);
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

}  // namespace glint
