// Editor actions for BRDF Explorer files: open a .brdf into the selected object's material,
// open and save .bparam values, and hot reload of .brdf files that change on disk. Every new or
// changed shader is probed in a child process first (runtime/brdf_probe.h); until it passes, the
// last good version stays on screen. Errors go to the UI; nothing here draws.
#pragma once

#include <string>
#include <vector>

#include "editor/editor_state.h"

namespace glint {

// `values`: the parameters' packed values (empty: the file's defaults); `warnings` about them are
// shown with the file's own.
void openBrdfFile(EditorState& state, const std::string& path, std::vector<float> values = {},
                  const std::vector<Diagnostic>& warnings = {});
// Values for the selected .brdf material; a file naming another .brdf (BRDF Explorer's first line
// `bparam NAME.brdf`) opens that .brdf with them.
void openBparamFile(EditorState& state, const std::string& path);
bool saveBparamTo(EditorState& state, const std::string& path);
// Each frame: takes a finished probe's verdict and looks for changed .brdf files (twice a
// second). Returns the seconds until it wants to look again (large when the scene has none).
double pollCustomBrdfs(EditorState& state, double nowSeconds);

}  // namespace glint
