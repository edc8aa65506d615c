// The status bar: frame time (and whether it was a reduced preview), triangle count, renderer, unsaved-changes marker and the last
// message (saved, opened, recovered).
#include <imgui.h>

#include <algorithm>
#include <string>

#include "classroom/lesson_document.h"
#include "editor/environment_loading.h"
#include "editor/panels/panels.h"
#include "editor/panels/widgets.h"

namespace glint {

float drawStatusBar(EditorState& state, float top, float width) {
    const float height = ImGui::GetFrameHeight() + 2.0f;
    ImGui::SetNextWindowPos(ImVec2(0, top - height));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 2));
    ImGui::Begin("##status", nullptr, flags);
    const std::string lesson = lessonDocumentName(state);
    const std::string& path = state.session.path();
    ImGui::Text("%s%s", hasUnsavedWork(state) ? "● " : "", !lesson.empty() ? lesson.c_str() : path.empty() ? "untitled" : path.c_str());
    ImGui::SameLine(0, 24);
    // While dragging: what the frame left out (editor/viewport_refresh.h).
    std::string reduced = state.previewScale > 1 ? "preview 1/" + std::to_string(state.previewScale) : "";
    if (state.simplifiedMeshesShown > 0) reduced += reduced.empty() ? "simplified meshes" : ", simplified meshes";
    if (state.standInProgramsShown > 0) reduced += reduced.empty() ? "generic shaders" : ", generic shaders";
    if (!reduced.empty()) ImGui::Text("frame %.1f ms (%s)", state.lastRenderMilliseconds, reduced.c_str());
    else ImGui::Text("frame %.1f ms", state.lastRenderMilliseconds);
    if (state.environmentLoad) {
        ImGui::SameLine(0, 24);
        ImGui::TextUnformatted(state.environmentLoad->progressText().c_str());
    }
    if (state.waitingForPrograms) {
        ImGui::SameLine(0, 24);
        ImGui::TextUnformatted("compiling shaders");
    }
    ImGui::SameLine(0, 24);
    ImGui::Text("%lld triangles", state.triangleCount);
    ImGui::SameLine(0, 24);
    ImGui::TextDisabled("%s", state.rendererDescription.c_str());
    if (!state.renderProblem.empty()) {
        ImGui::SameLine(0, 24);
        // One line: the located messages after a first line such as "surface.frag: shader compile failed:".
        const size_t firstBreak = state.renderProblem.find('\n');
        std::string located = firstBreak == std::string::npos ? state.renderProblem : state.renderProblem.substr(firstBreak + 1);
        std::replace(located.begin(), located.end(), '\n', ' ');
        drawProblemText(located, false);
    }
    if (!state.statusMessage.empty()) {
        ImGui::SameLine(0, 24);
        ImGui::TextUnformatted(state.statusMessage.c_str());
    }
    ImGui::End();
    ImGui::PopStyleVar();
    return height;
}

}  // namespace glint
