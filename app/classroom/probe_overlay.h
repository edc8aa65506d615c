// Draws the surface probe over an image of the scene: N, V and, per light, L, H, R (and T for
// refractive materials) as labelled arrows from the probed point with their angles, projected
// with the scene's camera. Shared by the editor's viewport and `glint render --overlay probe`;
// it computes nothing (classroom/surface_probe.h does) and owns no ImGui context.
#pragma once

#include "camera/camera.h"
#include "classroom/surface_probe.h"

struct ImDrawList;

namespace glint {

// Where the probed image lies in the draw list's coordinates (ImGui pixels, y down).
struct ProbeOverlayArea {
    float x = 0, y = 0, width = 1, height = 1;
};

// Where the legend of angles goes: the CLI's pictures keep it top left; the editor puts it bottom
// left, clear of the lesson note.
enum class ProbeLegendCorner { TopLeft, BottomLeft };

// What the overlay covers, for the editor to keep windows off it: the legend (the angle readout)
// and the box around the arrows and their labels; both empty when the ray sees no surface.
struct ProbeOverlayRects {
    ProbeOverlayArea legend{0, 0, 0, 0};
    ProbeOverlayArea arrows{0, 0, 0, 0};
};

// Arrows, line widths and labels scale with the current font (thick in presentation mode); each
// label takes a spot near its arrow's tip that overlaps no other label nor the legend.
ProbeOverlayRects drawProbeOverlay(ImDrawList* drawList, const ProbeResult& probe, const Camera& camera,
                                   const ProbeOverlayArea& area, ProbeLegendCorner corner = ProbeLegendCorner::TopLeft);

}  // namespace glint
