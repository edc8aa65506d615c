// Snapshot tests: headless renders compared with golden PNGs through OpenImageIO, with the
// tolerance of docs/architecture.md. On failure the actual, expected and ×16 difference images are written
// beside the test's output. Goldens change only with GLINT_UPDATE_GOLDENS=1.
#include <gtest/gtest.h>

#include <cstdlib>

#include "golden_support.h"
#include "gpu_test_support.h"
#include "brdf/presets.h"
#include "classroom/surface_probe.h"
#include "cli/render_overlays.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "test_support.h"

namespace glint {
namespace {

using test::expectMatchesGolden;

TEST(Snapshot, LambertSun) {
    auto images = test::sharedHeadless().render(test::loadTestScene("scenes/lambert_sun.json"), 256, 256);
    ASSERT_TRUE(images.ok()) << images.error().format();
    expectMatchesGolden("lambert_sun", images->display);
}

// tests/scenes/<name>.json at its own output size against goldens/<name>.png.
void expectSceneMatchesGolden(const std::string& name) {
    const Scene scene = test::loadTestScene("scenes/" + name + ".json");
    auto images = test::sharedHeadless().render(scene, scene.width, scene.height);
    ASSERT_TRUE(images.ok()) << images.error().format();
    expectMatchesGolden(name, images->display);
}

TEST(Snapshot, BlinnPointLight) { expectSceneMatchesGolden("blinn_point"); }

TEST(Snapshot, SpotLights) { expectSceneMatchesGolden("spot_light"); }

TEST(Snapshot, GlassAndMirrorUnderTheSky) { expectSceneMatchesGolden("glass_sphere"); }

// A ball over a floor under a shadowed sun, spot and bulb (2D, perspective and cube shadow maps).
TEST(Snapshot, Shadows) { expectSceneMatchesGolden("shadows"); }

TEST(Snapshot, DefaultScene) {
    const Scene scene = defaultScene();
    auto images = test::sharedHeadless().render(scene, 320, 240);
    ASSERT_TRUE(images.ok()) << images.error().format();
    expectMatchesGolden("default_scene", images->display);
}

// One sphere per model under a point and a directional light: the preset or parameters that show
// what the model is for (goldens/model_<id>.png).
TEST(Snapshot, OneSpherePerModel) {
    Scene scene = test::loadTestScene("scenes/model_sphere.json");
    // A bright Lommel-Seeliger moon with a retroreflective lobe (k_r = 0.6, m = 8) towards the bulb.
    Material moon = Material::withDefaults("retroreflective", BrdfModel::Retroreflective);
    moon.analytic()->values = {0.9f, 0.9f, 0.9f, 1.0f, 0.7f, 0.6f, 0.6f, 0.2f, 8.0f};
    const std::pair<BrdfModel, Material> samples[] = {
        {BrdfModel::Lambert, Material::withDefaults("lambert", BrdfModel::Lambert)},
        {BrdfModel::BlinnPhong, Material::withDefaults("blinn_phong", BrdfModel::BlinnPhong)},
        {BrdfModel::OrenNayar, Material::withDefaults("oren_nayar", BrdfModel::OrenNayar)},
        {BrdfModel::Phong, Material::withDefaults("phong", BrdfModel::Phong)},
        {BrdfModel::CookTorrance, findPreset("gold")->material()},
        {BrdfModel::GgxAnisotropic, Material::withDefaults("ggx_anisotropic", BrdfModel::GgxAnisotropic)},
        {BrdfModel::Ward, Material::withDefaults("ward", BrdfModel::Ward)},
        {BrdfModel::Retroreflective, moon},
        {BrdfModel::Mirror, Material::withDefaults("mirror", BrdfModel::Mirror)},
        {BrdfModel::Glass, Material::withDefaults("glass", BrdfModel::Glass)},
        {BrdfModel::OpenPbr, findPreset("car_paint")->material()},
    };
    ASSERT_EQ(std::size(samples), allModels().size());
    const Background constant = scene.background;
    Background sky;
    sky.kind = BackgroundKind::Sky;  // mirror and glass show what they reflect and refract
    for (const auto& [model, material] : samples) {
        SCOPED_TRACE(modelInfo(model).id);
        ASSERT_EQ(material.analytic()->model, model);
        scene.background = modelInfo(model).glslTransport ? sky : constant;
        scene.materials = {material};
        scene.materials[0].name = "sample";
        auto images = test::sharedHeadless().render(scene, scene.width, scene.height);
        ASSERT_TRUE(images.ok()) << images.error().format();
        expectMatchesGolden(std::string("model_") + modelInfo(model).id, images->display);
    }
}

// The classroom surface probe's arrows and angles (app/classroom/probe_overlay.h) on the ball of
// blinn_point, drawn as `glint render --overlay probe --probe 105,110` draws them.
TEST(Snapshot, SurfaceProbeOverlay) {
    const Scene scene = test::loadTestScene("scenes/blinn_point.json");
    auto images = test::sharedHeadless().render(scene, scene.width, scene.height);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const std::optional<ProbeResult> probe = probeSurface(scene, 105, 110, scene.width, scene.height);
    ASSERT_TRUE(probe->hitSurface);
    const RenderOverlay* overlays[] = {findRenderOverlay("probe")};
    ASSERT_NE(overlays[0], nullptr);
    auto composite = drawRenderOverlays(overlays, {scene, scene.width, scene.height, probe}, images->display);
    ASSERT_TRUE(composite.ok()) << composite.error().format();
    expectMatchesGolden("surface_probe_overlay", *composite);
}

TEST(ImageCompare, ToleranceFollowsTheDesign) {
    DisplayImage expected(100, 100), actual(100, 100);
    EXPECT_TRUE(compareImages(actual, expected).passed);
    actual.pixels[0] = 5;  // at the tolerance: not a failing pixel
    EXPECT_EQ(compareImages(actual, expected).failingPixels, 0);
    actual.pixels[0] = 6;  // 1 of 10,000 pixels = 0.01% ≤ 0.1%
    EXPECT_EQ(compareImages(actual, expected).failingPixels, 1);
    EXPECT_TRUE(compareImages(actual, expected).passed);
    for (int i = 0; i < 11; ++i) actual.pixels[i * 3 + 1] = 40;  // 11 pixels = 0.11%
    const CompareResult result = compareImages(actual, expected);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.maxChannelDifference, 40);
    EXPECT_EQ(differenceImage(actual, expected).pixels[1], 255);
    EXPECT_EQ(differenceImage(actual, expected).pixels[0], 96);
    EXPECT_FALSE(compareImages(DisplayImage(10, 10), expected).passed);
}

}  // namespace
}  // namespace glint
