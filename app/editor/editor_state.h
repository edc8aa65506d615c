// EditorState: everything the editor's panels and dialogs work on, in one struct grouped by use. The
// scene itself lives in `session` and changes only through it (app/editor/edit_session.h).
// It holds no GL objects and draws nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "classroom/classroom_state.h"
#include "classroom/compare_view.h"
#include "editor/edit_session.h"
#include "editor/recovery.h"
#include "editor/scene_message.h"
#include "editor/custom_brdf_state.h"
#include "editor/panels/file_browser.h"
#include "editor/panels/plots_window.h"
#include "editor/preset_swatches.h"
#include "editor/settings.h"
#include "interchange/imported.h"
#include "util/reference_confinement.h"

namespace glint {

class MeshLoadJob;  // editor/mesh_loading.h
class EnvironmentLoadJob;  // editor/environment_loading.h

// An interchange file that holds several materials, read and waiting while a modal asks which
// one to use (editor/interchange_open.h).
struct MaterialChoice {
    std::string path;
    ImportedFile file;
    int selected = 0;  // the row the modal highlights
};

struct EditorState {
    EditSession session;
    int selectedObject = 0;
    int selectedLight = 0;
    Settings settings;  // persisted: recent files, UI scale

    // Layout (pixels).
    // Side column widths at UI scale 1 [px]; on screen they grow with the scale (panels.h).
    float rightPanelWidth = 360.0f;
    float leftPanelWidth = 330.0f;
    bool showLeftPanel = true;
    bool showRightPanel = true;
    bool showHelp = false;
    // A typed value a panel refused, and why (dropped once the scene changes: scene_message.h).
    SceneMessage materialPanelMessage;
    SceneMessage lightPanelMessage;
    SceneMessage displayPanelMessage;  // a typed gamma or level count the display panel refused

    // Figures for the status bar.
    double lastRenderMilliseconds = 0.0;
    int previewScale = 1;  // >1 while a drag renders at reduced resolution
    int simplifiedMeshesShown = 0;  // large meshes drawn by their simplified stand-ins (while dragging)
    int standInProgramsShown = 0;   // objects drawn with generic programs while their own compile
    bool waitingForPrograms = false;  // a frame waits for programs compiling in the background
    bool shadowMapsRedrawn = false;  // the last render drew the shadow maps again
    long long triangleCount = 0;  // submitted by the last render
    std::string rendererDescription;
    std::string samplesNote;  // MSAA samples asked above what the OpenGL offers (Renderer::samplesNote)
    // The renderer's last error: a shader that does not compile (a hot reload, a .brdf) or a
    // failed frame; the status bar and the material panel show it until it goes.
    std::string renderProblem;
    SceneMessage statusMessage;  // one line ("Saved …")

    // Dialogs. An action waiting behind the unsaved-changes prompt (quit, new, open) runs once
    // the user saved or discarded; `errorMessage` is shown in a modal until dismissed.
    std::function<void(EditorState&)> actionAfterPrompt;
    std::string actionAfterPromptName;  // "closing Glint", "opening …"
    std::string pendingOpenPath;        // a scene to open once the prompt is answered
    bool unsavedPromptRequested = false;
    bool continueAfterSaveAs = false;   // Save chosen in the prompt for a scene with no file yet
    std::string errorMessage;
    std::vector<RecoveredWork> recoveryOffer;  // crashed editors' work, newest first; a modal at start
    std::string lastOpenedPath;  // the file last opened as File > Open does, replacing what it opens: opened again once references are allowed
    std::vector<RefusedReference> refusedReferences;  // asked about in a modal (panels/reference_prompt.cpp)
    FileBrowser fileBrowser;
    int textureMaterialIndex = -1;  // the material and parameter an image file is being chosen for
    std::string textureParameter;
    bool screenshotRequested = false;
    std::string screenshotPath;
    bool quitNow = false;
    std::optional<MaterialChoice> materialChoice;  // a file asking which of its materials to use
    std::shared_ptr<MeshLoadJob> meshLoad;  // the mesh file loading on a worker thread, if any
    std::shared_ptr<EnvironmentLoadJob> environmentLoad;  // the environment map being made, if any
    std::string environmentDeclined;  // the scene's environment whose map failed or was cancelled (environment_loading.cpp)

    // Autosave: the recovery file and the crash copy follow session.settledRevision().
    std::uint64_t autosavedRevision = 0;
    std::uint64_t crashCopyRevision = 0;
    double lastAutosaveSeconds = -1e9;  // glfwGetTime() of the last recovery write
    bool wroteRecovery = false;         // the recovery file on disk is this editor's

    ClassroomState classroom;  // lessons and the colour windows (app/classroom/)
    PresetSwatches presetSwatches;  // the preset browser's pictures (editor/preset_swatches.h)
    CompareViewState compare;  // the classroom's Compare window (classroom/compare_view.h)
    CustomBrdfEditorState customBrdfs;  // .brdf probes and hot reload (custom_brdf_editor.h)
    PlotsWindowState plots;  // classroom BRDF and Fresnel plots (panels/plots_window.h)
};

}  // namespace glint
