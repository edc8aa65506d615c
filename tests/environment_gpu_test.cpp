// Environment light on the GPU (OSMesa): the white-out and the GGX white furnace against the
// radiometry, every model's image-based lighting and the environment-mapped mirror and glass
// against the CPU reference pixel by pixel, and a golden of a GGX sphere in the studio.
#include <gtest/gtest.h>

#include <cstdio>

#include "brdf/cook_torrance.h"
#include "brdf/glass.h"
#include "brdf/presets.h"
#include "environment/environment_lighting.h"
#include "environment/lobe_albedo.h"
#include "environment_accuracy_support.h"
#include "environment_test_support.h"
#include "gpu_test_support.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "test_support.h"

namespace glint {
namespace {

using test::renderGpu;

void expectAgreesWithReference(const Scene& scene, int size, float relativeTolerance = 1e-3f) {
    const RadianceImage gpu = renderGpu(scene, size, size);
    const test::PixelAgreement agreement = test::compareWithReference(scene, gpu, relativeTolerance, 1e-4f);
    EXPECT_GT(agreement.compared, size * size / 4);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative "
                                        << agreement.worstRelative << ")";
}

// The GPU's disc is checked out to 0.97 of its radius, clear of the silhouette's pixels.
constexpr float kInsideTheRim = 0.97f;

TEST(EnvironmentGpu, WhiteOutLambertIsAFlatDisc) {
    Material material = Material::withDefaults("white-out", BrdfModel::Lambert);
    material.analytic()->values = {0.6f, 0.6f, 0.6f};
    Scene scene = test::sphereUnderEnvironment(material, EnvironmentKind::White);
    scene.environment.intensity = 2.0f;
    scene.environment.showAsBackground = false;  // the disc on the black constant background
    const RadianceImage image = renderGpu(scene, 64, 64);
    test::forDiscPixels(image, 0.0f, [&](int x, int y, float) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 1.2f, 1.2f * 2e-4f) << x << "," << y;
    }, kInsideTheRim);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f));
}

TEST(EnvironmentGpu, SphereOccludesTheFloorAnalytically) {
    // A white-out over a Lambert floor with a unit sphere resting on it, seen from straight above
    // (orthographic): the floor's radiance is ρ·L·(1 − cos θ·(r/D)²) (render/sphere_occlusion.h),
    // (r/D)³ = 1/(1 + d²)^1.5 at a distance d from the contact point for r = 1. The GLSL twin
    // agrees pixel by pixel.
    Scene scene;
    scene.camera.projection = Projection::Orthographic;
    scene.camera.position = {0.0f, 5.0f, 0.001f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.orthoHeight = 6.0f;
    Material floor = Material::withDefaults("floor", BrdfModel::Lambert);
    floor.analytic()->values = {0.5f, 0.5f, 0.5f};
    scene.materials = {Material::withDefaults("ball", BrdfModel::Lambert), floor};
    scene.objects.push_back({"ball", SphereShape{}, 0});
    scene.objects.push_back({"floor", PlaneShape{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {20.0f, 20.0f}}, 1,
                             SurfaceInterpolation::Phong});
    scene.environment.kind = EnvironmentKind::White;
    ASSERT_TRUE(loadEnvironment(scene.environment).ok());
    const RadianceImage image = renderGpu(scene, 96, 96);
    const test::PixelAgreement agreement = test::compareWithReference(scene, image, 1e-3f, 1e-4f);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 96 * 96 / 2);
    // The floor about 1.5 m from the contact point (column 24, row 48): there cos θ = r/D and
    // D² = 1 + d², so L = 0.5·(1 − D⁻³); unoccluded it would be 0.5.
    const float x = -3.0f + (24 + 0.5f) * 6.0f / 96.0f, z = -3.0f + (48 + 0.5f) * 6.0f / 96.0f;
    const float distanceSquared = 1.0f + x * x + z * z;
    EXPECT_NEAR(image.at(24, 48).r, 0.5f * (1.0f - std::pow(distanceSquared, -1.5f)), 2e-3f);
    EXPECT_GT(image.at(24, 48).r, 0.4f) << "an open floor 1.5 m away is barely occluded";
}

TEST(EnvironmentGpu, GgxWhiteFurnaceWithinTheSplitSumTolerance) {
    // F = 1 conductor. Under a uniform environment the prefiltered radiance is exactly L, so the
    // split sum gives L·(A + B) = L·E(μ): exact but for the table's 32×32 bilinear interpolation
    // and its 1024-sample estimate. Against the sampled CPU reference (512 samples, ≈ 1% noise)
    // a 3% band holds them both; and for a smooth lobe (α = 0.1) E ≥ 0.98 where μ ≥ 0.7, so there
    // the disc is ≈ L.
    for (float roughness : {0.1f, 0.5f}) {
        Material material = Material::withDefaults("furnace", BrdfModel::CookTorrance);
        material.analytic()->values = {0, 0, 0, 1, 1, 1, 1e4f, 1e4f, 1e4f, roughness, 1, 1, 0};
        const Scene scene = test::sphereUnderEnvironment(material, EnvironmentKind::White);
        const RadianceImage gpu = renderGpu(scene, 32, 32);
        const RadianceImage sampled = renderReference(scene, 32, 32, {true, 512});
        test::forDiscPixels(gpu, 0.2f, [&](int x, int y, float cosine) {
            ASSERT_NEAR(gpu.at(x, y).g, sampled.at(x, y).g, 0.03f) << "α " << roughness << " at " << x << "," << y;
            if (roughness < 0.2f && cosine >= 0.7f) {
                ASSERT_NEAR(gpu.at(x, y).g, 1.0f, 0.025f) << x << "," << y;
            }
        }, kInsideTheRim);
    }
}

