// The editor's Plots window (View ▸ BRDF and Fresnel plots, key B): the classroom plots of the
// selected object's material and of materials pinned to the plot, live with their parameters.
// Holds the window's state and its cache; the drawing itself is app/classroom/brdf_plots.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "classroom/brdf_plots.h"
#include "scene/environment.h"

namespace glint {

struct EditorState;
class BrdfSampler;

struct PlotsWindowState {
    bool open = false;
    float incidenceDegrees = 45.0f;
    bool fresnelFromInside = false;
    float lobeYaw = -0.6f, lobePitch = 0.45f;  // [rad], turned by dragging the lobe
    std::vector<int> pinnedMaterials;          // indices into the scene's materials
    // Cache: recomputed only when a plotted material, the angle or the environment changes.
    std::vector<PlotMaterial> cachedMaterials;
    float cachedIncidence = -1.0f;
    Environment cachedEnvironment;
    std::vector<std::string> environmentNotes;  // per plotted material with an environment term
    bool cachedFromInside = false;
    std::vector<PlottedMaterial> plotted;
    std::optional<FresnelCurves> fresnel;
    std::string fresnelName;
};

// `sampler` evaluates .brdf materials on the GPU, in the editor's GL context (current while ImGui
// builds the frame).
void drawPlotsWindow(EditorState& state, BrdfSampler& sampler);

}  // namespace glint
