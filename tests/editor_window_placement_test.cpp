// Window placement (app/editor/window_placement.h): a window opens where it covers no reserved
// rectangle, inside the bounds, preferring the top-right corner; it shrinks (not below its
// minimum) before covering one, and covers the least when nothing fits.
#include <gtest/gtest.h>

#include "editor/window_placement.h"

namespace glint {
namespace {

const ScreenRect kScreen{0, 30, 1000, 700};

ScreenRect placed(const WindowPlacement& placement) {
    return {placement.position.x, placement.position.y, placement.size.x, placement.size.y};
}

TEST(WindowPlacement, AnEmptyScreenPutsTheWindowTopRight) {
    const WindowPlacement placement = placeWindow(ImVec2(300, 200), ImVec2(100, 100), kScreen, {});
    EXPECT_FLOAT_EQ(placement.position.x, 700.0f);
    EXPECT_FLOAT_EQ(placement.position.y, 30.0f);
    EXPECT_FLOAT_EQ(placement.size.x, 300.0f);
}

TEST(WindowPlacement, ReservedRectanglesAreNotCoveredAndSoftOnesAreAvoided) {
    const PlacementObstacle obstacles[] = {{{650, 30, 350, 250}, 1.0f, true},    // the probe readout, top right
                                           {{10, 40, 400, 200}, 1.0f, true},     // the lesson note, top left
                                           {{0, 300, 500, 430}, 5.0f, false}};   // something to avoid if possible
    const ScreenRect rect = placed(placeWindow(ImVec2(300, 200), ImVec2(100, 100), kScreen, obstacles));
    EXPECT_TRUE(kScreen.contains(rect));
    EXPECT_EQ(rect.overlapArea(obstacles[0].rect), 0.0f);
    EXPECT_EQ(rect.overlapArea(obstacles[1].rect), 0.0f);
    EXPECT_EQ(rect.overlapArea(obstacles[2].rect), 0.0f);
}

TEST(WindowPlacement, AWindowShrinksBeforeItCoversSomethingReservedButNotBelowItsMinimum) {
    // Free: a 400 × 700 band on the right.
    const PlacementObstacle note[] = {{{0, 30, 600, 700}, 1.0f, true}};
    const WindowPlacement shrunk = placeWindow(ImVec2(600, 500), ImVec2(300, 300), kScreen, note);
    EXPECT_LE(shrunk.size.x, 400.0f);
    EXPECT_GE(shrunk.size.x, 300.0f);
    EXPECT_EQ(placed(shrunk).overlapArea(note[0].rect), 0.0f);
    EXPECT_TRUE(kScreen.contains(placed(shrunk)));

    // Its minimum does not fit the band: full size, covering as little as it can.
    const WindowPlacement covering = placeWindow(ImVec2(600, 500), ImVec2(500, 500), kScreen, note);
    EXPECT_FLOAT_EQ(covering.size.x, 600.0f);
    EXPECT_FLOAT_EQ(placed(covering).overlapArea(note[0].rect), 200.0f * 500.0f);
}

TEST(WindowPlacement, AWindowLargerThanTheScreenIsFittedToIt) {
    const ScreenRect rect = placed(placeWindow(ImVec2(3000, 2000), ImVec2(100, 100), kScreen, {}));
    EXPECT_TRUE(kScreen.contains(rect));
    EXPECT_FLOAT_EQ(rect.width, 1000.0f);
    EXPECT_FLOAT_EQ(rect.height, 700.0f);
}

}  // namespace
}  // namespace glint
