// One OSMesa context and Renderer shared by every test in a GPU test binary, and the per-pixel
// comparison of a GPU render with the CPU reference (silhouettes excluded).
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "runtime/headless.h"
#include "render/reference_renderer.h"
#include "scene/preview_stage.h"

namespace glint::test {

inline HeadlessRenderer& sharedHeadless() {
    static std::unique_ptr<HeadlessRenderer> headless = [] {
        auto created = HeadlessRenderer::create();
        if (!created) {
            ADD_FAILURE() << created.error().format();
            std::abort();
        }
        return std::move(*created);
    }();
    return *headless;
}

// The shared renderer's radiance image of `scene`; a failed render is a test failure (and a black
// image, so that the test goes on to report what it compares).
inline RadianceImage renderGpu(const Scene& scene, int width, int height) {
    auto images = sharedHeadless().render(scene, width, height);
    EXPECT_TRUE(images.ok()) << images.error().format();
    return images.ok() ? images->radiance : RadianceImage(width, height);
}

struct PixelAgreement {
    long compared = 0;
    long excluded = 0;   // silhouette pixels
    long disagreeing = 0;
    float worstRelative = 0.0f;
    std::string firstDisagreement;
};

// |GPU − CPU| ≤ relativeTolerance·|CPU| + absoluteFloor per channel, on every pixel whose 3×3
// neighbourhood sees one and the same object (or background) on the CPU, and is not marked in
// `alsoExcluded` (row-major, optional: other edges, e.g. of total internal reflection).
// The preview stage lit by its key light alone, unshadowed: for comparing a material's twins
// pixel by pixel, where neither the environment's GPU approximations (compared on their own in
// environment_gpu_test.cpp) nor PCF penumbrae (shadows_gpu_test.cpp) are what is tested.
inline Scene keyLitPreviewStage(const Material& material, int width, int height) {
    Scene stage = previewStage(material, width, height);
    stage.environment = Environment{};
    for (Light& light : stage.lights) light.castsShadows = false;
    return stage;
}

inline PixelAgreement compareWithReference(const Scene& scene, const RadianceImage& gpu, float relativeTolerance = 1e-3f,
                                           float absoluteFloor = 1e-5f, const std::vector<bool>& alsoExcluded = {}) {
    const int width = gpu.width, height = gpu.height;
    const RadianceImage cpu = renderReference(scene, width, height);
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / height));
    std::vector<int> objectAt(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, width, height));
            objectAt[y * width + x] = hit ? hit->objectIndex : -1;
        }
    PixelAgreement agreement;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            bool silhouette = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
                    silhouette |= objectAt[ny * width + nx] != objectAt[y * width + x];
                }
            if (!alsoExcluded.empty()) silhouette |= alsoExcluded[y * width + x];
            if (silhouette) {
                ++agreement.excluded;
                continue;
            }
            ++agreement.compared;
            const glm::vec3 expected = cpu.at(x, y), actual = gpu.at(x, y);
            bool bad = false;
            for (int c = 0; c < 3; ++c) {
                const float difference = std::abs(actual[c] - expected[c]);
                if (std::abs(expected[c]) > 1e-3f)
                    agreement.worstRelative = std::max(agreement.worstRelative, difference / std::abs(expected[c]));
                bad |= difference > relativeTolerance * std::abs(expected[c]) + absoluteFloor;
            }
            if (bad && agreement.disagreeing++ == 0) {
                agreement.firstDisagreement = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): GPU (" +
                                              std::to_string(actual.r) + ", " + std::to_string(actual.g) + ", " +
                                              std::to_string(actual.b) + ") CPU (" + std::to_string(expected.r) + ", " +
                                              std::to_string(expected.g) + ", " + std::to_string(expected.b) + ")";
            }
        }
    }
    return agreement;
}

}  // namespace glint::test
