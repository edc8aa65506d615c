// Scene materials as the classroom plots see them, shared by the editor's Plots window and
// `glint render --overlay polar|lobe|albedo`: built-in models and MERL tables evaluated on the CPU
// (app/classroom/brdf_plot_data.h), .brdf shaders sampled on the GPU (core/gl/brdf_sampler.h)
// in the GL context current when the plots are computed. Draws nothing.
#pragma once

#include <string>

#include "classroom/brdf_plot_data.h"
#include "gl/brdf_sampler.h"

namespace glint {

// The plot material of `material`. A .brdf material's sampling program is compiled first; its
// compile error (located in the .brdf) is the error. Its sampler uses `sampler`, which must
// outlive the returned material; give it only .brdf shaders that passed the safety probe.
Result<PlotMaterial> plotMaterialFor(const Material& material, BrdfSampler& sampler);

// Where a plotted material's f_r comes from when it is not a built-in model's formula, for a
// note beside the plots: the GPU for a .brdf shader, the measured table for MERL; "" otherwise.
std::string plotSourceNote(const PlotMaterial& material);

}  // namespace glint
