// `glint render … --overlay polar|lobe|albedo|fresnel [--incidence DEG] [--from-inside]`: the
// classroom plots of the scene's materials drawn over the rendered image (app/classroom/brdf_plots.h
// on the headless overlay canvas). Option parsing lives here so render_command.cpp only hooks it in.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

enum class PlotOverlayKind { None, Polar, Lobe, Albedo, Fresnel };

struct PlotOverlayOptions {
    PlotOverlayKind kind = PlotOverlayKind::None;
    float incidenceDegrees = 45.0f;  // θ_i of the polar plot, the lobe and the albedo marker
    bool incidenceGiven = false;
    bool fromInside = false;         // Fresnel: light inside the material (shows the critical angle)
};

// What parsePlotOverlayOption made of arguments[i].
enum class PlotOptionMatch { NotMine, Taken, Error };

// Takes `--overlay polar|lobe|albedo|fresnel`, `--incidence DEG` and `--from-inside` (advancing i
// past a value); any other argument, `--overlay probe` included, is NotMine. On Error, `error` says why.
PlotOptionMatch parsePlotOverlayOption(const std::vector<std::string>& arguments, size_t& i,
                                       PlotOverlayOptions& options, std::string& error);

// Why the options cannot be used together with the rest of the command, or "" when they can.
std::string plotOverlayConflict(const PlotOverlayOptions& options, bool reference, const std::string& outputPath);

// Draws the plot over `image` (needs the headless GL context current). The materials are the
// distinct ones the scene's objects use (at most six, .brdf materials left out with a warning on
// stderr); Fresnel plots the first with an index of refraction.
Status drawPlotOverlay(const Scene& scene, const PlotOverlayOptions& options, DisplayImage& image);

}  // namespace glint
