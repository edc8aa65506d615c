// The plot of the CIE 1931 colour matching functions x̄, ȳ, z̄ (core/colour/cie_cmf.h) over
// 380–780 nm, drawn into any ImGui draw list: the editor's window (View ▸ Colour matching
// functions) and headless overlays. It computes nothing beyond sampling the curves.
#pragma once

#include <imgui.h>

namespace glint {

// Draws axes, wavelength ticks every 50 nm, a visible-spectrum strip and the three curves in the
// rectangle at `topLeft` of `size` (pixels); text uses the current font at `fontSize`.
void drawCmfPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 size, float fontSize);
// Where (wavelength [nm], value) lands in that rectangle, in pixels (tests find the curves by it).
ImVec2 cmfPlotPoint(ImVec2 topLeft, ImVec2 size, float fontSize, float wavelengthNanometres, float value);
// The editor's window around it (state.classroom.showCmfWindow).
void drawCmfWindow(bool& open);

}  // namespace glint
