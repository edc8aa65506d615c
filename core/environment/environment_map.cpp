// Precomputed image-based lighting (see environment_map.h).
// Sections: parallel rows · irradiance · GGX prefiltering · lookups.
#include "environment/environment_map.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "light/photometry.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {
namespace {

// --- progress and parallel rows ------------------------------------------------------------

// The precompute's progress: each stage a share of [0, 1] (stage() moves on), rows within it. Once
// the callback declines, every later offer is declined and the stages left skip their rows.
class StagedProgress {
public:
    explicit StagedProgress(const EnvironmentProgress& callback) : callback_(callback) {}
    void stage(float share) {
        start_ = end_;
        end_ = std::min(1.0f, start_ + share);
        offer(0.0f);
    }
    bool offer(float withinStage) {
        if (!cancelled_ && callback_ && !callback_(std::min(end_, start_ + (end_ - start_) * withinStage))) cancelled_ = true;
        return !cancelled_;
    }
    bool cancelled() const { return cancelled_; }

private:
    const EnvironmentProgress& callback_;
    float start_ = 0.0f, end_ = 0.0f;
    bool cancelled_ = false;
};

// Calls row(y) for every row on all cores; the calling thread offers the rows done to `progress`.
template <class RowFunction>
void forEachRow(int rows, RowFunction&& row, StagedProgress& progress) {
    const int threadCount = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    std::atomic<int> done{0};
    std::atomic<bool> stop{progress.cancelled()};
    auto work = [&](int first) {
        for (int y = first; y < rows && !stop.load(std::memory_order_relaxed); y += threadCount) {
            row(y);
            const int rowsDone = done.fetch_add(1) + 1;
            if (first == 0 && !progress.offer(static_cast<float>(rowsDone) / rows)) stop.store(true);
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < threadCount; ++t) threads.emplace_back(work, t);
    work(0);
    for (std::thread& thread : threads) thread.join();
}

// --- irradiance ----------------------------------------------------------------------------

// E(n)/π at each texel direction n of a width × height image: Σ L cos⁺ Ω over the texels of
// `source` (a pyramid level, each texel at its centre with its exact solid angle; the pyramid's
// solid-angle-weighted means keep each source's power, so a light smaller than a texel still
// counts in full), normalised by the same sum for a uniform map (Σ cos⁺ Ω / π, within 0.4% of 1)
// so that a uniform map gives E/π = L exactly. Brute force over flat arrays: (64·32)·(128·64) products.
EquirectImage convolveIrradiance(const EquirectImage& source, int width, int height, StagedProgress& progress) {
    const size_t count = source.texels.size();
    std::vector<float> dx(count), dy(count), dz(count), red(count), green(count), blue(count), solidAnglesOverPi(count);
    for (int y = 0; y < source.height; ++y) {
        const float weight = texelSolidAngle(y, source.width, source.height) * kInvPi;
        for (int x = 0; x < source.width; ++x) {
            const size_t i = static_cast<size_t>(y) * source.width + x;
            const glm::vec3 d = equirectDirection({(x + 0.5f) / source.width, (y + 0.5f) / source.height});
            dx[i] = d.x, dy[i] = d.y, dz[i] = d.z, solidAnglesOverPi[i] = weight;
            red[i] = source.texels[i].r * weight, green[i] = source.texels[i].g * weight, blue[i] = source.texels[i].b * weight;
        }
    }
    EquirectImage irradiance(width, height);
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 n = equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
            float r = 0.0f, g = 0.0f, b = 0.0f, kernel = 0.0f;
            for (size_t i = 0; i < count; ++i) {
                const float cosine = std::max(0.0f, n.x * dx[i] + n.y * dy[i] + n.z * dz[i]);
                r += cosine * red[i], g += cosine * green[i], b += cosine * blue[i], kernel += cosine * solidAnglesOverPi[i];
            }
            irradiance.at(x, y) = glm::vec3(r, g, b) / kernel;
        }
    }, progress);
    return irradiance;
}

