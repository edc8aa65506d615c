// Keyboard shortcuts (see shortcuts.h).
#include "editor/shortcuts.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "editor/camera_actions.h"
#include "editor/document.h"
#include "editor/key_events.h"
#include "editor/object_actions.h"

namespace glint {
namespace {

constexpr Shortcut kShortcuts[] = {
    {"Ctrl+N", "new scene (the default one)"},
    {"Ctrl+O", "open a scene"},
    {"Ctrl+M", "open a mesh (.obj .ply .stl .gltf .glb .fbx) as a new object"},
    {"Ctrl+S", "save the scene (asks for a name the first time)"},
    {"Ctrl+Shift+S", "save the scene as"},
    {"Ctrl+Z", "undo (a whole slider drag is one step)"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"Ctrl+Q", "quit (asks about unsaved changes)"},
    {"F", "frame the selected object"},
    {"Home", "reset the view"},
    {"P", "perspective / orthographic"},
    {"W", "wireframe overlay on / off"},
    {"N", "vertex normals overlay on / off"},
    {"F12", "screenshot of the viewport (PNG or EXR)"},
    {"F11", "presentation mode on / off (large font, high contrast, advanced panels hidden)"},
    {"L", "the lesson list"},
    {"Right / Left (in a lesson), PageDown / PageUp", "next / previous lesson"},
    {"F1", "this help"},
    {"left drag (viewport)", "orbit the camera"},
    {"right or middle drag", "pan"},
    {"mouse wheel", "zoom"},
    {"Ctrl+click a slider", "type a value"},
};

constexpr int kCtrl = GLFW_MOD_CONTROL;
constexpr int kCtrlShift = GLFW_MOD_CONTROL | GLFW_MOD_SHIFT;

}  // namespace

std::span<const Shortcut> allShortcuts() { return kShortcuts; }

void handleShortcuts(EditorState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    const bool modal = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    if (keyPressed(GLFW_KEY_F1)) state.showHelp = !state.showHelp;
    if (modal) return;  // dialogs take their own keys (Enter, Escape)
    if (keyPressed(GLFW_KEY_Z, kCtrl) && state.session.undo()) state.statusMessage = "Undone";
    if ((keyPressed(GLFW_KEY_Z, kCtrlShift) || keyPressed(GLFW_KEY_Y, kCtrl)) && state.session.redo())
        state.statusMessage = "Redone";
    if (keyPressed(GLFW_KEY_S, kCtrl)) saveScene(state);
    if (keyPressed(GLFW_KEY_S, kCtrlShift))
        requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, state.session.path());
    if (keyPressed(GLFW_KEY_O, kCtrl)) requestFileBrowser(state.fileBrowser, FilePurpose::OpenScene, state.session.path());
    if (keyPressed(GLFW_KEY_M, kCtrl)) requestFileBrowser(state.fileBrowser, FilePurpose::OpenMesh, "");
    if (keyPressed(GLFW_KEY_N, kCtrl)) guardUnsavedChanges(state, "starting a new scene", newScene);
    if (keyPressed(GLFW_KEY_Q, kCtrl)) requestQuit(state);
    if (io.WantCaptureKeyboard) return;
    if (keyPressed(GLFW_KEY_F)) frameSelected(state);
    if (keyPressed(GLFW_KEY_HOME)) resetView(state);
    if (keyPressed(GLFW_KEY_P)) toggleProjection(state);
    if (keyPressed(GLFW_KEY_W)) toggleWireframe(state);
    if (keyPressed(GLFW_KEY_N)) toggleNormals(state);
    if (keyPressed(GLFW_KEY_F12)) requestFileBrowser(state.fileBrowser, FilePurpose::SaveScreenshot, "viewport.png");
}

}  // namespace glint
