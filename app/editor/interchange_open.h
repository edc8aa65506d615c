// Opening an interchange file (.mtl, .gltf: interchange/import_formats.h) in the editor: one of
// its materials goes onto the selected object's material, its lights are added to the scene, as
// one undoable edit. A file with several materials asks first which one (state.materialChoice,
// drawn by panels/dialogs.cpp). Errors leave the scene as it was. Exporting is not here.
#pragma once

#include <cstddef>
#include <string>

#include "editor/editor_state.h"

namespace glint {

// Opens `path` with the loader its extension names; false when no format claims the extension.
// A file with one material (or none) is applied at once; one with several is kept in
// state.materialChoice, the first preselected, until takeMaterialChoice or cancelMaterialChoice.
bool openInterchangeFile(EditorState& state, const std::string& path);

// Applies material `index` of the waiting file (and its lights, its warnings) as one undo step.
void takeMaterialChoice(EditorState& state, size_t index);
// Drops the waiting file; the scene and its history are unchanged.
void cancelMaterialChoice(EditorState& state);

}  // namespace glint