// The irradiance map at the prefiltered size: convolved at half that size from the first pyramid
// level no wider than the prefiltered levels, then resampled bilinearly (E is smooth: the
// resampling changes it by < 0.2% where a small light sits at the terminator).
EquirectImage irradianceMap(const std::vector<EquirectImage>& pyramid, StagedProgress& progress) {
    const auto source = std::find_if(pyramid.begin(), pyramid.end(),
                                     [](const EquirectImage& level) { return level.width <= kPrefilteredWidth; });
    const EquirectImage coarse = convolveIrradiance(*source, kPrefilteredWidth / 2, kPrefilteredHeight / 2, progress);
    EquirectImage irradiance(kPrefilteredWidth, kPrefilteredHeight);
    for (int y = 0; y < irradiance.height; ++y)
        for (int x = 0; x < irradiance.width; ++x)
            irradiance.at(x, y) = sampleEquirect(
                coarse, equirectDirection({(x + 0.5f) / irradiance.width, (y + 0.5f) / irradiance.height}));
    return irradiance;
}

// --- peaks --------------------------------------------------------------------------------

// The mean radiance over the sphere: Σ L Ω / 4π over the texels.
glm::vec3 meanRadiance(const EquirectImage& image) {
    glm::dvec3 sum(0.0);
    for (int y = 0; y < image.height; ++y) {
        const double solidAngle = texelSolidAngle(y, image.width, image.height);
        for (int x = 0; x < image.width; ++x) sum += solidAngle * glm::dvec3(image.at(x, y));
    }
    return glm::vec3(sum / (4.0 * kPi));
}

// Each texel's radiance above the threshold T = kPeakThreshold × the mean luminance over the
// sphere, as a share of its luminance Y: L·max(0, 1 − T/Y), so that the peak keeps its colour.
EquirectImage peakRadiance(const EquirectImage& radiance) {
    const float threshold = kPeakThreshold * relativeLuminance(meanRadiance(radiance));  // Y is linear in L
    EquirectImage peak(radiance.width, radiance.height);
    for (size_t i = 0; i < peak.texels.size(); ++i) {
        const float y = relativeLuminance(radiance.texels[i]);
        if (y > threshold) peak.texels[i] = radiance.texels[i] * (1.0f - threshold / y);
    }
    return peak;
}

