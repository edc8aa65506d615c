// `glint render … --overlay polar|lobe|albedo|fresnel [--incidence DEG] [--from-inside]`: the
// classroom plots of the scene's materials over the whole rendered image, drawn with
// app/classroom/brdf_plots.h. They are rows of the one overlay table (cli/render_overlays.h);
// here are their options, the checks on them and the drawing on the canvas.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace CLI {
class App;
}

namespace glint {

enum class PlotOverlayKind { Polar, Lobe, Albedo, Fresnel };

struct PlotOverlayOptions {
    float incidenceDegrees = 45.0f;  // θ_i of the polar plot, the lobe and the albedo marker
    bool incidenceGiven = false;
    bool fromInside = false;         // Fresnel: light inside the material (shows the critical angle)
};

// Adds `--incidence DEG` and `--from-inside` to `command`, into `options` (`--overlay NAME` is the
// overlay table's).
void addPlotOverlayOptions(CLI::App& command, PlotOverlayOptions& options);

// Why the options cannot be used with the plot chosen (`plot`: none chosen when empty) and the
// rest of the command, or "" when they can.
std::string plotOverlayConflict(const PlotOverlayOptions& options, std::optional<PlotOverlayKind> plot, bool reference,
                                const std::string& outputPath);

// The text height [px] of a plot over a width×height image: 1/20 of the shorter side, 13 to 28.
float plotOverlayFontPixels(int width, int height);

// Draws the plot over the whole width×height canvas into ImGui's current (canvas) context, with
// the headless GL context current (.brdf materials are sampled on the GPU). The materials are the
// distinct ones the scene's objects use (at most six; a .brdf whose shader does not compile for
// sampling is left out with a warning on stderr); Fresnel plots the first with an index of refraction.
Status drawPlotOverlay(const Scene& scene, PlotOverlayKind kind, const PlotOverlayOptions& options, int width, int height);

}  // namespace glint
