// Document actions: open, save and save-as for scenes and materials, dropped files, the
// unsaved-changes guard in front of actions that would drop work, and autosave to the recovery
// file (plus the copy the crash guard writes). Errors go to the UI (state.errorMessage) and the
// current work is left untouched. Drawing the dialogs lives in panels/dialogs.cpp.
#pragma once

#include <string>

#include "editor/editor_state.h"

namespace glint {

void openSceneFile(EditorState& state, const std::string& path);
// Saves to `path` atomically; true when it worked (else errorMessage says why).
bool saveSceneTo(EditorState& state, const std::string& path);
// Ctrl+S: to the scene's own path, or through the file browser when it has none.
void saveScene(EditorState& state);
void openMaterialFile(EditorState& state, const std::string& path);  // into the selected object's material
bool saveMaterialTo(EditorState& state, const std::string& path);
// A file dropped on the window or chosen in File ▸ Open: an asset (.obj, a .gltf or .glb with
// meshes) replaces the scene (asset_open.h); an interchange file (.mtl, a .gltf of materials) and
// a material file go into the selected object (glTF lights into the scene); anything else is
// opened as a scene.
void openDroppedFile(EditorState& state, const std::string& path);

// Runs `action` now when there are no unsaved changes, else asks first (Save / Don't save / Cancel).
void guardUnsavedChanges(EditorState& state, const std::string& what, std::function<void(EditorState&)> action);
// Runs the action waiting behind the prompt (after Save or Don't save).
void runActionAfterPrompt(EditorState& state);
// Opens a scene once unsaved changes are saved or discarded.
void openSceneGuarded(EditorState& state, const std::string& path);
void requestQuit(EditorState& state);
void newScene(EditorState& state);

// Start-up: installs the crash guard and, if a recovery file exists, offers it.
void startRecovery(EditorState& state);
// Each frame: keeps the crash copy current and writes the recovery file when the work changed
// and `autosaveIntervalSeconds` passed since the last write. Returns the seconds until a write
// is due (or a large number when none is), so the loop can sleep until then.
double autosave(EditorState& state, double nowSeconds, double autosaveIntervalSeconds);
// Clean exit: the work was saved or discarded, so the recovery file goes.
void finishRecovery(EditorState& state);

}  // namespace glint
