// The modal shown while a mesh loads on its worker thread: file name, a progress bar and Cancel.
// The rest of the window keeps drawing behind it; the job itself is editor/mesh_loading.h.
#include <imgui.h>

#include <filesystem>

#include "editor/mesh_loading.h"
#include "editor/panels/panels.h"

namespace glint {

void drawMeshLoadDialog(EditorState& state) {
    constexpr const char* kTitle = "Loading mesh###MeshLoad";
    const bool open = ImGui::IsPopupOpen(kTitle);
    if (!state.meshLoad && !open) return;
    if (state.meshLoad && !open) ImGui::OpenPopup(kTitle);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (!state.meshLoad) {  // finished: the result is in the scene, the status line or the error modal
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    MeshLoadJob& job = *state.meshLoad;
    ImGui::Text("%s", std::filesystem::path(job.path()).filename().string().c_str());
    ImGui::ProgressBar(job.progress(), ImVec2(ImGui::GetFontSize() * 20.0f, 0.0f));
    if (job.cancelRequested()) ImGui::TextDisabled("Cancelling…");
    else if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) job.cancel();
    ImGui::EndPopup();
}

}  // namespace glint
