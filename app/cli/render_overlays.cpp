// The overlays of `glint render --overlay` (see render_overlays.h).
#include "cli/render_overlays.h"

#include <imgui.h>

#include <algorithm>

#include "classroom/cmf_plot.h"
#include "classroom/overlay_canvas.h"
#include "classroom/probe_overlay.h"

namespace glint {
namespace {

constexpr float kRenderOverlayFontPixels = 13.0f;

Status drawProbeRenderOverlay(const RenderOverlayInput& input) {
    drawProbeOverlay(ImGui::GetBackgroundDrawList(), *input.probe, input.scene.camera,
                     {0.0f, 0.0f, static_cast<float>(input.width), static_cast<float>(input.height)});
    return success();
}

// The CIE 1931 matching functions over the whole image, as `glint cmf` draws them.
Status drawCmfRenderOverlay(const RenderOverlayInput& input) {
    drawCmfPlot(ImGui::GetBackgroundDrawList(), ImVec2(0.0f, 0.0f),
                ImVec2(static_cast<float>(input.width), static_cast<float>(input.height)), kRenderOverlayFontPixels);
    return success();
}

// The classroom plots (cli/plot_overlay.h), one row each.
template <PlotOverlayKind kind>
Status drawPlotRenderOverlay(const RenderOverlayInput& input) {
    return drawPlotOverlay(input.scene, kind, input.plots, input.width, input.height);
}

constexpr RenderOverlay kRenderOverlays[] = {
    {"probe", "the surface probe at --probe X,Y: N, V, and per light L, H, R (T for glass) with their angles", true,
     std::nullopt, drawProbeRenderOverlay},
    {"cmf", "the CIE 1931 colour matching functions x̄, ȳ, z̄ over 380–780 nm (as `glint cmf`)", false, std::nullopt,
     drawCmfRenderOverlay},
    {"polar", "the polar plot of f_r·cos θ_o in the plane of incidence (θ_i: --incidence DEG, default 45)", false,
     PlotOverlayKind::Polar, drawPlotRenderOverlay<PlotOverlayKind::Polar>},
    {"lobe", "the 3D lobe of f_r·cos θ_o over the hemisphere (θ_i: --incidence DEG)", false, PlotOverlayKind::Lobe,
     drawPlotRenderOverlay<PlotOverlayKind::Lobe>},
    {"albedo", "directional albedo ρ(θ_i) of the scene's materials", false, PlotOverlayKind::Albedo,
     drawPlotRenderOverlay<PlotOverlayKind::Albedo>},
    {"fresnel", "the Fresnel curves of the first material with an index (--from-inside: light inside)", false,
     PlotOverlayKind::Fresnel, drawPlotRenderOverlay<PlotOverlayKind::Fresnel>},
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
    // One font for the fixed-size overlays and, when it differs, a second for the plots.
    std::vector<float> fontPixels = {kRenderOverlayFontPixels};
    const float plotFontPixels = plotOverlayFontPixels(input.width, input.height);
    const bool anyPlot = std::any_of(overlays.begin(), overlays.end(), [](const RenderOverlay* overlay) { return overlay->plot.has_value(); });
    if (anyPlot && plotFontPixels != kRenderOverlayFontPixels) fontPixels.push_back(plotFontPixels);
    auto canvas = OverlayCanvas::create(fontPixels);
    if (!canvas) return canvas.error();
    (*canvas)->begin(input.width, input.height);
    Status drawn = success();
    for (const RenderOverlay* overlay : overlays) {
        if (!drawn) break;
        ImGui::PushFont((*canvas)->font(overlay->plot ? fontPixels.size() - 1 : 0));
        drawn = overlay->draw(input);
        ImGui::PopFont();
    }
    auto composite = (*canvas)->finish(under);  // the frame ends either way
    if (!drawn) return drawn.error();
    return composite;
}

}  // namespace glint