// The peaks as a few lights: the peak image's texels joined into connected regions (8-neighbours,
// wrapping in longitude), the kMaxPeakLights regions of most luminous power each a light with the
// region's exact ∫ L_peak dω, its luminance-weighted mean direction and the radius of the disc of
// the same mean cosine to it (a studio's soft box is one light). The peaks of the other regions go
// back to the rest: their texels are zeroed in `peak`.
std::vector<EnvironmentPeakLight> peakLights(EquirectImage& peak) {
    const int width = peak.width, height = peak.height;
    std::vector<int> parent(peak.texels.size());
    for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
    const auto root = [&](int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    const auto lit = [&](int x, int y) { return relativeLuminance(peak.at((x + width) % width, y)) > 0.0f; };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!lit(x, y)) continue;
            // The neighbours already visited: left, and the three above.
            const int neighbours[4][2] = {{x - 1, y}, {x - 1, y - 1}, {x, y - 1}, {x + 1, y - 1}};
            for (const auto& [nx, ny] : neighbours) {
                if (ny < 0 || !lit(nx, ny)) continue;
                const int a = root(y * width + x), b = root(ny * width + (nx + width) % width);
                parent[std::max(a, b)] = std::min(a, b);
            }
        }
    struct Region {
        glm::vec3 power{0.0f}, moment{0.0f};
        float luminousPower = 0.0f;
    };
    std::vector<Region> regions(peak.texels.size());
    for (int y = 0; y < height; ++y) {
        const float solidAngle = texelSolidAngle(y, width, height);
        for (int x = 0; x < width; ++x) {
            if (!lit(x, y)) continue;
            Region& region = regions[root(y * width + x)];
            const float luminousPower = relativeLuminance(peak.at(x, y)) * solidAngle;
            region.power += peak.at(x, y) * solidAngle;
            region.luminousPower += luminousPower;
            region.moment += luminousPower * equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
        }
    }
    std::vector<int> order;
    for (size_t i = 0; i < regions.size(); ++i)
        if (regions[i].luminousPower > 0.0f) order.push_back(static_cast<int>(i));
    std::sort(order.begin(), order.end(), [&](int a, int b) { return regions[a].luminousPower > regions[b].luminousPower; });
    order.resize(std::min(order.size(), static_cast<size_t>(kMaxPeakLights)));
    std::vector<bool> kept(regions.size(), false);
    std::vector<EnvironmentPeakLight> lights;
    for (int index : order) {
        const Region& region = regions[index];
        kept[index] = true;
        // A uniform disc of radius ρ has mean cosine (1 + cos ρ)/2 to its centre.
        const float cosRadius = std::clamp(2.0f * glm::length(region.moment) / region.luminousPower - 1.0f, 0.0f, 1.0f);
        lights.push_back({glm::normalize(region.moment), region.power, std::sqrt(1.0f - cosRadius * cosRadius)});
    }
    for (size_t i = 0; i < peak.texels.size(); ++i)
        if (!kept[root(static_cast<int>(i))]) peak.texels[i] = glm::vec3(0.0f);
    return lights;
}

std::vector<EquirectImage> pyramidOf(EquirectImage image) {
    std::vector<EquirectImage> pyramid{std::move(image)};
    while (pyramid.back().width > 8 && pyramid.back().height > 4) pyramid.push_back(downsampleEquirect(pyramid.back()));
    return pyramid;
}

// --- GGX prefiltering -----------------------------------------------------------------------

// Trilinear lookup in a mip pyramid (level 0 the full image) at a fractional level.
glm::vec3 samplePyramid(const std::vector<EquirectImage>& pyramid, glm::vec3 direction, float level) {
    level = std::clamp(level, 0.0f, static_cast<float>(pyramid.size() - 1));
    const int lower = static_cast<int>(level);
    const int upper = std::min(lower + 1, static_cast<int>(pyramid.size()) - 1);
    const float t = level - lower;
    const glm::vec2 coordinates = equirectCoordinates(direction);
    return sampleEquirectAt(pyramid[lower], coordinates) * (1.0f - t) + sampleEquirectAt(pyramid[upper], coordinates) * t;
}

// One prefiltered level: for each texel direction R, the cos θ_l-weighted mean of the radiance
// over the level's samples (prefilter_kernel.h), each read from the pyramid level whose texels
// cover kPrefilterTexelsPerSample × its solid angle.
EquirectImage prefilterLevel(const std::vector<EquirectImage>& pyramid, float alpha, StagedProgress& progress) {
    struct LocalSample {
        glm::vec3 light;
        float pyramidLevel;
    };
    std::vector<LocalSample> samples;  // the same for every texel
    float weightSum = 0.0f;
    const float texelSolidAngleMean = 4.0f * kPi / (pyramid[0].width * pyramid[0].height);
    for (const PrefilterSample& sample : prefilterSamples(alpha)) {
        samples.push_back({sample.light, 0.5f * std::log2(kPrefilterTexelsPerSample * sample.solidAngle / texelSolidAngleMean)});
        weightSum += sample.light.z;
    }
    EquirectImage level(kPrefilteredWidth, kPrefilteredHeight);
    forEachRow(level.height, [&](int y) {
        for (int x = 0; x < level.width; ++x) {
            const glm::vec3 mirror = equirectDirection({(x + 0.5f) / level.width, (y + 0.5f) / level.height});
            const ShadingFrame frame = ShadingFrame::fromNormal(mirror);
            glm::vec3 sum(0.0f);
            for (const LocalSample& sample : samples)
                sum += samplePyramid(pyramid, frame.toWorld(sample.light), sample.pyramidLevel) * sample.light.z;
            level.at(x, y) = sum / weightSum;
        }
    }, progress);
    return level;
}

}  // namespace

