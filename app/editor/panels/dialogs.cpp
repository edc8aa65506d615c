// Modal dialogs: "unsaved changes" (Save / Don't save / Cancel), errors (file:line from the
// Diagnostic), the recovery offer at start, which material of a file to use, the file browser's result, and the help window (F1)
// listing every shortcut.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include <imgui.h>

#include "classroom/lesson_document.h"
#include "editor/custom_brdf_editor.h"
#include "editor/document.h"
#include "editor/environment_loading.h"
#include "editor/interchange_export.h"
#include "editor/interchange_open.h"
#include "editor/mesh_loading.h"
#include "editor/key_events.h"
#include "editor/panels/panels.h"
#include "editor/texture_panel.h"
#include "editor/window_placement.h"
#include "editor/shortcuts.h"

namespace glint {
namespace {

void centreNextWindow() {
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
}

// ImGui keeps one popup per level: opening a modal closes any other one open. A modal that may be
// asked for while another is up (an error from a background job, a close request) waits for it.
bool noPopupOpen() { return !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel); }

void drawUnsavedPrompt(EditorState& state) {
    if (state.unsavedPromptRequested && noPopupOpen()) {
        ImGui::OpenPopup("Unsaved changes");
        state.unsavedPromptRequested = false;
    }
    centreNextWindow();
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    // No default button: Enter answers nothing here, so a key meant for something else cannot
    // save over a file. A lesson (no path: read-only course material) offers Save as instead.
    const std::string& path = state.session.path();
    const std::string lesson = lessonDocumentName(state);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    if (!lesson.empty()) ImGui::Text("Keep your edits to %s before %s? The lesson itself is never changed.", lesson.c_str(),
                                     state.actionAfterPromptName.c_str());
    else ImGui::Text("Save changes to %s before %s?", path.empty() ? "the untitled scene" : path.c_str(),
                     state.actionAfterPromptName.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Spacing();
    if (ImGui::Button(path.empty() ? "Save as… (S)" : "Save (S)") || takeKeyPress(GLFW_KEY_S)) {
        ImGui::CloseCurrentPopup();
        if (path.empty()) {
            state.continueAfterSaveAs = true;
            requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, "untitled.json");
        } else if (saveSceneTo(state, path)) {
            runActionAfterPrompt(state);
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Don't save (N)") || takeKeyPress(GLFW_KEY_N)) {
        ImGui::CloseCurrentPopup();
        runActionAfterPrompt(state);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)") || takeKeyPress(GLFW_KEY_ESCAPE)) {
        ImGui::CloseCurrentPopup();
        state.actionAfterPrompt = nullptr;
        state.pendingOpenPath.clear();
    }
    ImGui::EndPopup();
}

void drawErrorModal(EditorState& state) {
    if (!state.errorMessage.empty() && noPopupOpen()) {
        ImGui::OpenPopup("Error");
        std::fprintf(stderr, "glint: %s\n", state.errorMessage.c_str());  // the log keeps what the modal says
    }
    centreNextWindow();
    ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(900, 600));
    if (!ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextUnformatted(state.errorMessage.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("OK") || takeKeyPress(GLFW_KEY_ENTER) || takeKeyPress(GLFW_KEY_ESCAPE)) {
        state.errorMessage.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void drawRecoveryOffer(EditorState& state) {
    if (state.recoveryOffer.empty()) return;
    if (!ImGui::IsPopupOpen("Recover unsaved work")) ImGui::OpenPopup("Recover unsaved work");
    centreNextWindow();
    if (!ImGui::BeginPopupModal("Recover unsaved work", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const RecoveredWork& work = state.recoveryOffer.front();
    ImGui::Text("A Glint editor did not close cleanly. Unsaved work was kept:");
    ImGui::BulletText("scene: %s", work.scenePath.empty() ? "(never saved)" : work.scenePath.c_str());
    ImGui::BulletText("%zu objects, %zu lights", work.scene.objects.size(), work.scene.lights.size());
    ImGui::TextDisabled("from %s", work.recoveryPath.c_str());
    if (state.recoveryOffer.size() > 1)
        ImGui::TextDisabled("%zu more recovery files follow", state.recoveryOffer.size() - 1);
    ImGui::Spacing();
    if (ImGui::Button("Recover (Enter)") || takeKeyPress(GLFW_KEY_ENTER)) {
        state.session.replace(work.scene, work.scenePath, /*dirty=*/true);
        state.selectedObject = 0;
        state.selectedLight = 0;
        // The file becomes this editor's: autosave updates it, a clean exit removes it. Other
        // offers stay on disk for the next start.
        std::error_code error;
        if (work.recoveryPath != recoveryFilePath()) {
            std::filesystem::rename(work.recoveryPath, recoveryFilePath(), error);
            if (!error) removeRecoveryFile(work.recoveryPath);  // what is left: its lock file
        }
        state.wroteRecovery = !error;
        const size_t kept = state.recoveryOffer.size() - 1;
        state.statusMessage = "Recovered unsaved work: save it to keep it" +
                              (kept ? " (" + std::to_string(kept) + " more recovery files are kept for the next start)" : "");
        state.recoveryOffer.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard (Delete)") || takeKeyPress(GLFW_KEY_DELETE)) {
        removeRecoveryFile(work.recoveryPath);
        state.recoveryOffer.erase(state.recoveryOffer.begin());
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// A file with several materials: pick one by index and name (Enter or double-click), Esc cancels.
void drawMaterialChoice(EditorState& state) {
    if (!state.materialChoice) return;
    if (!ImGui::IsPopupOpen("Choose a material")) ImGui::OpenPopup("Choose a material");
    centreNextWindow();
    if (!ImGui::BeginPopupModal("Choose a material", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    MaterialChoice& choice = *state.materialChoice;
    const int count = static_cast<int>(choice.file.materials.size());
    ImGui::Text("%s holds %d materials. Which one goes on the selected object?", choice.path.c_str(), count);
    if (takeKeyPress(GLFW_KEY_DOWN)) choice.selected = std::min(choice.selected + 1, count - 1);
    if (takeKeyPress(GLFW_KEY_UP)) choice.selected = std::max(choice.selected - 1, 0);
    int taken = -1;
    const float rows = static_cast<float>(std::min(count, 12));
    if (ImGui::BeginListBox("##materials", ImVec2(ImGui::GetFontSize() * 30.0f, rows * ImGui::GetTextLineHeightWithSpacing() + 8.0f))) {
        for (int i = 0; i < count; ++i) {
            const std::string label = std::to_string(i) + "  " + choice.file.materials[i].material.name + "##" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), i == choice.selected, ImGuiSelectableFlags_AllowDoubleClick)) {
                choice.selected = i;
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) taken = i;
            }
        }
        ImGui::EndListBox();
    }
    if (ImGui::Button("Open (Enter)") || takeKeyPress(GLFW_KEY_ENTER)) taken = choice.selected;
    ImGui::SameLine();
    const bool cancelled = ImGui::Button("Cancel (Esc)") || takeKeyPress(GLFW_KEY_ESCAPE);
    if (taken >= 0 || cancelled) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (taken >= 0) takeMaterialChoice(state, static_cast<size_t>(taken));
    else if (cancelled) cancelMaterialChoice(state);
}

void handleFileBrowser(EditorState& state) {
    const auto chosen = drawFileBrowser(state.fileBrowser);
    if (!chosen) {
        if (!ImGui::IsPopupOpen("###FileBrowser")) state.continueAfterSaveAs = false;
        return;
    }
    switch (state.fileBrowser.purpose) {
        case FilePurpose::OpenScene: openDroppedFile(state, *chosen); break;  // scene, material or interchange file
        case FilePurpose::SaveSceneAs:
            if (saveSceneTo(state, *chosen) && state.continueAfterSaveAs) runActionAfterPrompt(state);
            state.continueAfterSaveAs = false;
            break;
        case FilePurpose::OpenMaterial: openDroppedFile(state, *chosen); break;
        case FilePurpose::SaveMaterialAs: saveMaterialTo(state, *chosen); break;
        case FilePurpose::OpenMesh:  // adds an object: not added again once references are allowed
            state.lastOpenedPath.clear();
            startMeshLoad(state, *chosen);
            break;
        case FilePurpose::OpenTexture: openTextureFile(state, *chosen); break;
        case FilePurpose::OpenBrdf: openDroppedFile(state, *chosen); break;  // routes .brdf and .bparam
        case FilePurpose::SaveBparamAs: saveBparamTo(state, *chosen); break;
        case FilePurpose::OpenEnvironment: startEnvironmentLoad(state, EnvironmentKind::File, *chosen); break;
        case FilePurpose::ExportMaterial: exportMaterialTo(state, *chosen); break;
        case FilePurpose::SaveScreenshot:
            state.screenshotRequested = true;
            state.screenshotPath = *chosen;
            break;
    }
}

void drawHelpWindow(EditorState& state) {
    if (!state.showHelp) return;
    // Rows wrap inside the window, which scales with the UI and never leaves the screen.
    if (beginPlacedWindow("Keyboard and mouse (F1)", &state.showHelp, {ImVec2(40.0f, 28.0f), ImVec2(20.0f, 10.0f), ImVec2(0.8f, 0.9f)})) {
        if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthStretch, 0.4f);
            ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch, 0.6f);
            for (const Shortcut& shortcut : allShortcuts()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextWrapped("%s", shortcut.keys);
                ImGui::TableNextColumn();
                ImGui::TextWrapped("%s", shortcut.action);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace

void drawDialogs(EditorState& state) {
    drawHelpWindow(state);  // an ordinary window: before every modal (see panels.h)
    // One modal at a time, and the recovery offer at start first: the lesson `glint present`
    // opens, or the file given on the command line, may ask something of its own meanwhile.
    if (!state.recoveryOffer.empty()) {
        drawRecoveryOffer(state);
        return;
    }
    drawMeshLoadDialog(state);
    drawUnsavedPrompt(state);
    handleFileBrowser(state);
    drawMaterialChoice(state);
    drawErrorModal(state);
    drawReferencePrompt(state);  // waits for every other modal to be answered
}

}  // namespace glint
