// The overlays `glint render --overlay NAME` draws over the rendered PNG: a table of names (add a
// row for a new overlay; the classroom plots of cli/plot_overlay.h are rows too) and the
// compositing of all of them on one headless ImGui canvas (classroom/overlay_canvas.h). It does
// not render the scene or parse the command line.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "classroom/surface_probe.h"
#include "cli/plot_overlay.h"
#include "image/image.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// What an overlay may draw from: the scene, the image's size, the probe (--probe X,Y) if given,
// the plot options (--incidence, --from-inside).
struct RenderOverlayInput {
    const Scene& scene;
    int width, height;
    const std::optional<ProbeResult>& probe;
    PlotOverlayOptions plots = {};  // defaults when no plot is drawn
};

struct RenderOverlay {
    const char* name;      // as typed after --overlay
    const char* help;      // its line in `glint render --help`
    bool needsProbePoint;  // refused without --probe X,Y
    // A classroom plot: it covers the whole image (one per image), its text grows with the image
    // (plotOverlayFontPixels) and it takes the plot options.
    std::optional<PlotOverlayKind> plot;
    // Draws into ImGui's current (canvas) context, e.g. ImGui::GetBackgroundDrawList(); an error
    // (nothing to plot) fails the render.
    Status (*draw)(const RenderOverlayInput& input);
};

std::span<const RenderOverlay> allRenderOverlays();
const RenderOverlay* findRenderOverlay(std::string_view name);

// Draws the overlays, in order, over `under` (width×height) on one canvas in the GL context
// current now (HeadlessRenderer's), and returns the composite or the first overlay's error.
Result<DisplayImage> drawRenderOverlays(std::span<const RenderOverlay* const> overlays, const RenderOverlayInput& input,
                                        const DisplayImage& under);

}  // namespace glint
