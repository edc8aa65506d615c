// The classroom on the GPU: the display lessons (levels, dither, halftone, gamma off, the levels
// ramp) in the fused radiance pass and the separate display pass equal the CPU chain pixel by
// pixel; the split compare shows material A left and B right of the divider exactly as their own
// renders do; snapshot goldens of the dither lesson and the split, grid and interpolation views.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "classroom/compare_render.h"
#include "cli/classroom_options.h"
#include "display/display_chain.h"
#include "golden_support.h"
#include "gpu_test_support.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

// Channels where the GPU's 8-bit image differs from the CPU chain applied to the GPU's own radiance.
long classroomMismatches(const RenderedImages& images, const DisplaySettings& display) {
    const DisplayImage cpu = applyDisplayChain(images.radiance, display);
    long differing = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) differing += cpu.pixels[i] != images.display.pixels[i];
    return differing;
}

TEST(ClassroomGpu, DisplayLessonsEqualTheCpuChainPixelByPixel) {
    Scene scene = defaultScene();
    scene.background.kind = BackgroundKind::Sky;  // smooth gradients cross many thresholds
    struct Lesson { Transfer transfer; int levels; Dither dither; bool ramp; };
    const Lesson lessons[] = {{Transfer::Linear, 2, Dither::Bayer2, false}, {Transfer::Srgb, 4, Dither::Bayer4, false},
                              {Transfer::Gamma, 3, Dither::Halftone, false}, {Transfer::Srgb, 8, Dither::Bayer4, true},
                              {Transfer::Linear, 256, Dither::None, true}};
    Renderer& renderer = test::sharedHeadless().renderer();
    for (const Lesson& lesson : lessons) {
        scene.display.transfer = lesson.transfer;
        scene.display.gamma = 1.8f;
        scene.display.levels = lesson.levels;
        scene.display.dither = lesson.dither;
        scene.display.levelsRamp = lesson.ramp;
        SCOPED_TRACE(std::to_string(lesson.levels) + " levels, " + kDitherIds[static_cast<int>(lesson.dither)]);
        auto fused = test::sharedHeadless().render(scene, 96, 64);  // fused unless the ramp is on
        ASSERT_TRUE(fused.ok()) << fused.error().format();
        EXPECT_EQ(classroomMismatches(*fused, scene.display), 0);
        renderer.options().fuseDisplay = false;
        auto separate = test::sharedHeadless().render(scene, 96, 64);
        renderer.options().fuseDisplay = true;
        ASSERT_TRUE(separate.ok()) << separate.error().format();
        EXPECT_EQ(classroomMismatches(*separate, scene.display), 0);
    }
}

TEST(ClassroomGpu, SplitShowsMaterialALeftAndBRightOfTheDivider) {
    const Scene scene = defaultScene();
    auto clay = loadMaterial(test::dataPath("snapshots/clay.json"));
    auto plastic = loadMaterial(test::dataPath("snapshots/red_plastic.json"));
    ASSERT_TRUE(clay.ok() && plastic.ok());
    const Scene left = withSubjectMaterial(scene, 0, *clay), right = withSubjectMaterial(scene, 0, *plastic);
    const int width = 128, height = 96;
    auto split = renderCompare(test::sharedHeadless().renderer(), {{left, ""}, {right, ""}}, CompareLayout::Split, width, height, 0.5f);
    ASSERT_TRUE(split.ok()) << split.error().format();
    auto alone = [&](const Scene& paneScene) {
        auto images = test::sharedHeadless().render(paneScene, width, height);
        EXPECT_TRUE(images.ok());
        return images.ok() ? images->display : DisplayImage(width, height);
    };
    const DisplayImage leftAlone = alone(left), rightAlone = alone(right);
    long compared = 0, differing = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (std::abs(x - width / 2) <= kDividerThickness) continue;  // the divider line
            const DisplayImage& expected = x < width / 2 ? leftAlone : rightAlone;
            for (int c = 0; c < 3; ++c) {
                const size_t i = (static_cast<size_t>(y) * width + x) * 3 + c;
                ++compared;
                differing += split->display.pixels[i] != expected.pixels[i];
            }
        }
    EXPECT_EQ(differing, 0) << "of " << compared;
    EXPECT_NE(leftAlone.pixels, rightAlone.pixels);  // the two materials do look different
    const size_t onDivider = (static_cast<size_t>(height / 2) * width + width / 2) * 3;
    EXPECT_EQ(split->display.pixels[onDivider], kDividerColor.r);
    EXPECT_EQ(split->display.pixels[onDivider + 2], kDividerColor.b);
}

// `glint render`'s options turned into panes, rendered and checked against a golden.
void expectCompareGolden(const std::string& golden, const Scene& scene, const std::vector<std::string>& arguments, int width, int height) {
    ClassroomOptions options;
    CLI::App render;
    options.addTo(render);
    std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 takes them last first
    ASSERT_NO_THROW(render.parse(reversed));
    ASSERT_EQ(options.check(), "");
    auto panes = options.paneScenes(scene);
    ASSERT_TRUE(panes.ok()) << panes.error().format();
    auto images = renderCompare(test::sharedHeadless().renderer(), *panes, options.chosenLayout(), width, height,
                                options.divider.value_or(0.5f));
    ASSERT_TRUE(images.ok()) << images.error().format();
    test::expectMatchesGolden(golden, images->display);
}

TEST(ClassroomSnapshot, Split) {
    expectCompareGolden("classroom_split", defaultScene(),
                        {"--compare", test::dataPath("snapshots/clay.json") + ",preset:gold", "--divider", "0.4"}, 160, 120);
}

TEST(ClassroomSnapshot, Grid) {
    expectCompareGolden("classroom_grid", defaultScene(),
                        {"--compare", test::dataPath("snapshots/clay.json") + ",preset:gold,model:oren_nayar," +
                                          test::dataPath("snapshots/red_plastic.json")},
                        160, 120);
}

TEST(ClassroomSnapshot, Interpolation) {
    expectCompareGolden("classroom_interpolation", defaultScene(), {"--compare-interpolation", "--tessellation", "10x6"}, 192, 80);
}

TEST(ClassroomSnapshot, DitherAndLevelsRamp) {
    Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    scene.display.levels = 4;
    scene.display.dither = Dither::Bayer4;
    scene.display.levelsRamp = true;
    auto images = test::sharedHeadless().render(scene, 96, 96);
    ASSERT_TRUE(images.ok()) << images.error().format();
    test::expectMatchesGolden("classroom_dither", images->display);
}

}  // namespace
}  // namespace glint