// --- making a map ---------------------------------------------------------------------------

std::shared_ptr<const EnvironmentMap> makeEnvironmentMap(EquirectImage radiance, const EnvironmentProgress& callback) {
    // Shares of the time each stage takes (1024×512 studio HDRI): the prefiltered levels most.
    constexpr float kIrradianceShare = 0.1f, kPeaksShare = 0.06f, kDistributionShare = 0.04f;
    constexpr float kLevelShare = (1.0f - kIrradianceShare - kPeaksShare - kDistributionShare) / (2 * kPrefilteredLevels);
    StagedProgress progress(callback);
    auto map = std::make_shared<EnvironmentMap>();
    progress.stage(kIrradianceShare);
    const std::vector<EquirectImage> pyramid = pyramidOf(radiance);
    map->irradiance = irradianceMap(pyramid, progress);
    progress.stage(kPeaksShare);
    EquirectImage peak = peakRadiance(radiance);
    map->peaks = peakLights(peak);
    for (const EnvironmentPeakLight& light : map->peaks)
        map->peakMinimumAlpha = std::max(map->peakMinimumAlpha, kPeakLobeToLight * kPeakWidening * light.sinRadius);
    EquirectImage residual = radiance;
    for (size_t i = 0; i < residual.texels.size(); ++i) residual.texels[i] -= peak.texels[i];
    map->residualMean = meanRadiance(residual);
    const std::vector<EquirectImage> residualPyramid = pyramidOf(std::move(residual));
    for (int k = 1; k <= kPrefilteredLevels; ++k) {
        const float perceptual = static_cast<float>(k) / kPrefilteredLevels;
        progress.stage(kLevelShare);
        map->prefiltered.push_back(prefilterLevel(pyramid, perceptual * perceptual, progress));
        progress.stage(kLevelShare);
        map->residualPrefiltered.push_back(prefilterLevel(residualPyramid, perceptual * perceptual, progress));
    }
    progress.stage(kDistributionShare);
    if (progress.cancelled()) return nullptr;
    map->distribution = EnvironmentDistribution(radiance);
    map->radiance = std::move(radiance);
    progress.offer(1.0f);
    return map;
}

// --- lookups --------------------------------------------------------------------------------

glm::vec3 diffuseRadiance(const EnvironmentMap& map, glm::vec3 normal) { return sampleEquirect(map.irradiance, normal); }

glm::vec3 prefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness) {
    const float level = std::clamp(perceptualRoughness, 0.0f, 1.0f) * kPrefilteredLevels;
    const int lower = std::min(static_cast<int>(level), kPrefilteredLevels - 1);
    const float t = level - lower;
    const glm::vec3 lowerRadiance =
        sampleEquirect(lower == 0 ? map.radiance : map.prefiltered[lower - 1], direction);
    const glm::vec3 upperRadiance = sampleEquirect(map.prefiltered[lower], direction);
    return lowerRadiance * (1.0f - t) + upperRadiance * t;
}

glm::vec3 residualPrefilteredRadiance(const EnvironmentMap& map, glm::vec3 direction, float perceptualRoughness) {
    const float level = std::clamp(perceptualRoughness * kPrefilteredLevels, 1.0f, static_cast<float>(kPrefilteredLevels));
    const int lower = std::min(static_cast<int>(level), kPrefilteredLevels - 1);
    const float t = level - lower;
    return sampleEquirect(map.residualPrefiltered[lower - 1], direction) * (1.0f - t) +
           sampleEquirect(map.residualPrefiltered[lower], direction) * t;
}

}  // namespace glint
