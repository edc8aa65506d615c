// Precomputed image-based lighting (see environment_map.h).
// Sections: parallel rows · spherical harmonics · GGX prefiltering · split-sum table · lookups.
#include "environment/environment_map.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "brdf/microfacet.h"
#include "environment/ggx_sampling.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {
namespace {

// --- parallel rows --------------------------------------------------------------------------

template <class RowFunction>
void forEachRow(int rows, RowFunction&& row) {
    const int threadCount = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    auto work = [&](int first) {
        for (int y = first; y < rows; y += threadCount) row(y);
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < threadCount; ++t) threads.emplace_back(work, t);
    work(0);
    for (std::thread& thread : threads) thread.join();
}

// --- spherical harmonics --------------------------------------------------------------------

// The real SH basis up to l = 2 at a unit direction (Ramamoorthi & Hanrahan 2001, eq. 3).
std::array<float, 9> shBasis(glm::vec3 d) {
    return {0.282095f,
            0.488603f * d.y, 0.488603f * d.z, 0.488603f * d.x,
            1.092548f * d.x * d.y, 1.092548f * d.y * d.z, 0.315392f * (3.0f * d.z * d.z - 1.0f),
            1.092548f * d.x * d.z, 0.546274f * (d.x * d.x - d.y * d.y)};
}

// L_lm = Σ L(texel) ∫_texel Y_lm dω, each texel's integral taken over `strips` strips in θ with
// their exact solid angles (the basis varies along θ within a tall texel; along φ the column
// centres already integrate sin and cos of φ and 2φ exactly). Enough strips that a texel is at most
// 1/256 of π high: a uniform map then projects to L_00 alone within 1e-5.
std::array<glm::vec3, 9> projectSh(const EquirectImage& image) {
    std::array<glm::vec3, 9> coefficients{};
    const int strips = std::clamp(256 / image.height, 1, 64);
    for (int y = 0; y < image.height; ++y) {
        for (int strip = 0; strip < strips; ++strip) {
            const float top = kPi * (y + static_cast<float>(strip) / strips) / image.height;
            const float bottom = kPi * (y + static_cast<float>(strip + 1) / strips) / image.height;
            const float solidAngle = 2.0f * kPi / image.width * (std::cos(top) - std::cos(bottom));
            const float v = 0.5f * (top + bottom) * kInvPi;
            for (int x = 0; x < image.width; ++x) {
                const std::array<float, 9> basis = shBasis(equirectDirection({(x + 0.5f) / image.width, v}));
                for (int i = 0; i < 9; ++i) coefficients[i] += image.at(x, y) * (basis[i] * solidAngle);
            }
        }
    }
    return coefficients;
}

// --- GGX prefiltering -----------------------------------------------------------------------

// Trilinear lookup in a mip pyramid (level 0 the full image) at a fractional level.
glm::vec3 samplePyramid(const std::vector<EquirectImage>& pyramid, glm::vec3 direction, float level) {
    level = std::clamp(level, 0.0f, static_cast<float>(pyramid.size() - 1));
    const int lower = static_cast<int>(level);
    const int upper = std::min(lower + 1, static_cast<int>(pyramid.size()) - 1);
    const float t = level - lower;
    return sampleEquirect(pyramid[lower], direction) * (1.0f - t) + sampleEquirect(pyramid[upper], direction) * t;
}

// One prefiltered level: for each texel direction R (taking n = v = R, Karis 2013), the mean of
// the radiance over GGX-sampled light directions weighted by cos θ_i; each sample reads the
// pyramid level whose texels match the sample's solid angle (Colbert & Křivánek, "GPU-Based
// Importance Sampling", GPU Gems 3, ch. 20).
EquirectImage prefilterLevel(const std::vector<EquirectImage>& pyramid, float alpha) {
    EquirectImage level(kPrefilteredWidth, kPrefilteredHeight);
    const float texelSolidAngleMean = 4.0f * kPi / (pyramid[0].width * pyramid[0].height);
    forEachRow(level.height, [&](int y) {
        for (int x = 0; x < level.width; ++x) {
            const glm::vec3 mirror = equirectDirection({(x + 0.5f) / level.width, (y + 0.5f) / level.height});
            const ShadingFrame frame = ShadingFrame::fromNormal(mirror);
            glm::vec3 sum(0.0f);
            float weightSum = 0.0f;
            for (int i = 0; i < kPrefilterSamples; ++i) {
                const glm::vec3 halfLocal = sampleGgxHalfVector(hammersley(i, kPrefilterSamples), alpha);
                const glm::vec3 lightLocal = 2.0f * halfLocal.z * halfLocal - glm::vec3(0, 0, 1);
                if (lightLocal.z <= 0.0f) continue;
                // pdf of the light direction with n = v: D(h) cos θ_h / (4 v·h) = D(h)/4.
                const float sin2Half = std::max(0.0f, 1.0f - halfLocal.z * halfLocal.z);
                const float pdf = distributionGgx(halfLocal.z, sin2Half, alpha) * 0.25f;
                const float sampleSolidAngle = 1.0f / (kPrefilterSamples * pdf);
                const float pyramidLevel = 0.5f * std::log2(sampleSolidAngle / texelSolidAngleMean) + 1.0f;
                sum += samplePyramid(pyramid, frame.toWorld(lightLocal), pyramidLevel) * lightLocal.z;
                weightSum += lightLocal.z;
            }
            level.at(x, y) = sum / weightSum;
        }
    });
    return level;
}

}  // namespace

