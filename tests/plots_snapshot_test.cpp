// Snapshot goldens of the classroom plots (`glint render --overlay polar|lobe|albedo|fresnel|cmf`):
// each plot drawn on the headless canvas over a black 256×256 image, compared with
// goldens/plot_<name>.png; a .brdf material (sampled on the GPU) and a MERL table among them.
// Goldens change only with GLINT_UPDATE_GOLDENS=1.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "brdf/presets.h"
#include "cli/plot_overlay.h"
#include "cli/render_overlays.h"
#include "golden_support.h"
#include "gpu_test_support.h"
#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"

namespace glint {
namespace {

// The overlay named `overlay` (a plot row of cli/render_overlays.h) over a black 256×256 image.
void expectPlotMatchesGolden(const std::string& name, const Scene& scene, const char* overlay,
                             const PlotOverlayOptions& options) {
    test::sharedHeadless();  // makes the OSMesa context current and loads GL
    const RenderOverlay* plot = findRenderOverlay(overlay);
    ASSERT_NE(plot, nullptr);
    ASSERT_TRUE(plot->plot.has_value());
    const std::optional<ProbeResult> noProbe;
    auto image = drawRenderOverlays(std::span(&plot, 1), {scene, 256, 256, noProbe, options}, DisplayImage(256, 256));
    ASSERT_TRUE(image) << image.error().format();
    test::expectMatchesGolden("plot_" + name, *image);
}

PlotOverlayOptions plotSnapshotOptions(float incidenceDegrees, bool fromInside = false) {
    PlotOverlayOptions options;
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
    expectPlotMatchesGolden("polar_blinn", test::loadTestScene("scenes/blinn_point.json"), "polar", plotSnapshotOptions(30));
}

// Glass and mirror: delta arrows, the transmitted one below the surface line.
TEST(PlotSnapshot, PolarGlassTransmission) {
    expectPlotMatchesGolden("polar_glass", test::loadTestScene("scenes/glass_sphere.json"), "polar", plotSnapshotOptions(45));
}

TEST(PlotSnapshot, LobeBlinnPhong) {
    expectPlotMatchesGolden("lobe_blinn", test::loadTestScene("scenes/blinn_point.json"), "lobe", plotSnapshotOptions(30));
}

// The lecture-form Phong (k_s cos^n δ / cos θ') climbs past 1 at grazing: the red warning.
TEST(PlotSnapshot, AlbedoWarnsAboveOne) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    Material lecture = Material::withDefaults("lecture phong", BrdfModel::Phong);
    lecture.analytic()->values = {0.2f, 0.2f, 0.2f, 0.8f, 0.8f, 0.8f, 10.0f, 0.0f};
    scene.materials.push_back(lecture);
    scene.objects[1].materialIndex = static_cast<int>(scene.materials.size()) - 1;
    expectPlotMatchesGolden("albedo_phong", scene, "albedo", plotSnapshotOptions(60));
}

// Glass from inside: Brewster's angle and the critical angle marked.
TEST(PlotSnapshot, FresnelGlassFromInside) {
    expectPlotMatchesGolden("fresnel_glass", test::loadTestScene("scenes/glass_sphere.json"),
                            "fresnel", plotSnapshotOptions(45, true));
}

// Gold: a conductor, one curve set per channel.
TEST(PlotSnapshot, FresnelGoldPerChannel) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.materials = {findPreset("gold")->material()};
    for (SceneObject& object : scene.objects) object.materialIndex = 0;
    expectPlotMatchesGolden("fresnel_gold", scene, "fresnel", plotSnapshotOptions(45));
}

// blinn_point with the ball's material replaced by `material` (the floor's stays beside it).
Scene blinnPointWith(Material material) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.materials.push_back(std::move(material));
    scene.objects[0].materialIndex = static_cast<int>(scene.materials.size()) - 1;
    return scene;
}

// A .brdf material, sampled on the GPU through its own GLSL: a glossy lobe written here.
TEST(PlotSnapshot, PolarCustomBrdf) {
    const std::string path = test::outputDirectory("plot_snapshot") + "/gloss.brdf";
    std::ofstream(path) << "analytic\n::begin parameters\ncolor diffuse 0.3 0.2 0.1\nfloat exponent 1 200 30\n"
                           "::end parameters\n::begin shader\n"
                           "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n"
                           "    float lobe = pow(max(dot(reflect(-L, N), V), 0.0), exponent);\n"
                           "    return diffuse / 3.14159265 + vec3(0.5 * (exponent + 2.0) / 6.2831853 * lobe);\n}\n"
                           "::end shader\n";
    auto brdf = loadCustomBrdf(path);
    ASSERT_TRUE(brdf) << brdf.error().format();
    expectPlotMatchesGolden("polar_custom", blinnPointWith(customBrdfMaterial(*brdf)), "polar", plotSnapshotOptions(40));
}

// A MERL table, plotted from its lookup: a synthetic one, diffuse plus a lobe in θ_h.
TEST(PlotSnapshot, PolarMerlTable) {
    MerlTable table;
    table.reflectance.resize(3 * kMerlSamplesPerChannel);
    const glm::vec3 diffuse(0.25f, 0.35f, 0.5f);
    for (int c = 0; c < 3; ++c)
        for (int h = 0; h < kMerlThetaHalfBins; ++h) {
            const float halfIndex = static_cast<float>(h) / kMerlThetaHalfBins;  // θ_h = (index/90)² · π/2
            const float thetaHalf = halfIndex * halfIndex * 0.5f * kPi;
            const float value = diffuse[c] / kPi + 1.5f * std::exp(-thetaHalf * thetaHalf / 0.02f);
            const size_t first = (static_cast<size_t>(c) * kMerlThetaHalfBins + h) * kMerlThetaDifferenceBins * kMerlPhiDifferenceBins;
            std::fill_n(table.reflectance.begin() + first, kMerlThetaDifferenceBins * kMerlPhiDifferenceBins, value);
        }
    expectPlotMatchesGolden("polar_merl", blinnPointWith(measuredBrdfMaterial(makeMeasuredBrdf(std::move(table), "sheen.binary"))),
                            "polar", plotSnapshotOptions(40));
}

}  // namespace
}  // namespace glint
