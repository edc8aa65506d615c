// The path tracer against what is known without it: a white furnace (a white Lambert sphere and
// a clear glass sphere vanish in a uniform white environment), direct light only and a mirror's
// reflection against the reference renderer, the same picture for the same seed, the bounces
// inside a closed sphere against their closed form, and a Lambert box whose walls light each
// other (brighter than direct light, yet bounded). Tiny images and few samples: each test
// runs in about a second.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "environment_test_support.h"
#include "math/constants.h"
#include "render/path_tracer.h"
#include "render/reference_renderer.h"
#include "test_support.h"

namespace glint {
namespace {

Material lambert(const char* name, glm::vec3 albedo) { return test::materialWith(name, BrdfModel::Lambert, {{"albedo", albedo}}); }

// The mean radiance over the pixels check() accepts, per channel.
template <class Accept>
glm::dvec3 meanOver(const RadianceImage& image, Accept accept) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (accept(x, y)) sum += glm::dvec3(image.at(x, y)), ++count;
    return count > 0 ? sum / static_cast<double>(count) : sum;
}

glm::dvec3 imageMean(const RadianceImage& image) {
    return meanOver(image, [](int, int) { return true; });
}

TEST(PathTracer, WhiteLambertSphereVanishesInAWhiteFurnace) {
    Scene scene = test::sphereUnderEnvironment(lambert("white", glm::vec3(1.0f)), EnvironmentKind::White);
    scene.environment.intensity = 2.0f;  // L = 2 W/(sr·m²) from everywhere: ρ = 1 reflects it all
    const RadianceImage image = renderPathTraced(scene, 256, 32, 32);
    int checked = 0;
    test::forDiscPixels(image, 0.0f, [&](int x, int y, float) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 2.0f, 0.15f) << x << "," << y;
        ++checked;
    }, 0.9f);
    EXPECT_GT(checked, 500);
    const glm::dvec3 mean = imageMean(image);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 2.0, 0.02) << "the whole picture, sphere and background";
}

TEST(PathTracer, ClearGlassSphereVanishesInAWhiteFurnace) {
    // Reflection and refraction, inside and out, carry all the light: every path brings L.
    Scene scene = test::sphereUnderEnvironment(Material::withDefaults("glass", BrdfModel::Glass), EnvironmentKind::White);
    const RadianceImage image = renderPathTraced(scene, 32, 16, 16);
    const glm::dvec3 mean = imageMean(image);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0, 0.03);
}

// A grey Lambert sphere on a floor under the studio environment and a slanted sun: one bounce
// sees the same light as the reference renderer's Monte-Carlo environment and shadow rays.
Scene sunAndStudio() {
    Scene scene = test::sphereUnderEnvironment(lambert("grey", glm::vec3(0.5f)), EnvironmentKind::Studio);
    scene.camera.position = {0.0f, 1.5f, 5.0f};
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    sun.irradiance = 3.0f;
    scene.lights = {sun};
    return scene;
}

TEST(PathTracer, DirectLightAgreesWithTheReference) {
    const Scene scene = sunAndStudio();
    ReferenceOptions sampled;
    sampled.sampleEnvironment = true;
    sampled.environmentSamples = 1024;
    const int size = 32, block = 4;
    const RadianceImage reference = renderReference(scene, size, size, sampled);
    const RadianceImage traced = renderPathTraced(scene, 512, size, size, {.maxBounces = 1});
    // The disc's interior only: the path tracer's pixels average over their area, the
    // reference's are their centres, which differ on the silhouette.
    std::vector<bool> interior(size * size, false);
    test::forDiscPixels(reference, 0.0f, [&](int x, int y, float) { interior[y * size + x] = true; }, 0.85f);
    const auto inside = [&](int x, int y) { return interior[y * size + x]; };
    const glm::dvec3 referenceMean = meanOver(reference, inside), tracedMean = meanOver(traced, inside);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tracedMean[c], referenceMean[c], 0.02 * referenceMean[c]);
    // Block by block (4×4 pixels, averaging the studio lights' noise down): the same shading.
    int blocksChecked = 0;
    for (int by = 0; by < size; by += block)
        for (int bx = 0; bx < size; bx += block) {
            const auto inBlock = [&](int x, int y) { return x >= bx && x < bx + block && y >= by && y < by + block; };
            bool whole = true;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) whole = whole && inside(x, y);
            if (!whole) continue;
            const glm::dvec3 expected = meanOver(reference, inBlock), actual = meanOver(traced, inBlock);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 0.05 * expected[c] + 0.01) << bx << "," << by;
            ++blocksChecked;
        }
    EXPECT_GE(blocksChecked, 20);
}

TEST(PathTracer, MirrorReflectsAsTheReferencesMirror) {
    // An aluminium ball in a white furnace: F(θ_o; n + iκ) · L, a delta lobe followed by one ray.
    const Scene scene = test::sphereUnderEnvironment(Material::withDefaults("aluminium", BrdfModel::Mirror), EnvironmentKind::White);
    const RadianceImage reference = renderReference(scene, 32, 32);
    const RadianceImage traced = renderPathTraced(scene, 16, 32, 32);
    int checked = 0;
    test::forDiscPixels(reference, 0.0f, [&](int x, int y, float) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(traced.at(x, y)[c], reference.at(x, y)[c], 0.01f) << x << "," << y;
        ++checked;
    }, 0.9f);
    EXPECT_GT(checked, 500);
}

