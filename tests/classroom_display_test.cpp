// The classroom's display lessons on the CPU (core/display/quantisation.h, display_chain.h):
// quantisation to N levels, ordered dithering that keeps a tile's average, the clustered-dot
// halftone, gamma off, the levels ramp, and the scene-file keys with located errors. GPU twin:
// classroom_gpu_test.cpp.
#include <gtest/gtest.h>

#include <set>

#include "display/display_chain.h"
#include "located_error_support.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

// A constant radiance field through the chain, with no encoding (so encoded = radiance).
DisplayImage displayConstantField(float radiance, int levels, Dither dither, int size = 8) {
    RadianceImage field(size, size);
    std::fill(field.pixels.begin(), field.pixels.end(), radiance);
    DisplaySettings display;
    display.transfer = Transfer::Linear;
    display.levels = levels;
    display.dither = dither;
    return applyDisplayChain(field, display);
}

double displayMeanOf(const DisplayImage& image) {
    double sum = 0.0;
    for (uint8_t value : image.pixels) sum += value;
    return sum / static_cast<double>(image.pixels.size()) / 255.0;
}

TEST(ClassroomDisplay, BayerDitheredHalfGreyAveragesToHalfAtTwoLevels) {
    for (Dither dither : {Dither::Bayer2, Dither::Bayer4, Dither::Halftone}) {
        const DisplayImage image = displayConstantField(0.5f, 2, dither);
        for (uint8_t value : image.pixels) EXPECT_TRUE(value == 0 || value == 255);  // two levels only
        EXPECT_DOUBLE_EQ(displayMeanOf(image), 0.5) << kDitherIds[static_cast<int>(dither)];
    }
    // Without dither the same field rounds, all of it, to one level.
    EXPECT_DOUBLE_EQ(displayMeanOf(displayConstantField(0.5f, 2, Dither::None)), 1.0);
}

// Over a whole tile, an n×n ordered dither reproduces any value to 1/n² of a level.
TEST(ClassroomDisplay, DitheredTilesKeepTheAverageToASixteenthOfALevel) {
    for (int levels : {2, 3, 5, 16}) {
        const double step = 1.0 / (levels - 1);
        for (float value = 0.0f; value <= 1.0f; value += 0.0371f) {
            EXPECT_NEAR(displayMeanOf(displayConstantField(value, levels, Dither::Bayer4)), value, step / 16 + 1.0 / 255);
            EXPECT_NEAR(displayMeanOf(displayConstantField(value, levels, Dither::Halftone)), value, step / 16 + 1.0 / 255);
            EXPECT_NEAR(displayMeanOf(displayConstantField(value, levels, Dither::Bayer2)), value, step / 4 + 1.0 / 255);
        }
    }
}

TEST(ClassroomDisplay, LevelsQuantiseToEquallySpacedValues) {
    std::set<int> seen;
    for (float value = 0.0f; value <= 1.0f; value += 0.001f)
        seen.insert(quantize8(quantiseToLevels(value, 4, 0.5f)));
    EXPECT_EQ(seen, (std::set<int>{0, 85, 170, 255}));
    // 256 levels without dither is the ordinary 8-bit rounding.
    for (float value = 0.0f; value <= 1.0f; value += 0.0007f)
        EXPECT_EQ(quantize8(quantiseToLevels(value, 256, 0.5f)), quantize8(value)) << value;
}

// The clustered-dot screen prints a light grey (0.75) as one dark 2×2 dot per tile, as ink on
// paper; Bayer 4×4 disperses the same four dark pixels so that none touches another along an edge.
TEST(ClassroomDisplay, HalftoneClustersWhatBayerDisperses) {
    auto darkPixels = [](Dither dither) {
        const DisplayImage image = displayConstantField(0.75f, 2, dither, 4);
        std::set<std::pair<int, int>> dark;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                if (image.pixels[(y * 4 + x) * 3] == 0) dark.insert({x, y});
        return dark;
    };
    const auto halftone = darkPixels(Dither::Halftone);
    ASSERT_EQ(halftone.size(), 4u);
    const auto [minX, minY] = *halftone.begin();
    EXPECT_EQ(halftone, (std::set<std::pair<int, int>>{{minX, minY}, {minX + 1, minY}, {minX, minY + 1}, {minX + 1, minY + 1}}));
    const auto bayer = darkPixels(Dither::Bayer4);
    ASSERT_EQ(bayer.size(), 4u);
    for (const auto& [x, y] : bayer) {
        EXPECT_FALSE(bayer.count({x + 1, y}));
        EXPECT_FALSE(bayer.count({x, y + 1}));
    }
}

TEST(ClassroomDisplay, GammaOffLeavesTheValueLinear) {
    DisplaySettings display;
    display.transfer = Transfer::Linear;
    EXPECT_FLOAT_EQ(encodeForDisplay(0.5f, display), 0.5f);
    display.transfer = Transfer::Gamma;
    display.gamma = 2.0f;
    EXPECT_FLOAT_EQ(encodeForDisplay(0.25f, display), 0.5f);
}

TEST(ClassroomDisplay, TheLevelsRampShowsEveryLevelAlongTheBottom) {
    RadianceImage black(64, 32);
    DisplaySettings display;
    display.transfer = Transfer::Linear;
    display.levels = 4;
    display.levelsRamp = true;
    const DisplayImage image = applyDisplayChain(black, display);
    std::set<int> rampValues;
    for (int x = 0; x < 64; ++x) rampValues.insert(image.pixels[((32 - 1) * 64 + x) * 3]);
    EXPECT_EQ(rampValues, (std::set<int>{0, 85, 170, 255}));
    EXPECT_EQ(image.pixels[((32 - levelsRampRows(32) - 1) * 64 + 63) * 3], 0);  // above the strip: the image
    EXPECT_EQ(image.pixels[((32 - levelsRampRows(32)) * 64 + 63) * 3], 255);    // its top row: the ramp
}

TEST(ClassroomDisplay, SceneKeysRoundTripAndBadValuesAreLocated) {
    Scene scene = defaultScene();
    scene.display.transfer = Transfer::Linear;
    scene.display.levels = 6;
    scene.display.dither = Dither::Halftone;
    scene.display.levelsRamp = true;
    auto reread = parseScene(sceneToJson(scene).dump(2), "levels.json");
    ASSERT_TRUE(reread.ok()) << reread.error().format();
    EXPECT_EQ(reread->display.transfer, Transfer::Linear);
    EXPECT_EQ(reread->display.levels, 6);
    EXPECT_EQ(reread->display.dither, Dither::Halftone);
    EXPECT_TRUE(reread->display.levelsRamp);
    const std::string head = "{\n  \"format\": \"glint-scene\", \"version\": 1,\n";
    test::expectLocatedError(head + "  \"display\": { \"levels\": 1 }\n}\n", 3, "levels", "");
    test::expectLocatedError(head + "  \"display\": { \"levels\": 2.5 }\n}\n", 3, "levels", "");
    test::expectLocatedError(head + "  \"display\": { \"dither\": \"floyd\" }\n}\n", 3, "dither", "");
    test::expectLocatedError(head + "  \"display\": { \"transfer\": \"log\" }\n}\n", 3, "transfer", "");
    test::expectLocatedError(head + "  \"display\": { \"levels_ramp\": 1 }\n}\n", 3, "levels_ramp", "");
}

}  // namespace
}  // namespace glint
