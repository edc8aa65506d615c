// Light handles in the viewport: a dot per light drawn over the picture (a point or spot light
// at its position; a directional light on the side it shines from, 1.5 m from the camera
// target; ambient lights have none), labelled with the light's name and kind. The selected
// light's dot is larger, ringed in white, its label highlighted; a spot light shows its cone
// (the rim θ_c about its axis) and its aim line. A handle hidden behind an object (a ray from
// the camera meets a surface first) is drawn faint and hollow. Dragging a dot moves a point or
// spot light in the plane facing the camera, or turns the directional light; each drag is one
// undoable edit. Clicking a dot selects the light in the lights panel. Dots grow with the UI scale.
#pragma once

#include <glm/glm.hpp>

#include "editor/camera_actions.h"
#include "editor/editor_state.h"

namespace glint {

// Draws the handles and handles their drags; returns true while a handle is being dragged (the
// camera then ignores the mouse).
bool handleLightHandles(EditorState& state, const ViewportRect& viewport);

// Whether an object hides `point` [m] from the scene's camera: the primary ray towards it meets a
// surface first (the CPU reference's intersection).
bool hiddenFromCamera(const Scene& scene, glm::vec3 point);

// Where a new point or spot light goes [m]: in front of the camera, up and to the right of the
// target, inside the view of any viewport at least as wide as it is tall.
glm::vec3 newLightPosition(const Camera& camera);

}  // namespace glint