TEST(EnvironmentGpu, EveryModelMatchesTheCpuReferenceInTheStudio) {
    // The image-based lighting of every model to 2e-3. Mirror and glass look up the base level
    // along traced rays: near the silhouette a reflected ray turns twice as fast as the normal, and
    // the studio's soft boxes have 3° edges of radiance 0.03 → 12, so the last float bits of the
    // GPU's and CPU's ray-sphere hit move a pixel by up to a few percent there (on the smooth map of
    // the EnvironmentHdrTest cases below they agree to 1e-3).
    for (const ModelInfo& info : allModels()) {
        SCOPED_TRACE(info.id);
        const Scene scene = test::sphereUnderEnvironment(Material::withDefaults("m", info.model), EnvironmentKind::Studio);
        const bool traced = info.glslTransport != nullptr;
        expectAgreesWithReference(scene, 48, traced ? 3e-2f : 2e-3f);
    }
}

TEST(EnvironmentGpu, EachMicrofacetPairMatchesTheCpuReferenceInTheStudio) {
    // Cook-Torrance's D × G pairs, each with its own split-sum tables and (but GGX with Smith) its
    // GGX stand-in, at α 0.2 (the oblique lookups) and 0.7 (one lookup), to 2e-3.
    for (const MicrofacetDistribution distribution : {MicrofacetDistribution::Beckmann, MicrofacetDistribution::Ggx})
        for (const MicrofacetGeometry geometry : {MicrofacetGeometry::VCavity, MicrofacetGeometry::Smith})
            for (const float alpha : {0.2f, 0.7f}) {
                Material material = test::glossyMaterial(BrdfModel::CookTorrance, alpha);
                test::setParam(material, "distribution", {static_cast<float>(distribution)});
                test::setParam(material, "geometry", {static_cast<float>(geometry)});
                SCOPED_TRACE(testing::Message() << "pair " << microfacetPair(distribution, geometry) << ", α " << alpha);
                expectAgreesWithReference(test::sphereUnderEnvironment(material, EnvironmentKind::Studio), 48, 2e-3f);
            }
}

class EnvironmentHdrTest : public ::testing::Test {
protected:
    static std::string hdrPath() {
        static const std::string path = [] {
            const std::string written = test::outputDirectory("environment_gpu") + "/smooth_sky.exr";
            test::writeTestHdr(written, 128);
            return written;
        }();
        return path;
    }
};

TEST_F(EnvironmentHdrTest, GlassSphereRefractsTheMapAsTheCpuReferenceDoes) {
    Material glass = Material::withDefaults("glass", BrdfModel::Glass);
    Scene scene = test::sphereUnderEnvironment(glass, EnvironmentKind::File, hdrPath());
    scene.environment.rotationDegrees = 40.0f;
    expectAgreesWithReference(scene, 96);
    // Thick tinted glass (Beer-Lambert, σ = (0.2, 0.8, 1.6)/m): still the same per pixel, and darker.
    const RadianceImage clear = renderGpu(scene, 32, 32);
    scene.materials[0].analytic()->values = {1.5f, 0.2f, 0.8f, 1.6f, 0.0f, 0.9f};
    expectAgreesWithReference(scene, 96);
    const RadianceImage tinted = renderGpu(scene, 32, 32);
    EXPECT_LT(tinted.at(16, 16).b, 0.5f * clear.at(16, 16).b);
}

TEST_F(EnvironmentHdrTest, EveryLayeredPresetAgreesWithTheReference) {
    // The OpenPBR presets (coat, fuzz, thin film, rough and thin-walled transmission, F82 metal)
    // under the smooth sky: environment hook and traced transmission to 1e-3.
    for (const Preset& preset : allPresets()) {
        if (preset.model != BrdfModel::OpenPbr) continue;
        Scene scene = test::sphereUnderEnvironment(preset.material(), EnvironmentKind::File, hdrPath());
        scene.environment.rotationDegrees = 40.0f;
        const RadianceImage gpu = renderGpu(scene, 96, 96);
        const test::PixelAgreement agreement = test::compareWithReference(scene, gpu, 1e-3f, 1e-4f);
        std::printf("%s: worst relative GPU-CPU difference %.2e over %ld pixels\n", preset.name, agreement.worstRelative,
                    agreement.compared);
        EXPECT_GT(agreement.compared, 96 * 96 / 4) << preset.name;
        EXPECT_EQ(agreement.disagreeing, 0) << preset.name << ": " << agreement.firstDisagreement;
    }
}

