// What the editor puts on screen each iteration (editor/viewport_presenter.h), without a window:
// the damaged rectangles and what each shows of a viewport refined in bands.
#include <gtest/gtest.h>

#include "editor/viewport_presenter.h"

namespace glint {
namespace {

bool same(const PixelRegion& a, const PixelRegion& b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

// A 400×300 viewport at (100, 20) in a 640×360 window, last copied at the same size.
DamageInput steadyViewport() {
    DamageInput input;
    input.viewport = {100, 20, 400, 300};
    input.copiedBefore = input.viewport;
    input.window = {0, 0, 640, 360};
    return input;
}

TEST(ViewportPresenter, NothingChangedDamagesNothing) { EXPECT_TRUE(screenDamage(steadyViewport()).empty()); }

TEST(ViewportPresenter, AnExposedWindowIsDrawnWhole) {
    DamageInput input = steadyViewport();
    input.ui = {{0, 0, 10, 10}};
    input.rendered = true;
    input.whole = true;
    const auto damage = screenDamage(input);
    ASSERT_EQ(damage.size(), 1u);
    EXPECT_TRUE(same(damage[0], input.window));
}

TEST(ViewportPresenter, AChangedMaterialDamagesOnlyTheScaledPixelsItDrew) {
    DamageInput input = steadyViewport();
    input.rendered = true;
    input.scale = input.scaleBefore = 2;
    input.drawnPixels = PixelRegion{10, 5, 20, 30};  // rendered pixels
    input.ui = {{600, 340, 20, 10}};                 // the status bar, apart
    const auto damage = screenDamage(input);
    ASSERT_EQ(damage.size(), 2u);
    EXPECT_TRUE(same(damage[0], {600, 340, 20, 10}));
    EXPECT_TRUE(same(damage[1], {100 + 20, 20 + 10, 40, 60}));
}

TEST(ViewportPresenter, ANewScaleDamagesTheViewportAndWhereTheOldCopyReached) {
    DamageInput input = steadyViewport();
    input.rendered = true;
    input.scale = 1, input.scaleBefore = 2;
    input.drawnPixels = PixelRegion{0, 0, 5, 5};
    input.viewport = {100, 20, 399, 299};
    input.copiedBefore = {100, 20, 400, 300};  // whole pixels at ½ reached one pixel further
    const auto damage = screenDamage(input);
    ASSERT_EQ(damage.size(), 1u);  // merged: the old copy holds the new viewport
    EXPECT_TRUE(same(damage[0], {100, 20, 400, 300}));
}

TEST(ViewportPresenter, ABandDamagesItsRowsAndAFirstBandOverARefinedFrameAllOfIt) {
    DamageInput input = steadyViewport();
    input.rendered = true;
    input.bands = 4, input.band = 1;
    input.rows = {150, 75};
    auto damage = screenDamage(input);
    ASSERT_EQ(damage.size(), 1u);
    EXPECT_TRUE(same(damage[0], {100, 20 + 150, 400, 75}));
    input.band = 0;
    input.bandsMissing = true;  // a new full frame in place of one being refined
    damage = screenDamage(input);
    ASSERT_EQ(damage.size(), 1u);
    EXPECT_TRUE(same(damage[0], input.viewport));
}

TEST(ViewportPresenter, OutsideTheViewportNothingOfItIsPainted) {
    const ViewportPaint paint = viewportPaint({0, 0, 50, 50}, {100, 20, 400, 300}, {400, 300}, true, 100);
    EXPECT_TRUE(paint.reduced.empty());
    EXPECT_TRUE(paint.frame.empty());
}

TEST(ViewportPresenter, AWholeFrameIsPaintedAcrossTheRectangle) {
    const PixelRegion rect{80, 0, 100, 100};
    const ViewportPaint paint = viewportPaint(rect, {100, 20, 400, 300}, {400, 300}, false, 0);
    EXPECT_TRUE(paint.reduced.empty());
    EXPECT_TRUE(same(paint.frame, rect));
}

// Refined from the top: the top 100 rows show the bands, the 200 below them the reduced frame.
TEST(ViewportPresenter, WhileRefiningTheBandsShowAboveTheReducedFrame) {
    const PixelRegion viewport{100, 20, 400, 300};
    const ViewportPaint paint = viewportPaint({0, 0, 640, 360}, viewport, {400, 300}, true, 100);
    EXPECT_TRUE(same(paint.reduced, {100, 20, 400, 200}));
    EXPECT_TRUE(same(paint.frame, {100, 220, 400, 100}));
}

}  // namespace
}  // namespace glint
