// Opening an asset (a glTF / GLB with meshes, an OBJ + MTL: interchange/asset.h) in the editor:
// after the unsaved-changes guard it loads on the mesh loader's worker thread (mesh_loading.h:
// progress, Cancel) and then replaces the scene, as opening a scene file does. The scene it
// makes is untitled (Save asks where). Adding a mesh to the scene is mesh_loading.h.
#pragma once

#include <string>

#include "editor/editor_state.h"
#include "interchange/asset.h"

namespace glint {

// Asks about unsaved work first, then starts loading `path` as the asset; an error leaves the
// work as it was and says why.
void openAssetGuarded(EditorState& state, const std::string& path);
// The loaded asset on the preview stage in place of the scene, with its summary and warnings.
void openLoadedAsset(EditorState& state, const std::string& path, const Asset& asset);

}  // namespace glint