TEST_F(EnvironmentHdrTest, OpenPbrsPeakLightsAgreeWithTheReference) {
    // Under the studio HDRI, whose bright regions are peak lights from GGX α 0.04, the default
    // OpenPBR and a half-metal under a rough coat: each lobe meets the peaks through its own shape
    // and the layers above it, the GPU as the CPU to 1e-3.
    Material coated = Material::withDefaults("coated", BrdfModel::OpenPbr);
    test::setParam(coated, "base_metalness", {0.5f});
    test::setParam(coated, "specular_roughness", {0.5f});
    test::setParam(coated, "coat_weight", {1.0f});
    test::setParam(coated, "coat_roughness", {0.3f});
    for (const Material& material : {Material::withDefaults("default", BrdfModel::OpenPbr), coated}) {
        Scene scene = test::sphereUnderEnvironment(material, EnvironmentKind::File,
                                                   test::dataPath("environments/studio_small_01_256.exr"));
        scene.environment.rotationDegrees = 40.0f;
        ASSERT_TRUE(environmentUsesPeaks(scene.environment, 0.09f)) << "the map's peaks light the lobes";
        const RadianceImage gpu = renderGpu(scene, 64, 64);
        const test::PixelAgreement agreement = test::compareWithReference(scene, gpu, 1e-3f, 1e-4f);
        EXPECT_GT(agreement.compared, 64 * 64 / 4) << material.name;
        EXPECT_EQ(agreement.disagreeing, 0) << material.name << ": " << agreement.firstDisagreement;
    }
}

TEST_F(EnvironmentHdrTest, InsideAWaterBallTotalInternalReflectionAgreesWithTheReference) {
    Material water = Material::withDefaults("water", BrdfModel::Glass);
    water.analytic()->values[0] = 1.333f;
    Scene scene = test::sphereUnderEnvironment(water, EnvironmentKind::File, hdrPath());
    scene.objects[0].shape = SphereShape{{0, 0, 0}, 3.0f};
    scene.camera.projection = Projection::Perspective;
    scene.camera.position = {0.0f, 0.0f, 0.5f};
    scene.camera.target = {0.0f, 0.3f, -1.0f};
    scene.camera.verticalFovDegrees = 100.0f;
    // The edge of the critical-angle circle jumps in radiance; pixels straddling it are excluded.
    const RadianceImage gpu = renderGpu(scene, 96, 96);
    const RadianceImage cpu = renderReference(scene, 96, 96);
    std::vector<bool> edge(96 * 96, false);
    for (int y = 1; y < 95; ++y)
        for (int x = 1; x < 95; ++x)
            for (int d = -1; d <= 1; d += 2)
                edge[y * 96 + x] = edge[y * 96 + x] || glm::length(cpu.at(x + d, y) - cpu.at(x, y)) > 0.2f ||
                                   glm::length(cpu.at(x, y + d) - cpu.at(x, y)) > 0.2f;
    const test::PixelAgreement agreement = test::compareWithReference(scene, gpu, 1e-3f, 1e-4f, edge);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 96 * 96 / 2);
}

TEST_F(EnvironmentHdrTest, MirrorSphereReflectsTheMapAsTheCpuReferenceDoes) {
    Scene scene = test::sphereUnderEnvironment(Material::withDefaults("mirror", BrdfModel::Mirror),
                                               EnvironmentKind::File, hdrPath());
    scene.environment.intensity = 0.7f;
    expectAgreesWithReference(scene, 96);
}

TEST_F(EnvironmentHdrTest, TheBackgroundShowsTheMapOnlyWhenAsked) {
    Scene scene = test::sphereUnderEnvironment(Material::withDefaults("m", BrdfModel::Lambert),
                                               EnvironmentKind::File, hdrPath());
    scene.background.color = {0.1f, 0.2f, 0.3f};
    expectAgreesWithReference(scene, 32);
    EXPECT_NE(renderGpu(scene, 32, 32).at(0, 0), scene.background.color);
    scene.environment.showAsBackground = false;
    EXPECT_EQ(renderGpu(scene, 32, 32).at(0, 0), scene.background.color);
}

TEST(EnvironmentSnapshot, GgxSphereInTheStudio) {
    const Scene scene = test::loadTestScene("scenes/environment_studio.json");
    auto images = test::sharedHeadless().render(scene, scene.width, scene.height);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const std::string golden = test::dataPath("goldens/environment_studio.png");
    const char* update = std::getenv("GLINT_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        ASSERT_TRUE(writeDisplayImage(images->display, golden).ok());
        return;
    }
    auto expected = readDisplayImage(golden);
    ASSERT_TRUE(expected.ok()) << expected.error().format() << " (create it with GLINT_UPDATE_GOLDENS=1)";
    const CompareResult result = compareImages(images->display, *expected);
    if (!result.passed) {
        const std::string directory = test::outputDirectory("snapshots");
        (void)writeDisplayImage(images->display, directory + "/environment_studio.actual.png");
        ADD_FAILURE() << result.summary() << "; actual written to " << directory;
    }
}

}  // namespace
}  // namespace glint
