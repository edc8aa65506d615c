// File ▸ Export material…: the selected object's material written as a Wavefront .mtl or a
// glTF .gltf (with the scene's lights), atomically, through the same core functions as
// `glint export` (interchange/export_formats.h). Opening interchange files is interchange_open.h.
#pragma once

#include <string>

#include "editor/editor_state.h"

namespace glint {

// Writes the file; what the format cannot hold is shown as warnings (errorMessage), failures
// too, and the scene is never changed. False when nothing was written.
bool exportMaterialTo(EditorState& state, const std::string& path);

}  // namespace glint
