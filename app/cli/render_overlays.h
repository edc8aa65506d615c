// The overlays `glint render --overlay NAME` draws over the rendered PNG: a table of names (add a
// row for a new overlay) and the compositing through the headless ImGui canvas
// (classroom/overlay_canvas.h). It does not render the scene or parse the command line.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "classroom/surface_probe.h"
#include "image/image.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// What an overlay may draw from: the scene, the image's size, the probe (--probe X,Y) if given.
struct RenderOverlayInput {
    const Scene& scene;
    int width, height;
    const std::optional<ProbeResult>& probe;
};

struct RenderOverlay {
    const char* name;      // as typed after --overlay
    const char* help;      // one line for the usage text
    bool needsProbePoint;  // refused without --probe X,Y
    // Draws into ImGui's current (canvas) context, e.g. ImGui::GetBackgroundDrawList().
    void (*draw)(const RenderOverlayInput& input);
};

std::span<const RenderOverlay> allRenderOverlays();
const RenderOverlay* findRenderOverlay(std::string_view name);

// Draws the overlays, in order, over `under` (width×height) on a canvas in the GL context current
// now (HeadlessRenderer's), and returns the composite.
Result<DisplayImage> drawRenderOverlays(std::span<const RenderOverlay* const> overlays, const RenderOverlayInput& input,
                                        const DisplayImage& under);

}  // namespace glint
