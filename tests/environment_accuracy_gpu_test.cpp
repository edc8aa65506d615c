// Environment light on the GPU against the Monte-Carlo ground truth (issue 21): every model with
// an environment hook, glossy ones at α ∈ {0.05, 0.2, 0.5, 1}, on a smooth sky, one small bright
// light and the shipped CC0 studio HDRI (tests/environment_accuracy_support.h). The target is
// 40 dB over the sphere's interior with the mean within 2%; the cells the real-time approximation
// does not reach are listed below with the floor they do hold (measured: docs/environment-lighting.md,
// tests/bench/environment_accuracy.cpp). The reference's own noise is checked to stay 10 dB below.
#include <gtest/gtest.h>

#include <cstring>

#include "environment_accuracy_support.h"
#include "gpu_test_support.h"
#include "render/reference_renderer.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr int kSize = 32, kFirstSamples = 1024, kMostSamples = 16384;
constexpr double kTargetDb = 40.0, kTargetRatio = 0.02;

// A cell below the target: the PSNR floor [dB] and the ratio band it holds instead.
struct Shortfall {
    const char* material;
    const char* map;
    double minDb, maxRatioError;
};

constexpr Shortfall kShortfalls[] = {
    {"cook_torrance α 0.2", "studio HDRI", 27.0, 0.04},
};

const Shortfall* shortfall(const std::string& material, const std::string& map) {
    for (const Shortfall& cell : kShortfalls)
        if (material == cell.material && map == cell.map) return &cell;
    return nullptr;
}

TEST(EnvironmentAccuracy, EveryHookAgainstTheMonteCarloReference) {
    const auto maps = test::accuracyMaps(test::dataPath("environments/studio_small_01_256.exr"));
    for (const auto& map : maps) ASSERT_TRUE(map.environment.enabled()) << map.name;
    for (const auto& entry : test::accuracyMaterials()) {
        for (const auto& map : maps) {
            SCOPED_TRACE(entry.name + " on the " + map.name);
            const Scene scene = test::accuracyScene(entry.material, map.environment);
            const Shortfall* below = shortfall(entry.name, map.name);
            const double minDb = below ? below->minDb : kTargetDb;
            const double maxRatioError = below ? below->maxRatioError : kTargetRatio;
            // The reference: two seeds, 4× the samples until their noise is 10 dB below the floor
            // (two estimates differ by √2 × the noise of one: its PSNR is theirs + 3 dB; their
            // mean, compared below, is 3 dB quieter still).
            RadianceImage truth, again;
            double noiseDb = 0.0;
            for (int samples = kFirstSamples; samples <= kMostSamples && noiseDb < minDb + 10.0; samples *= 4) {
                truth = renderReference(scene, kSize, kSize, {true, samples, 0});
                again = renderReference(scene, kSize, kSize, {true, samples, 1});
                noiseDb = test::measureAccuracy(again, truth).psnr + 3.0103;
            }
            EXPECT_GE(noiseDb, minDb + 10.0) << "reference noise";
            for (size_t i = 0; i < truth.pixels.size(); ++i) truth.pixels[i] = 0.5f * (truth.pixels[i] + again.pixels[i]);
            const RadianceImage gpu = test::renderGpu(scene, kSize, kSize);
            const test::Accuracy accuracy = test::measureAccuracy(gpu, truth);
            EXPECT_GE(accuracy.psnr, minDb);
            EXPECT_NEAR(accuracy.ratio, 1.0, maxRatioError);
            std::printf("%-28s %-12s %5.1f dB  ratio %.3f  (reference noise %.1f dB)%s\n", entry.name.c_str(),
                        map.name.c_str(), accuracy.psnr, accuracy.ratio, noiseDb, below ? "  listed shortfall" : "");
        }
    }
}

}  // namespace
}  // namespace glint
