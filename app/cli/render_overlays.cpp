// The overlays of `glint render --overlay` (see render_overlays.h).
#include "cli/render_overlays.h"

#include <imgui.h>

#include "classroom/cmf_plot.h"
#include "classroom/overlay_canvas.h"
#include "classroom/probe_overlay.h"

namespace glint {
namespace {

constexpr float kRenderOverlayFontPixels = 13.0f;

void drawProbeRenderOverlay(const RenderOverlayInput& input) {
    drawProbeOverlay(ImGui::GetBackgroundDrawList(), *input.probe, input.scene.camera,
                     {0.0f, 0.0f, static_cast<float>(input.width), static_cast<float>(input.height)});
}

// The CIE 1931 matching functions over the whole image, as `glint cmf` draws them.
void drawCmfRenderOverlay(const RenderOverlayInput& input) {
    drawCmfPlot(ImGui::GetBackgroundDrawList(), ImVec2(0.0f, 0.0f),
                ImVec2(static_cast<float>(input.width), static_cast<float>(input.height)), kRenderOverlayFontPixels);
}

constexpr RenderOverlay kRenderOverlays[] = {
    {"probe", "the surface probe at --probe X,Y: N, V, and per light L, H, R (T for glass) with their angles", true,
     drawProbeRenderOverlay},
    {"cmf", "the CIE 1931 colour matching functions x̄, ȳ, z̄ over 380–780 nm (as `glint cmf`)", false, drawCmfRenderOverlay},
};

}  // namespace

std::span<const RenderOverlay> allRenderOverlays() { return kRenderOverlays; }

const RenderOverlay* findRenderOverlay(std::string_view name) {
    for (const RenderOverlay& overlay : kRenderOverlays)
        if (name == overlay.name) return &overlay;
    return nullptr;
}

Result<DisplayImage> drawRenderOverlays(std::span<const RenderOverlay* const> overlays, const RenderOverlayInput& input,
                                        const DisplayImage& under) {
    auto canvas = OverlayCanvas::create(kRenderOverlayFontPixels);
    if (!canvas) return canvas.error();
    (*canvas)->begin(input.width, input.height);
    for (const RenderOverlay* overlay : overlays) overlay->draw(input);
    return (*canvas)->finish(under);
}

}  // namespace glint
