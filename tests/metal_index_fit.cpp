// Fitting per-channel (n, κ) to a metal's integrated reflectance (see metal_index_fit.h).
#include "metal_index_fit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "brdf/fresnel.h"
#include "math/constants.h"
#include "reflectance_colour.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

using ChannelCurve = std::array<float, kIndexFitAngleCount>;

constexpr int kScanSteps = 200;          // points of the scan over log n
constexpr int kGoldenSectionSteps = 60;  // each shrinks the bracket by 0.618

float fitAngleCosine(int index) { return static_cast<float>(std::cos(index * kPi / 180.0)); }

// κ on the family of constant F0 (inverting F0 = ((n−1)² + κ²)/((n+1)² + κ²)); 0 at its ends.
double extinctionForF0(double n, double f0) {
    const double square = ((n + 1.0) * (n + 1.0) * f0 - (n - 1.0) * (n - 1.0)) / (1.0 - f0);
    return std::sqrt(std::max(square, 0.0));
}

// Σ over the fit's angles of (conductor Fresnel of (n, κ(n)) − target)², in double: smooth in n,
// so the search below converges to the same minimum whatever the last bits of the target.
double curveError(double n, double f0, const ChannelCurve& target) {
    const double k = extinctionForF0(n, f0);
    double sum = 0.0;
    for (int angle = 0; angle < kIndexFitAngleCount; ++angle) {
        const auto [s, p] = fresnelConductorSP(static_cast<double>(fitAngleCosine(angle)), n, k);
        const double difference = 0.5 * (s + p) - target[angle];
        sum += difference * difference;
    }
    return sum;
}

// The best (n, κ) of the constant-F0 family for one channel with 0 < F0 < 1.
glm::vec2 fitChannel(const ChannelCurve& target) {
    const double f0 = target[0];
    const double root = std::sqrt(f0);
    const double lowest = (1.0 - root) / (1.0 + root), highest = (1.0 + root) / (1.0 - root);
    const auto indexAt = [&](double u) { return lowest * std::pow(highest / lowest, u); };  // u ∈ [0, 1]
    const auto errorAt = [&](double u) { return curveError(indexAt(u), f0, target); };
    int best = 0;
    double bestError = errorAt(0.0);
    for (int step = 1; step <= kScanSteps; ++step) {
        const double error = errorAt(static_cast<double>(step) / kScanSteps);
        if (error < bestError) bestError = error, best = step;
    }
    // Golden-section search on the scan interval either side of the best point.
    const double shrink = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = std::max(best - 1, 0) / static_cast<double>(kScanSteps);
    double b = std::min(best + 1, kScanSteps) / static_cast<double>(kScanSteps);
    double c = b - shrink * (b - a), d = a + shrink * (b - a);
    double errorC = errorAt(c), errorD = errorAt(d);
    for (int step = 0; step < kGoldenSectionSteps; ++step) {
        if (errorC < errorD) {
            b = d, d = c, errorD = errorC;
            c = b - shrink * (b - a), errorC = errorAt(c);
        } else {
            a = c, c = d, errorC = errorD;
            d = a + shrink * (b - a), errorD = errorAt(d);
        }
    }
    const float n = static_cast<float>(indexAt(0.5 * (a + b)));
    return {n, static_cast<float>(extinctionForF0(n, f0))};
}

// The colorimetric wavelength [nm] that channel `channel` responds to most.
float mostSensitiveWavelength(int channel) {
    int best = 0;
    for (int index = 1; index < kColorimetryWavelengthCount; ++index)
        if (srgbReflectanceWeight(index)[channel] > srgbReflectanceWeight(best)[channel]) best = index;
    return colorimetryWavelength(best);
}

}  // namespace

ChannelIndices fitMetalIndices(const MetalSpectrum& spectrum) {
    std::array<ChannelCurve, 3> curves;
    for (int angle = 0; angle < kIndexFitAngleCount; ++angle) {
        const glm::vec3 reflectance = metalReflectance(spectrum, fitAngleCosine(angle));
        for (int channel = 0; channel < 3; ++channel) curves[channel][angle] = reflectance[channel];
    }
    ChannelIndices indices;
    for (int channel = 0; channel < 3; ++channel) {
        const float f0 = curves[channel][0];
        GLINT_CHECK(f0 > 0.0f && "a metal reflects in every channel");
        const glm::vec2 index = f0 < 1.0f ? fitChannel(curves[channel])
                                          : glm::vec2(kLosslessIndex, complexIndexAt(spectrum, mostSensitiveWavelength(channel)).y);
        indices.n[channel] = index.x;
        indices.k[channel] = index.y;
    }
    return indices;
}

}  // namespace glint
