// The CPU reference's hook for measured (MERL) materials: ambient reflectance and environment
// light of a material that carries a table, in place of its model's (f_r: evalMeasuredBrdf). It does not
// shade analytic models (reference_renderer.cpp calls evalBrdf and the environment code for those).
#pragma once

#include <glm/glm.hpp>

#include "interchange/measured_brdf.h"
#include "math/frame.h"
#include "scene/environment.h"

namespace glint {

// Ambient: uniform radiance L_a from every direction reflects as ρ(θ_o)·L_a, exactly.
glm::vec3 measuredAmbientReflectance(const MeasuredBrdf& brdf, glm::vec3 wo, const ShadingFrame& frame);

// Environment light, approximated as for a diffuse surface with the measured directional
// albedo: ρ(θ_o)·E(n)/π (irradiance map). Exact for a Lambertian table; for a glossy one it
// loses the reflection of the environment's detail. The GPU does the same (merl.glsl).
glm::vec3 measuredEnvironmentLighting(const MeasuredBrdf& brdf, glm::vec3 wo, const ShadingFrame& frame,
                                      const Environment& environment);

}  // namespace glint
