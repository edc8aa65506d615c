// The material panel's texture controls: per scalar or colour parameter (and the normal map) a
// small button whose menu puts a texture on it (none, image file, checker, marble, wood), and
// that texture's settings below it. Edits a Material copy, like material_panel.h; choosing an
// image file is asked of the caller (the file browser), which calls openTextureFile().
#pragma once

#include <string>

#include "editor/editor_state.h"
#include "scene/scene.h"

namespace glint {

// The label of `parameter`'s texture button: "Tex", or the kind of texture it has.
const char* textureButtonLabel(const AnalyticMaterial& material, const std::string& parameter);

// `spec` is the table entry, nullptr for the normal map. Returns true when the material changed;
// sets `fileRequest` to the parameter when the user asked for an image file. A typed value
// outside the valid range is refused with a message in `refusal`.
bool drawTextureControls(AnalyticMaterial& material, const std::string& parameter, const ParamSpec* spec,
                         std::string& fileRequest, std::string& refusal);

// Puts the image at `path` on state.textureParameter of material state.textureMaterialIndex as
// one undo step; a file that fails to load leaves the material as it was and shows why.
void openTextureFile(EditorState& state, const std::string& path);

}  // namespace glint
