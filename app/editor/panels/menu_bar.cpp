// The menu bar: File (new, open, recent, save, save as, materials, screenshot, quit), Edit (undo,
// redo), View (panels, camera, UI scale), Help (shortcuts).
#include <imgui.h>

#include "classroom/classroom_editor.h"
#include "classroom/presentation.h"

#include "editor/camera_actions.h"
#include "editor/document.h"
#include "editor/object_actions.h"
#include "editor/panels/panels.h"
#include "editor/probe_panel.h"

namespace glint {
namespace {

void drawFileMenu(EditorState& state) {
    if (!ImGui::BeginMenu("File")) return;
    if (ImGui::MenuItem("New scene", "Ctrl+N")) guardUnsavedChanges(state, "starting a new scene", newScene);
    if (ImGui::MenuItem("Open scene…", "Ctrl+O"))
        requestFileBrowser(state.fileBrowser, FilePurpose::OpenScene, state.session.path());
    if (ImGui::BeginMenu("Open recent", !state.settings.recentFiles.empty())) {
        for (const std::string& path : state.settings.recentFiles)
            if (ImGui::MenuItem(path.c_str())) {
                const std::string chosen = path;  // the list changes when the scene opens
                openSceneGuarded(state, chosen);
                break;
            }
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Open mesh…", "Ctrl+M")) requestFileBrowser(state.fileBrowser, FilePurpose::OpenMesh, "");
    if (ImGui::MenuItem("Save scene", "Ctrl+S")) saveScene(state);
    if (ImGui::MenuItem("Save scene as…", "Ctrl+Shift+S"))
        requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, state.session.path());
    ImGui::Separator();
    const bool hasObject = !state.session.scene().objects.empty();
    if (ImGui::MenuItem("Open material…", nullptr, false, hasObject))
        requestFileBrowser(state.fileBrowser, FilePurpose::OpenMaterial, "");
    if (ImGui::MenuItem("Save material as…", nullptr, false, hasObject))
        requestFileBrowser(state.fileBrowser, FilePurpose::SaveMaterialAs, "material.json");
    if (ImGui::MenuItem("Export material (.gltf, .mtl, .mtlx)…", nullptr, false, hasObject))  // editor/interchange_export.h
        requestFileBrowser(state.fileBrowser, FilePurpose::ExportMaterial, "material.gltf");
    if (advancedPanelsVisible(state.settings)) {  // presentation mode hides the BRDF Explorer file actions
        if (ImGui::MenuItem("Open BRDF Explorer file (.brdf, .bparam)…", nullptr, false, hasObject))
            requestFileBrowser(state.fileBrowser, FilePurpose::OpenBrdf, "");
        const bool customMaterial =
            hasObject && state.session.scene().materials[state.session.scene().objects[state.selectedObject].materialIndex].custom();
        if (ImGui::MenuItem("Save parameter values as .bparam…", nullptr, false, customMaterial))
            requestFileBrowser(state.fileBrowser, FilePurpose::SaveBparamAs, "values.bparam");
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot of the viewport…", "F12"))
        requestFileBrowser(state.fileBrowser, FilePurpose::SaveScreenshot, "viewport.png");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit(state);
    ImGui::EndMenu();
}

void drawEditMenu(EditorState& state) {
    if (!ImGui::BeginMenu("Edit")) return;
    const std::string undo = "Undo " + state.session.undoLabel();
    const std::string redo = "Redo " + state.session.redoLabel();
    if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, state.session.canUndo())) state.session.undo();
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, state.session.canRedo())) state.session.redo();
    ImGui::EndMenu();
}

void drawViewMenu(EditorState& state) {
    if (!ImGui::BeginMenu("View")) return;
    ImGui::MenuItem("Scene panel (left)", nullptr, &state.showLeftPanel);
    ImGui::MenuItem("Material panel (right)", nullptr, &state.showRightPanel);
    ImGui::Separator();
    if (ImGui::MenuItem("Frame selected", "F")) frameSelected(state);
    if (ImGui::MenuItem("Reset view", "Home")) resetView(state);
    const bool orthographic = state.session.scene().camera.projection == Projection::Orthographic;
    if (ImGui::MenuItem("Orthographic", "P", orthographic)) toggleProjection(state);
    const OverlaySettings& overlays = state.session.scene().display.overlays;
    if (ImGui::MenuItem("Wireframe overlay", "W", overlays.wireframe)) toggleWireframe(state);
    if (ImGui::MenuItem("Normals overlay", "N", overlays.normals)) toggleNormals(state);
    if (ImGui::MenuItem("Surface probe (Shift+click)", "I", probeToolOn())) toggleProbeTool();
    ImGui::MenuItem("BRDF and Fresnel plots", "B", &state.plots.open);
    // Large meshes' stand-ins and coarser changed shadow maps while dragging (editor/viewport_refresh.h);
    // kept in settings.json.
    if (ImGui::MenuItem("Simplify meshes and shadows while dragging", nullptr, &state.settings.simplifyMeshesWhileDragging))
        saveSettings(state.settings);
    // Files a file names outside its own folder (util/reference_confinement.h); kept in settings.json.
    if (ImGui::MenuItem(kAllowOutsideReferencesSetting, nullptr, &state.settings.allowOutsideReferences)) {
        setOutsideReferencesAllowed(state.settings.allowOutsideReferences);
        saveSettings(state.settings);
    }
    ImGui::Separator();  // the classroom's compare views (classroom/compare_view.h)
    if (ImGui::MenuItem("Compare materials…")) openCompareView(state, false);
    if (ImGui::MenuItem("Shading interpolation…")) openCompareView(state, true);
    ImGui::Separator();
    float scale = state.settings.uiScale;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    if (ImGui::SliderFloat("UI scale", &scale, 0.75f, 3.0f, "%.2f×") && scale >= 0.75f && scale <= 3.0f)
        state.settings.uiScale = scale;
    if (ImGui::IsItemDeactivatedAfterEdit()) saveSettings(state.settings);
    drawClassroomViewMenuItems(state);  // lessons, presentation mode, colour windows
    ImGui::EndMenu();
}

}  // namespace

float drawMenuBar(EditorState& state) {
    float height = 0.0f;
    if (ImGui::BeginMainMenuBar()) {
        drawFileMenu(state);
        drawEditMenu(state);
        drawViewMenu(state);
        if (ImGui::BeginMenu("Help")) {
            ImGui::MenuItem("Keyboard and mouse", "F1", &state.showHelp);
            ImGui::EndMenu();
        }
        height = ImGui::GetWindowSize().y;
        ImGui::EndMainMenuBar();
    }
    return height;
}

}  // namespace glint
