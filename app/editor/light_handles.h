// Light handles in the viewport: a dot per light drawn over the picture (a point or spot light
// at its position; a directional light on the side it shines from, 1.5 m from the camera
// target; ambient lights have none). Dragging a dot moves a point or spot light in the plane
// facing the camera, or turns the directional light; each drag is one undoable edit. Clicking a dot selects the light in the lights panel.
#pragma once

#include "editor/camera_actions.h"
#include "editor/editor_state.h"

namespace glint {

// Draws the handles and handles their drags; returns true while a handle is being dragged (the
// camera then ignores the mouse).
bool handleLightHandles(EditorState& state, const ViewportRect& viewport);

}  // namespace glint
