// Opening an asset (a glTF / GLB with meshes, an OBJ + MTL: interchange/asset.h) in the editor:
// it replaces the scene, as opening a scene file does, after the unsaved-changes guard. The
// scene it makes is untitled (Save asks where). Adding a mesh to the scene is mesh_loading.h.
#pragma once

#include <string>

#include "editor/editor_state.h"

namespace glint {

// Asks about unsaved work first, then opens `path` as the asset on the preview stage; an error
// leaves the work as it was and says why.
void openAssetGuarded(EditorState& state, const std::string& path);

}  // namespace glint