// --- making a map ---------------------------------------------------------------------------

std::shared_ptr<const EnvironmentMap> makeEnvironmentMap(EquirectImage radiance) {
    auto map = std::make_shared<EnvironmentMap>();
    map->irradianceSh = projectSh(radiance);
    std::vector<EquirectImage> pyramid{radiance};
    while (pyramid.back().width > 8 && pyramid.back().height > 4) pyramid.push_back(downsampleEquirect(pyramid.back()));
    for (int k = 1; k <= kPrefilteredLevels; ++k) {
        const float perceptual = static_cast<float>(k) / kPrefilteredLevels;
        map->prefiltered.push_back(prefilterLevel(pyramid, perceptual * perceptual));
    }
    map->radiance = std::move(radiance);
    return map;
}

// --- split-sum table ------------------------------------------------------------------------

const SplitSumLut& splitSumLut() {
    static const SplitSumLut lut = [] {
        constexpr int kSamples = 1024;
        SplitSumLut table;
        table.texels.resize(kSplitSumLutSize * kSplitSumLutSize);
        for (int row = 0; row < kSplitSumLutSize; ++row) {
            const float perceptual = (row + 0.5f) / kSplitSumLutSize;
            const float alpha = perceptual * perceptual;
            for (int column = 0; column < kSplitSumLutSize; ++column) {
                const float cosOut = (column + 0.5f) / kSplitSumLutSize;
                const glm::vec3 view{std::sqrt(1.0f - cosOut * cosOut), 0.0f, cosOut};
                glm::vec2 sum(0.0f);
                for (int i = 0; i < kSamples; ++i) {
                    const glm::vec3 halfway = sampleGgxHalfVector(hammersley(i, kSamples), alpha);
                    const float viewDotHalf = glm::dot(view, halfway);
                    const glm::vec3 light = 2.0f * viewDotHalf * halfway - view;
                    if (light.z <= 0.0f || viewDotHalf <= 0.0f) continue;
                    // f_r cos θ_i / pdf = G2 (v·h) / (cos θ_o cos θ_h) for pdf = D cos θ_h / (4 v·h).
                    const float geometry = smithHeightCorrelated(lambdaGgx(light.z, alpha), lambdaGgx(cosOut, alpha));
                    const float weight = geometry * viewDotHalf / (cosOut * halfway.z);
                    const float schlick = std::pow(1.0f - viewDotHalf, 5.0f);
                    sum += glm::vec2((1.0f - schlick) * weight, schlick * weight);
                }
                table.texels[row * kSplitSumLutSize + column] = sum / static_cast<float>(kSamples);
            }
        }
        return table;
    }();
    return lut;
}

// --- lookups --------------------------------------------------------------------------------

glm::vec2 sampleSplitSum(const SplitSumLut& lut, float cosOut, float perceptualRoughness) {
    const float x = std::clamp(cosOut * kSplitSumLutSize - 0.5f, 0.0f, kSplitSumLutSize - 1.0f);
    const float y = std::clamp(perceptualRoughness * kSplitSumLutSize - 0.5f, 0.0f, kSplitSumLutSize - 1.0f);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(x0 + 1, kSplitSumLutSize - 1), y1 = std::min(y0 + 1, kSplitSumLutSize - 1);
    const float fx = x - x0, fy = y - y0;
    auto at = [&](int column, int row) { return lut.texels[row * kSplitSumLutSize + column]; };
    const glm::vec2 top = at(x0, y0) * (1.0f - fx) + at(x1, y0) * fx;
    const glm::vec2 bottom = at(x0, y1) * (1.0f - fx) + at(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

glm::vec3 shIrradiance(const std::array<glm::vec3, 9>& coefficients, glm::vec3 normal) {
    const std::array<float, 9> basis = shBasis(normal);
    constexpr float kBand[3] = {kPi, 2.0f * kPi / 3.0f, kPi / 4.0f};
    glm::vec3 irradiance(0.0f);
    for (int i = 0; i < 9; ++i) irradiance += coefficients[i] * (kBand[i == 0 ? 0 : i < 4 ? 1 : 2] * basis[i]);
    return glm::max(irradiance, glm::vec3(0.0f));  // l ≤ 2 ringing can dip below zero
}

glm::vec3 prefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness) {
    const float level = std::clamp(perceptualRoughness, 0.0f, 1.0f) * kPrefilteredLevels;
    const int lower = std::min(static_cast<int>(level), kPrefilteredLevels - 1);
    const float t = level - lower;
    const glm::vec3 lowerRadiance =
        sampleEquirect(lower == 0 ? map.radiance : map.prefiltered[lower - 1], direction);
    const glm::vec3 upperRadiance = sampleEquirect(map.prefiltered[lower], direction);
    return lowerRadiance * (1.0f - t) + upperRadiance * t;
}

}  // namespace glint
