// The modal that asks about referenced files refused outside a file's folder
// (core/util/reference_confinement.h): "Allow once" allows the files that named them for this run
// and opens the file again, "Always allow" also ticks the setting, "Keep refused" leaves them out.
// It waits while another modal is open, so that two modals never compete for the same frame. No
// Enter default: a key meant for something else must not read what was refused.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <string>
#include <utility>

#include <imgui.h>

#include "editor/document.h"
#include "editor/key_events.h"
#include "editor/panels/panels.h"

namespace glint {
namespace {

constexpr const char* kTitle = "Files outside the folder";

// Files refused since the last frame, added once each.
void collectRefusals(EditorState& state) {
    for (RefusedReference& refused : takeRefusedReferences())
        if (std::find(state.refusedReferences.begin(), state.refusedReferences.end(), refused) == state.refusedReferences.end())
            state.refusedReferences.push_back(std::move(refused));
}

// Opens the file that named them again, as File > Open does, now that they are allowed. A mesh
// added as an object is not added twice: the user opens it again.
void openAgain(EditorState& state) {
    state.refusedReferences.clear();
    const std::string path = std::exchange(state.lastOpenedPath, {});
    if (!path.empty()) openDroppedFile(state, path);
    else state.statusMessage = "Allowed: open the mesh again to read the files it names";
}

}  // namespace

void drawReferencePrompt(EditorState& state) {
    collectRefusals(state);
    if (state.refusedReferences.empty()) return;
    if (!ImGui::IsPopupOpen(kTitle)) {
        const bool otherModal = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) || !state.errorMessage.empty() ||
                                !state.recoveryOffer.empty() || state.materialChoice || state.meshLoad;
        if (otherModal) return;  // asked once the other is answered
        ImGui::OpenPopup(kTitle);
    }
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextUnformatted("These files name files outside their own folder, which Glint does not read unless you allow it:");
    ImGui::PopTextWrapPos();
    for (const RefusedReference& refused : state.refusedReferences)
        ImGui::BulletText("%s names %s", refused.referencingFile.c_str(), refused.written.c_str());
    ImGui::Spacing();
    if (ImGui::Button("Allow once (O)") || takeKeyPress(GLFW_KEY_O)) {
        for (const RefusedReference& refused : state.refusedReferences) allowOutsideReferencesOf(refused.referencingFile);
        ImGui::CloseCurrentPopup();
        openAgain(state);
    }
    ImGui::SameLine();
    if (ImGui::Button("Always allow")) {
        state.settings.allowOutsideReferences = true;
        saveSettings(state.settings);
        setOutsideReferencesAllowed(true);
        ImGui::CloseCurrentPopup();
        openAgain(state);
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep refused (Esc)") || takeKeyPress(GLFW_KEY_ESCAPE)) {
        state.refusedReferences.clear();
        state.lastOpenedPath.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace glint
