// The program caches of .brdf and measured (MERL) materials stay bounded: a soak of light set-ups
// (each one a new specialised program per material) keeps their sizes within capacity, and the
// programs they evict are deleted from the GL context, not merely forgotten.
#include <glad/gl.h>

#include <gtest/gtest.h>

#include "gpu_test_support.h"
#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"
#include "twin_brdf_texts.h"

namespace glint {
namespace {

constexpr int kSoakSize = 32;

// GL program objects alive in the current context (names are small integers, shared with shaders).
int liveGlPrograms() {
    int live = 0;
    for (GLuint name = 1; name < (1u << 16); ++name) live += glIsProgram(name) == GL_TRUE;
    return live;
}

// A Lambertian sphere of each kind side by side: one from a .brdf file, one from a MERL table.
Scene twoSpheres() {
    auto file = parseBrdfFile(test::kLambertTwinBrdf, "lambert.brdf");
    EXPECT_TRUE(file.ok());
    MerlTable table;
    table.reflectance.assign(3 * kMerlSamplesPerChannel, 0.5f / kPi);
    Scene scene = previewStage(customBrdfMaterial(makeCustomBrdf(std::move(*file))), kSoakSize, kSoakSize);
    scene.environment = Environment{};
    scene.materials = {scene.materials[0], measuredBrdfMaterial(makeMeasuredBrdf(std::move(table), "grey.binary"))};
    scene.objects = {{"custom", SphereShape{{-1.1f, 0.0f, 0.0f}, 1.0f}, 0}, {"measured", SphereShape{{1.1f, 0.0f, 0.0f}, 1.0f}, 1}};
    return scene;
}

TEST(ProgramCacheGpu, LightSetUpsKeepCustomAndMeasuredProgramsBounded) {
    Renderer& renderer = test::sharedHeadless().renderer();
    Scene scene = twoSpheres();
    (void)test::renderGpu(scene, kSoakSize, kSoakSize);
    const int liveBefore = liveGlPrograms();
    // Set-up n: four lights whose kinds are n's base-3 digits, each set-up a new pair of programs.
    const size_t setUps = 2 * (CustomBrdfPrograms::kCapacity + MeasuredBrdfGpu::kProgramCapacity);
    const LightType kinds[] = {LightType::Directional, LightType::Point, LightType::Spot};
    Light light = scene.lights.at(0);
    light.castsShadows = false;
    for (size_t n = 0; n < setUps; ++n) {
        scene.lights.assign(4, light);
        for (size_t i = 0, digits = n; i < scene.lights.size(); ++i, digits /= 3) scene.lights[i].type = kinds[digits % 3];
        (void)test::renderGpu(scene, kSoakSize, kSoakSize);
        ASSERT_LE(renderer.customBrdfProgramCount(), CustomBrdfPrograms::kCapacity) << "after set-up " << n;
        ASSERT_LE(renderer.measuredProgramCount(), MeasuredBrdfGpu::kProgramCapacity) << "after set-up " << n;
    }
    EXPECT_EQ(renderer.customBrdfProgramCount(), CustomBrdfPrograms::kCapacity);
    EXPECT_EQ(renderer.measuredProgramCount(), MeasuredBrdfGpu::kProgramCapacity);
    // Without eviction the soak would leave 2 × setUps more programs alive.
    const int grown = liveGlPrograms() - liveBefore;
    EXPECT_LE(grown, static_cast<int>(CustomBrdfPrograms::kCapacity + MeasuredBrdfGpu::kProgramCapacity));
    std::printf("[ programs ] %zu light set-ups: %d more GL programs alive, caches at %zu and %zu\n", setUps, grown,
                renderer.customBrdfProgramCount(), renderer.measuredProgramCount());
}

}  // namespace
}  // namespace glint
