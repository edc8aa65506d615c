// Snapshot goldens of the classroom plots (`glint render --overlay polar|lobe|albedo|fresnel|cmf`):
// each plot drawn on the headless canvas over a black 256×256 image, compared
// with goldens/plot_<name>.png. Goldens change only with GLINT_UPDATE_GOLDENS=1.
#include <gtest/gtest.h>

#include "brdf/presets.h"
#include "cli/plot_overlay.h"
#include "cli/render_overlays.h"
#include "golden_support.h"
#include "gpu_test_support.h"

namespace glint {
namespace {

void expectPlotMatchesGolden(const std::string& name, const Scene& scene, const PlotOverlayOptions& options) {
    test::sharedHeadless();  // makes the OSMesa context current and loads GL
    DisplayImage image(256, 256);
    const Status drawn = drawPlotOverlay(scene, options, image);
    ASSERT_TRUE(drawn) << drawn.error().format();
    test::expectMatchesGolden("plot_" + name, image);
}

PlotOverlayOptions plotSnapshotOptions(PlotOverlayKind kind, float incidenceDegrees, bool fromInside = false) {
    PlotOverlayOptions options;
    options.kind = kind;
    options.incidenceDegrees = incidenceDegrees;
    options.fromInside = fromInside;
    return options;
}

// The CIE 1931 colour matching functions, as `glint render --overlay cmf` draws them.
TEST(PlotSnapshot, ColourMatchingFunctions) {
    test::sharedHeadless();
    const Scene scene = test::loadTestScene("scenes/blinn_point.json");
    const RenderOverlay* cmf = findRenderOverlay("cmf");
    ASSERT_NE(cmf, nullptr);
    const std::optional<ProbeResult> noProbe;
    auto image = drawRenderOverlays(std::span(&cmf, 1), {scene, 256, 256, noProbe}, DisplayImage(256, 256));
    ASSERT_TRUE(image) << image.error().format();
    test::expectMatchesGolden("plot_cmf", *image);
}

// Two Blinn-Phong materials (red plastic, floor) overlaid.
TEST(PlotSnapshot, PolarBlinnPhong) {
    expectPlotMatchesGolden("polar_blinn", test::loadTestScene("scenes/blinn_point.json"), plotSnapshotOptions(PlotOverlayKind::Polar, 30));
}

// Glass and mirror: delta arrows, the transmitted one below the surface line.
TEST(PlotSnapshot, PolarGlassTransmission) {
    expectPlotMatchesGolden("polar_glass", test::loadTestScene("scenes/glass_sphere.json"), plotSnapshotOptions(PlotOverlayKind::Polar, 45));
}

TEST(PlotSnapshot, LobeBlinnPhong) {
    expectPlotMatchesGolden("lobe_blinn", test::loadTestScene("scenes/blinn_point.json"), plotSnapshotOptions(PlotOverlayKind::Lobe, 30));
}

// The lecture-form Phong (k_s cos^n δ / cos θ') climbs past 1 at grazing: the red warning.
TEST(PlotSnapshot, AlbedoWarnsAboveOne) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    Material lecture = Material::withDefaults("lecture phong", BrdfModel::Phong);
    lecture.values = {0.2f, 0.2f, 0.2f, 0.8f, 0.8f, 0.8f, 10.0f, 0.0f};
    scene.materials.push_back(lecture);
    scene.objects[1].materialIndex = static_cast<int>(scene.materials.size()) - 1;
    expectPlotMatchesGolden("albedo_phong", scene, plotSnapshotOptions(PlotOverlayKind::Albedo, 60));
}

// Glass from inside: Brewster's angle and the critical angle marked.
TEST(PlotSnapshot, FresnelGlassFromInside) {
    expectPlotMatchesGolden("fresnel_glass", test::loadTestScene("scenes/glass_sphere.json"),
                            plotSnapshotOptions(PlotOverlayKind::Fresnel, 45, true));
}

// Gold: a conductor, one curve set per channel.
TEST(PlotSnapshot, FresnelGoldPerChannel) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.materials = {findPreset("gold")->material()};
    for (SceneObject& object : scene.objects) object.materialIndex = 0;
    expectPlotMatchesGolden("fresnel_gold", scene, plotSnapshotOptions(PlotOverlayKind::Fresnel, 45));
}

}  // namespace
}  // namespace glint
