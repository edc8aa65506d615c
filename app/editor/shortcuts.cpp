// Keyboard shortcuts (see shortcuts.h).
#include "editor/shortcuts.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "editor/camera_actions.h"
#include "editor/document.h"

namespace glint {
namespace {

constexpr Shortcut kShortcuts[] = {
    {"Ctrl+N", "new scene (the default one)"},
    {"Ctrl+O", "open a scene"},
    {"Ctrl+S", "save the scene (asks for a name the first time)"},
    {"Ctrl+Shift+S", "save the scene as"},
    {"Ctrl+Z", "undo (a whole slider drag is one step)"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"Ctrl+Q", "quit (asks about unsaved changes)"},
    {"F", "frame the selected object"},
    {"Home", "reset the view"},
    {"P", "perspective / orthographic"},
    {"F12", "screenshot of the viewport (PNG or EXR)"},
    {"F1", "this help"},
    {"left drag (viewport)", "orbit the camera"},
    {"right or middle drag", "pan"},
    {"mouse wheel", "zoom"},
    {"Ctrl+click a slider", "type a value"},
};

bool pressed(int key) { return ImGui::IsKeyPressed(key, /*repeat=*/false); }
bool repeated(int key) { return ImGui::IsKeyPressed(key, /*repeat=*/true); }

}  // namespace

std::span<const Shortcut> allShortcuts() { return kShortcuts; }

void handleShortcuts(EditorState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    const bool modal = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    if (pressed(GLFW_KEY_F1)) state.showHelp = !state.showHelp;
    if (modal) return;  // dialogs take their own keys (Enter, Escape)
    if (io.KeyCtrl) {
        if (repeated(GLFW_KEY_Z) && !io.KeyShift && state.session.undo()) state.statusMessage = "Undone";
        if ((repeated(GLFW_KEY_Z) && io.KeyShift) || repeated(GLFW_KEY_Y))
            if (state.session.redo()) state.statusMessage = "Redone";
        if (pressed(GLFW_KEY_S)) {
            if (io.KeyShift) requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, state.session.path());
            else saveScene(state);
        }
        if (pressed(GLFW_KEY_O)) requestFileBrowser(state.fileBrowser, FilePurpose::OpenScene, state.session.path());
        if (pressed(GLFW_KEY_N)) guardUnsavedChanges(state, "starting a new scene", newScene);
        if (pressed(GLFW_KEY_Q)) requestQuit(state);
        return;
    }
    if (io.WantCaptureKeyboard) return;
    if (pressed(GLFW_KEY_F)) frameSelected(state);
    if (pressed(GLFW_KEY_HOME)) resetView(state);
    if (pressed(GLFW_KEY_P)) toggleProjection(state);
    if (pressed(GLFW_KEY_F12)) requestFileBrowser(state.fileBrowser, FilePurpose::SaveScreenshot, "viewport.png");
}

}  // namespace glint
