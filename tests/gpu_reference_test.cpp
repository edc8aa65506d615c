// The OpenGL renderer (through OSMesa) against the radiometry and against the CPU reference,
// pixel by pixel on linear float output: the test that keeps the GLSL twins honest.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>

#include "display/display_chain.h"
#include "gl/gl_loader.h"
#include "gpu_test_support.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

TEST(GpuRenderer, LambertSunMatchesTheRadiometry) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    auto images = test::sharedHeadless().render(scene, 256, 256);
    ASSERT_TRUE(images.ok()) << images.error().format();
    // Through the EXR file, as a user would read it.
    const std::string path = test::outputDirectory("gpu") + "/lambert_sun.exr";
    ASSERT_TRUE(writeRenderedImage(*images, path).ok());
    auto exr = readRadianceImage(path);
    ASSERT_TRUE(exr.ok()) << exr.error().format();
    EXPECT_NEAR(exr->at(128, 128).r, 0.5f, 1e-3f);
    const float pixelSize = 2.2f / 256.0f;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const float px = -1.1f + (x + 0.5f) * pixelSize, py = 1.1f - (y + 0.5f) * pixelSize;
            const float r2 = px * px + py * py;
            if (r2 > 0.95f * 0.95f) continue;
            ASSERT_NEAR(exr->at(x, y).g, 0.5f * std::sqrt(1.0f - r2), 1e-4f) << x << "," << y;
        }
}

TEST(GpuRenderer, LambertSunMatchesTheCpuReference) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    auto images = test::sharedHeadless().render(scene, 256, 256);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const auto agreement = test::compareWithReference(scene, images->radiance);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 60000);
    EXPECT_LT(agreement.excluded, 3000);
}

TEST(GpuRenderer, BlinnPhongPointLightMatchesTheCpuReference) {
    const Scene scene = test::loadTestScene("scenes/blinn_point.json");
    auto images = test::sharedHeadless().render(scene, scene.width, scene.height);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const auto agreement = test::compareWithReference(scene, images->radiance);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 40000);
}

TEST(GpuRenderer, EveryBlinnFormMatchesTheCpuReference) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    for (float form = 0; form < 4; ++form) {
        scene.materials[0].analytic()->values[7] = form;
        scene.materials[1].analytic()->values[7] = form;
        auto images = test::sharedHeadless().render(scene, 128, 96);
        ASSERT_TRUE(images.ok()) << images.error().format();
        const auto agreement = test::compareWithReference(scene, images->radiance);
        EXPECT_EQ(agreement.disagreeing, 0) << "form " << form << ": " << agreement.firstDisagreement;
    }
}

TEST(GpuRenderer, PngMatchesTheCpuDisplayChain) {
    Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    // +2.5 EV pushes the lit sphere above 1 so the tone curves differ from a clip.
    // A saturated orange albedo: PBR Neutral works on the whole colour, not channel by channel.
    scene.materials[0].analytic()->values = {0.9f, 0.35f, 0.05f};
    for (ToneMap toneMap : {ToneMap::None, ToneMap::Reinhard, ToneMap::AcesFilmic, ToneMap::PbrNeutral}) {
        for (Transfer transfer : {Transfer::Srgb, Transfer::Gamma}) {
            scene.display = {2.5f, transfer, 2.2f, toneMap};
            auto images = test::sharedHeadless().render(scene, 64, 64);
            ASSERT_TRUE(images.ok());
            const DisplayImage cpu = applyDisplayChain(images->radiance, scene.display);
            int worst = 0;
            for (size_t i = 0; i < cpu.pixels.size(); ++i)
                worst = std::max(worst, std::abs(cpu.pixels[i] - images->display.pixels[i]));
            EXPECT_LE(worst, 1) << "the display pass is the twin of display_chain.h (tone map "
                                << static_cast<int>(toneMap) << ")";
        }
    }
}

TEST(GpuRenderer, MsaaSmoothsTheSilhouette) {
    Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    scene.msaaSamples = 4;
    auto images = test::sharedHeadless().render(scene, 64, 64);
    ASSERT_TRUE(images.ok()) << images.error().format();
    std::set<int> silhouetteLevels;
    for (int x = 0; x < 64; ++x) silhouetteLevels.insert(images->display.pixels[(32 * 64 + x) * 3]);
    // With 4 samples, edge pixels take partial-coverage values; the interior is unchanged.
    Scene single = scene;
    single.msaaSamples = 1;
    auto reference = test::sharedHeadless().render(single, 64, 64);
    ASSERT_TRUE(reference.ok());
    EXPECT_NEAR(images->radiance.at(32, 32).r, reference->radiance.at(32, 32).r, 1e-6f);
    long differing = 0;
    for (size_t i = 0; i < images->display.pixels.size(); ++i) differing += images->display.pixels[i] != reference->display.pixels[i];
    EXPECT_GT(differing, 30) << "edge pixels blend with the background";
    EXPECT_TRUE(takeGlErrors("msaa test").ok());
}

