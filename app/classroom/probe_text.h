// The surface probe's numbers as text: the shading equation with the numbers filled in, one line
// per step, and the whole chain as a plain-text report (`glint render --probe`). Formatting only:
// the numbers come from classroom/surface_probe.h.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "classroom/surface_probe.h"

namespace glint {

// A number with 3 decimals (fewer for large values, scientific for tiny or huge ones).
std::string formatProbeNumber(float value);
// An RGB quantity: one number when the channels are equal, else "(r, g, b)".
std::string formatProbeRgb(glm::vec3 value);

// One light's chain: E⊥ from the source, E = E⊥·cos θ, then L_i = f_r·E, filled in.
std::vector<std::string> probeLightEquation(const ProbeLight& light);
// The total: L = Σ f_r·E (+ k_a·L_a, environment, traced delta lobes) with the numbers.
std::string probeTotalEquation(const ProbeResult& result);
// The environment term's approximation, its value and its error against the Monte-Carlo integral
// (kProbeEnvironmentSamples samples): the probe's line and the plots' note say it alike.
std::string environmentAccuracyText(const std::string& method, glm::vec3 preview, glm::vec3 truth);
// That text at the probed point; empty when there is no environment term.
std::string probeEnvironmentLine(const ProbeResult& result);
// Radiance → exposure → tone map → clamp → encoding → 8-bit, per channel (one line when equal).
std::vector<std::string> probeDisplayEquation(const ProbeResult& result);

// Everything, as printed by `glint render --probe X,Y`.
std::string probeReport(const ProbeResult& result);

}  // namespace glint