TEST(PathTracer, SameSeedSamePictureOtherSeedAnother) {
    const Scene scene = sunAndStudio();
    const RadianceImage first = renderPathTraced(scene, 4, 16, 16, {.seed = 7});
    EXPECT_EQ(renderPathTraced(scene, 4, 16, 16, {.seed = 7}).pixels, first.pixels);
    EXPECT_NE(renderPathTraced(scene, 4, 16, 16, {.seed = 8}).pixels, first.pixels);
}

TEST(PathTracer, PassesAccumulateIntoTheMean) {
    const Scene scene = sunAndStudio();
    PathTracer tracer(scene, 8, 8);
    EXPECT_EQ(tracer.radiance().pixels, RadianceImage(8, 8).pixels) << "black before the first pass";
    tracer.addPass();
    tracer.addPass();
    EXPECT_EQ(tracer.samplesPerPixel(), 2);
    EXPECT_EQ(tracer.radiance().pixels, renderPathTraced(scene, 2, 8, 8).pixels);
}

// Inside a closed Lambert sphere (albedo ρ, radius R) with a point light Φ at its centre, every
// point gets E₀ = Φ/(4πR²) directly and sees the whole sphere with form factor 1, so the
// radiosity is B = ρE₀ + ρB and each bounce adds ρ times the last: L = (ρE₀/π)·(1 + ρ + ρ² + …).
TEST(PathTracer, InsideAWhiteSphereEachBounceAddsAlbedoTimesTheLast) {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 0.5f};
    scene.materials = {lambert("grey", glm::vec3(0.5f))};
    scene.objects = {{"room", SphereShape{}, 0}};
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0.0f, 0.0f, 0.0f};
    bulb.power = 4.0f * kPi * kPi;  // E₀ = π W/m² on the unit sphere: ρE₀/π = 0.5
    scene.lights = {bulb};
    for (const auto& [bounces, expected] : {std::pair{1, 0.5f}, {2, 0.75f}, {3, 0.875f}})
        for (float value : renderPathTraced(scene, 2, 8, 8, {.maxBounces = bounces}).pixels)
            ASSERT_NEAR(value, expected, 1e-4f) << bounces << " bounces: every path adds the same";
    // All bounces, ended by Russian roulette: 0.5 / (1 − 0.5) = 1 on average.
    const glm::dvec3 mean = imageMean(renderPathTraced(scene, 64, 16, 16));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0, 0.02);
}

// Five 2 m Lambert walls (white floor, ceiling and back, red left, green right), open towards
// the camera, with a point light under the ceiling: a small Cornell box.
Scene lambertBox() {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 3.9f};
    scene.camera.verticalFovDegrees = 38.0f;
    scene.materials = {lambert("white", glm::vec3(0.75f)), lambert("red", {0.75f, 0.1f, 0.1f}),
                       lambert("green", {0.1f, 0.75f, 0.1f})};
    const glm::vec2 wall{2.0f, 2.0f};
    scene.objects = {{"floor", PlaneShape{{0, -1, 0}, {0, 1, 0}, wall}, 0},
                     {"ceiling", PlaneShape{{0, 1, 0}, {0, -1, 0}, wall}, 0},
                     {"back", PlaneShape{{0, 0, -1}, {0, 0, 1}, wall}, 0},
                     {"left", PlaneShape{{-1, 0, 0}, {1, 0, 0}, wall}, 1},
                     {"right", PlaneShape{{1, 0, 0}, {-1, 0, 0}, wall}, 2}};
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0.0f, 0.8f, 0.0f};
    bulb.power = 30.0f;
    scene.lights = {bulb};
    return scene;
}

TEST(PathTracer, LambertBoxWallsLightEachOtherWithinBounds) {
    const Scene scene = lambertBox();
    const RadianceImage direct = renderPathTraced(scene, 16, 20, 20, {.maxBounces = 1});
    const RadianceImage global = renderPathTraced(scene, 64, 20, 20);
    for (float value : global.pixels) ASSERT_TRUE(std::isfinite(value) && value >= 0.0f);
    const glm::dvec3 directMean = imageMean(direct), globalMean = imageMean(global);
    for (int c = 0; c < 3; ++c) {
        // Every wall gains the light the others reflect onto it.
        EXPECT_GT(globalMean[c], 1.2 * directMean[c]) << "channel " << c;
        // Each bounce keeps at most ρ ≤ 0.75 of the light: the sum of all bounces ≤ direct / (1 − 0.75).
        EXPECT_LT(globalMean[c], 4.0 * directMean[c]) << "channel " << c;
    }
    // Colour bleeding: the floor near the red wall is redder than near the green one.
    const glm::vec3 nearRed = global.at(4, 17), nearGreen = global.at(15, 17);
    EXPECT_GT(nearRed.r / nearRed.g, nearGreen.r / nearGreen.g);
}

}  // namespace
}  // namespace glint
