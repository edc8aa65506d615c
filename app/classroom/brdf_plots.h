// Draws the classroom plots (issue 7) into an ImDrawList, shared by the editor's Plots window and
// `glint render --overlay polar|lobe|albedo|fresnel`: the polar plot, the 3D lobe with the
// transmitted lobe below the surface, directional albedo and the Fresnel plot. Computes nothing
// physical itself (core/classroom) and owns no window.
#pragma once

#include <span>
#include <string>

#include <imgui.h>

#include "classroom/brdf_plot_data.h"
#include "classroom/fresnel_curves.h"

namespace glint {

// One material's plot data at one incidence angle, with the colour it is drawn in.
struct PlottedMaterial {
    PlotMaterial material;
    ImU32 colour = IM_COL32_WHITE;
    PolarPlotData polar;
    LobeMesh lobe;
    DeltaLobes delta;
    AlbedoCurve albedo;
};

// Evaluates every plot's data for `material` at θ_i = incidenceDegrees (the albedo curve is
// the slow part: about 31 × 64 × 128 evaluations).
PlottedMaterial computePlottedMaterial(const PlotMaterial& material, ImU32 colour, float incidenceDegrees);

// The colour of the index-th overlaid material (a fixed palette, readable on the dark background).
ImU32 plotSeriesColour(int index);

// Each draws into [topLeft, bottomRight] on a dark background, with axes, labels and a legend.
// Polar: f_r·cos θ_o (luminance) in the plane of incidence, θ_o from −90° to 90°, and the delta
// lobes of mirror and glass as arrows with their weights (transmission below the surface line).
void drawPolarPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials);
// 3D lobe as a projected wireframe, turned by yaw about the normal and tilted by pitch [rad].
void drawLobePlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials,
                  float yawRadians, float pitchRadians);
// ρ(θ_i) with the 1.0 line, the current incidence marked and a red warning when ρ exceeds 1.
void drawAlbedoPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials);
// R_s, R_p, unpolarised and Schlick per channel, Brewster's and the critical angle marked.
void drawFresnelPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, const FresnelCurves& curves,
                     const std::string& materialName);

}  // namespace glint
