// Luminance importance sampling of an equirect (see environment_distribution.h).
#include "environment/environment_distribution.h"

#include <algorithm>
#include <cmath>

#include "light/photometry.h"
#include "math/constants.h"

namespace glint {
namespace {

// Index i with cdf[i] ≤ u < cdf[i + 1] in a non-decreasing table that starts at 0 and ends at 1,
// skipping empty intervals.
int findInterval(const float* cdf, int count, float u) {
    const float* upper = std::upper_bound(cdf + 1, cdf + count + 1, u);
    return std::clamp(static_cast<int>(upper - cdf) - 1, 0, count - 1);
}

// The mean luminance over texel (x, y) of the bilinearly interpolated image (the radiance the
// integrand sees): per axis 1/8 of each neighbour and 3/4 of the texel itself (wrapping in x,
// clamped in y). Drawing in proportion to it keeps a bright texel's bilinear skirt in the
// neighbours from being drawn rarely.
float bilinearMeanLuminance(const EquirectImage& radiance, int x, int y) {
    constexpr float kWeights[3] = {0.125f, 0.75f, 0.125f};
    float sum = 0.0f;
    for (int j = -1; j <= 1; ++j) {
        const int row = std::clamp(y + j, 0, radiance.height - 1);
        for (int i = -1; i <= 1; ++i) {
            const int column = (x + i + radiance.width) % radiance.width;
            sum += kWeights[i + 1] * kWeights[j + 1] * relativeLuminance(radiance.at(column, row));
        }
    }
    return std::max(0.0f, sum);
}

}  // namespace

EnvironmentDistribution::EnvironmentDistribution(const EquirectImage& radiance)
    : width_(radiance.width), height_(radiance.height) {
    std::vector<double> weights(static_cast<size_t>(width_) * height_);
    double total = 0.0;
    for (int y = 0; y < height_; ++y) {
        const double solidAngle = texelSolidAngle(y, width_, height_);
        for (int x = 0; x < width_; ++x) {
            const double weight = bilinearMeanLuminance(radiance, x, y) * solidAngle;
            weights[static_cast<size_t>(y) * width_ + x] = weight;
            total += weight;
        }
    }
    // A black map: uniform over solid angle, so that sampling still has a density.
    if (!(total > 0.0)) {
        total = 0.0;
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) total += weights[static_cast<size_t>(y) * width_ + x] = texelSolidAngle(y, width_, height_);
    }
    texelProbability_.resize(weights.size());
    rowCdf_.assign(height_ + 1, 0.0f);
    columnCdf_.assign(static_cast<size_t>(height_) * (width_ + 1), 0.0f);
    double rowSum = 0.0;
    for (int y = 0; y < height_; ++y) {
        double columnSum = 0.0;
        float* columns = &columnCdf_[static_cast<size_t>(y) * (width_ + 1)];
        for (int x = 0; x < width_; ++x) {
            const double weight = weights[static_cast<size_t>(y) * width_ + x];
            texelProbability_[static_cast<size_t>(y) * width_ + x] = static_cast<float>(weight / total);
            columnSum += weight;
            columns[x + 1] = static_cast<float>(columnSum);
        }
        for (int x = 1; x <= width_; ++x) columns[x] = columnSum > 0.0 ? columns[x] / static_cast<float>(columnSum) : 1.0f;
        columns[width_] = 1.0f;
        rowSum += columnSum;
        rowCdf_[y + 1] = static_cast<float>(rowSum / total);
    }
    rowCdf_[height_] = 1.0f;
}

EnvironmentDirectionSample EnvironmentDistribution::sample(glm::vec2 u) const {
    const int y = findInterval(rowCdf_.data(), height_, u.y);
    const float* columns = &columnCdf_[static_cast<size_t>(y) * (width_ + 1)];
    const int x = findInterval(columns, width_, u.x);
    // The position within the texel: what is left of each coordinate, rescaled to [0,1).
    const float rowWidth = rowCdf_[y + 1] - rowCdf_[y], columnWidth = columns[x + 1] - columns[x];
    const float fy = rowWidth > 0.0f ? std::clamp((u.y - rowCdf_[y]) / rowWidth, 0.0f, 0.99999f) : 0.5f;
    const float fx = columnWidth > 0.0f ? std::clamp((u.x - columns[x]) / columnWidth, 0.0f, 0.99999f) : 0.5f;
    const glm::vec2 coordinates{(x + fx) / width_, (y + fy) / height_};
    const glm::vec3 direction = equirectDirection(coordinates);
    const float sinTheta = std::sin(kPi * coordinates.y);
    const float density = texelProbability_[static_cast<size_t>(y) * width_ + x] * width_ * height_;
    return {direction, sinTheta > 0.0f ? density / (2.0f * kPi * kPi * sinTheta) : 0.0f};
}

float EnvironmentDistribution::pdf(glm::vec3 direction) const {
    const glm::vec2 coordinates = equirectCoordinates(direction);
    const int x = std::clamp(static_cast<int>(coordinates.x * width_), 0, width_ - 1);
    const int y = std::clamp(static_cast<int>(coordinates.y * height_), 0, height_ - 1);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - direction.y * direction.y));
    const float density = texelProbability_[static_cast<size_t>(y) * width_ + x] * width_ * height_;
    return sinTheta > 0.0f ? density / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

}  // namespace glint