TEST(GpuRenderer, PlaneEdgeFadeMatchesTheCpuReference) {
    // A faded floor seen from above under a sky background: its middle is the floor's own
    // radiance, its corners the background's, the band between the twins' smoothstep.
    Scene scene;
    scene.camera.position = {0.0f, 6.0f, 0.01f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.background.kind = BackgroundKind::Sky;
    scene.materials = {Material::withDefaults("floor", BrdfModel::Lambert)};
    PlaneShape floor{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {4.0f, 4.0f}};
    floor.edgeFade = 0.5f;
    scene.objects.push_back({"floor", floor, 0, SurfaceInterpolation::Phong});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    scene.lights = {sun};
    auto images = test::sharedHeadless().render(scene, 96, 96);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const auto agreement = test::compareWithReference(scene, images->radiance);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 3000);
    // Near a corner the plane shows the background: the fade reached 1 there.
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(1.0f));
    const Ray nearCorner = primaryRay(inverse, 48 + 36 + 0.5f, 48 + 36 + 0.5f, 96, 96);
    ASSERT_TRUE(intersectScene(scene, nearCorner).has_value());
    const glm::vec3 sky = backgroundRadiance(scene.background, nearCorner.direction);
    EXPECT_NEAR(images->radiance.at(48 + 36, 48 + 36).g, sky.g, 1e-3f * sky.g);
}

TEST(GpuRenderer, CameraInsideASphereSeesItsInside) {
    // The sphere proxy's back faces are culled only when the whole proxy lies beyond the near
    // plane; from inside, they are what draws the (two-sided) inner surface.
    Scene scene;
    scene.materials = {Material::withDefaults("inside", BrdfModel::Lambert)};
    scene.objects.push_back({"room", SphereShape{{0, 0, 0}, 3.0f}, 0});
    scene.camera.position = {0.5f, 0.2f, 1.0f};
    scene.camera.target = {0, 0, -1};
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0, 1, 0};
    scene.lights = {bulb};
    for (const glm::vec3 position : {glm::vec3(0.5f, 0.2f, 1.0f), glm::vec3(0.0f, 0.0f, 7.0f), glm::vec3(0.0f, 0.0f, 3.01f)}) {
        scene.camera.position = position;
        auto images = test::sharedHeadless().render(scene, 64, 48);
        ASSERT_TRUE(images.ok()) << images.error().format();
        const auto agreement = test::compareWithReference(scene, images->radiance);
        EXPECT_EQ(agreement.disagreeing, 0) << "camera at z = " << position.z << ": " << agreement.firstDisagreement;
        EXPECT_GT(agreement.compared, 1000);
    }
}

TEST(GpuRenderer, ShaderErrorsNameTheFileAndLine) {
    const std::string directory = test::outputDirectory("broken_shaders");
    std::filesystem::copy(std::string(GLINT_TEST_DATA_DIR) + "/../shaders", directory,
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
    std::ofstream(directory + "/brdf/lambert.glsl") << "// broken on purpose\n\nvec3 evalLambert(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {\n    return undefinedThing;\n}\n";
    auto platform = OsMesaPlatform::create();
    ASSERT_TRUE(platform.ok());
    auto renderer = Renderer::create(**platform, ShaderSources(directory));
    ASSERT_TRUE(renderer.ok()) << renderer.error().format();
    const Status status = (*renderer)->renderRadiance(test::loadTestScene("scenes/lambert_sun.json"), 16, 16);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("brdf/lambert.glsl:4:"), std::string::npos) << status.error().format();
    EXPECT_NE((*renderer)->shaderError().find("undefinedThing"), std::string::npos);
}

// A shader broken while Glint runs: the last good program keeps drawing, the error (named in the
// included file, whatever source number the driver reports) stays until the file compiles again.
TEST(GpuRenderer, AFailedHotReloadKeepsItsErrorUntilTheFileCompiles) {
    const std::string directory = test::outputDirectory("hot_reload_shaders");
    std::filesystem::copy(std::string(GLINT_TEST_DATA_DIR) + "/../shaders", directory,
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
    const std::string lambert = directory + "/brdf/lambert.glsl";
    const std::string good = readTextFile(lambert).value();
    auto platform = OsMesaPlatform::create();
    ASSERT_TRUE(platform.ok());
    auto renderer = Renderer::create(**platform, ShaderSources(directory));
    ASSERT_TRUE(renderer.ok()) << renderer.error().format();
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    ASSERT_TRUE((*renderer)->renderRadiance(scene, 16, 16).ok());
    const auto saveAt = [&](const std::string& text, int secondsLater) {  // a later time than the build saw
        std::ofstream(lambert) << text;
        std::filesystem::last_write_time(lambert, std::filesystem::file_time_type::clock::now() + std::chrono::seconds(secondsLater));
    };
    std::string broken = good;
    broken.insert(broken.find('{', broken.find("vec3 evalLambert(")) + 1, "\n    float q = undefinedThing;");
    saveAt(broken, 2);
    EXPECT_TRUE((*renderer)->reloadChangedShaders());
    ASSERT_TRUE((*renderer)->renderRadiance(scene, 16, 16).ok()) << "the last good program draws";
    EXPECT_NE((*renderer)->shaderError().find("brdf/lambert.glsl:"), std::string::npos) << (*renderer)->shaderError();
    EXPECT_NE((*renderer)->shaderError().find("undefinedThing"), std::string::npos);
    saveAt(good, 4);
    EXPECT_TRUE((*renderer)->reloadChangedShaders());
    ASSERT_TRUE((*renderer)->renderRadiance(scene, 16, 16).ok());
    EXPECT_EQ((*renderer)->shaderError(), "");
}

}  // namespace
}  // namespace glint
