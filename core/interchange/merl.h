// MERL measured isotropic BRDFs (.binary, Matusik et al., "A Data-Driven Reflectance Model",
// SIGGRAPH 2003): loading with a validated header and size, and evaluating the table at a pair of
// directions by the standard nearest-bin lookup or trilinearly. It does not fit or resample data.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "math/frame.h"
#include "util/diagnostic.h"

namespace glint {

// The table's resolution in (θ_h, θ_d, φ_d): fixed by the format.
inline constexpr int kMerlThetaHalfBins = 90, kMerlThetaDifferenceBins = 90, kMerlPhiDifferenceBins = 180;
inline constexpr size_t kMerlSamplesPerChannel = size_t(kMerlThetaHalfBins) * kMerlThetaDifferenceBins * kMerlPhiDifferenceBins;
inline constexpr size_t kMerlFileBytes = 3 * sizeof(int32_t) + 3 * kMerlSamplesPerChannel * sizeof(double);
// Per-channel scale from stored values to f_r [1/sr] (the reference code's RED/GREEN/BLUE_SCALE).
inline constexpr double kMerlChannelScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct MerlTable {
    // f_r [1/sr], scaled, as float; index (channel · θ_h · θ_d · φ_d), φ_d fastest.
    std::vector<float> reflectance;
    size_t negativeSamples = 0;  // stored values below 0: "no measurement", read as 0

    glm::vec3 at(int thetaHalf, int thetaDifference, int phiDifference) const;
};

// Parses the bytes of a .binary file; `file` names it in messages. Refuses other dimensions,
// a size that does not match them, truncation, NaN and infinity (with the sample's index).
Result<MerlTable> parseMerl(std::string_view bytes, const std::string& file);
Result<MerlTable> loadMerl(const std::string& path);

// The table's coordinates of a direction pair (Rusinkiewicz, "A New Change of Variables for
// Efficient BRDF Representation", EGWR 1998): θ_h, θ_d ∈ [0, π/2], φ_d ∈ [0, π) folded by reciprocity.
struct HalfDifference {
    float thetaHalf, thetaDifference, phiDifference;
};
HalfDifference toHalfDifference(glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame);

// Continuous bin coordinates: θ_h index = 90·√(θ_h/(π/2)), θ_d index = 90·θ_d/(π/2), φ_d index = 180·φ_d/π.
glm::vec3 merlBinCoordinates(const HalfDifference& angles);

// f_r [1/sr] per channel: the reference code's nearest-bin lookup (floor of each index)...
glm::vec3 lookupMerlNearest(const MerlTable& table, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame);
// ...and trilinear interpolation between the 8 surrounding samples (φ_d wraps around). Both are
// 0 below either horizon.
glm::vec3 lookupMerlTrilinear(const MerlTable& table, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame);

// Writes a MERL file whose every sample is `reflectance` [1/sr] per channel (e.g. ρ/π for a
// Lambertian surface), for tests and examples.
std::string makeConstantMerl(glm::vec3 reflectance);

}  // namespace glint
