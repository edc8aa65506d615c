// Opening an interchange file (.mtl, .gltf: interchange/import_formats.h) in the editor: its
// first material goes onto the selected object's material, its lights are added to the scene,
// as one undoable edit. Errors leave the scene as it was. Exporting is not here.
#pragma once

#include <string>

#include "editor/editor_state.h"

namespace glint {

// Opens `path` with the loader its extension names; false when no format claims the extension.
bool openInterchangeFile(EditorState& state, const std::string& path);

}  // namespace glint
