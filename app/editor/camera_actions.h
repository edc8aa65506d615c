// Camera actions, each an undoable edit: orbit/pan/zoom from viewport drags, frame the selected
// object, reset the view, switch perspective/orthographic. The maths is core's OrbitController.
#pragma once

#include "editor/editor_state.h"

namespace glint {

struct ViewportRect {
    float x = 0, y = 0, width = 1, height = 1;  // ImGui pixels, y down
};

// Mouse input over the viewport; returns true while a camera drag is in progress (one undo
// step per drag).
bool handleViewportInput(EditorState& state, const ViewportRect& viewport);
void frameSelected(EditorState& state);
void resetView(EditorState& state);
void toggleProjection(EditorState& state);

}  // namespace glint
