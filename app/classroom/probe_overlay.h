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

void drawProbeOverlay(ImDrawList* drawList, const ProbeResult& probe, const Camera& camera, const ProbeOverlayArea& area);

}  // namespace glint
