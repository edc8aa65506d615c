// The editor's surface probe tool: Shift+click (or I, then click) on the viewport sets the probe
// point; the viewport then shows the probe's arrows (app/classroom/probe_overlay.h) and a
// "Surface probe" window shows the chain from each light to the pixel, recomputed only when the scene
// or the point changes. The numbers come from core/classroom/surface_probe.h.
#pragma once

#include <optional>

#include "editor/camera_actions.h"
#include "editor/editor_state.h"

namespace glint {

// The I key and the View menu: off when on; else armed, waiting for a click on the viewport.
void toggleProbeTool();
// Shows the probe at a point of the viewport given as fractions of its size (0..1, y down): a lesson's point.
void showProbeAt(glm::vec2 fractionOfViewport);
// Whether the probe is on (armed or showing a point), for the View menu's check mark.
bool probeToolOn();
// A Shift+click (or an armed click) on the viewport sets the point. Returns true when it took
// the click, so the camera does not start a drag with it.
bool handleProbeClick(const ViewportRect& viewport);
// The arrows over the viewport and the numbers in their window, when a point is set.
void drawProbe(const EditorState& state, const ViewportRect& viewport);
// θ_i of the first light that reaches the probed surface point (the Plots window follows it);
// nothing while the probe is off, saw no surface or no light reaches the point.
std::optional<float> probedIncidenceDegrees();

}  // namespace glint
