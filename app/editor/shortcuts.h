// Keyboard shortcuts: the table the help window (F1) and docs/editor.md list, and the handler that
// runs them. Text fields keep their own keys (ImGui's undo inside a field, typing letters).
#pragma once

#include <span>

#include "editor/editor_state.h"

namespace glint {

struct Shortcut {
    const char* keys;
    const char* action;
};

std::span<const Shortcut> allShortcuts();
// Called once per frame after the panels.
void handleShortcuts(EditorState& state);

}  // namespace glint
