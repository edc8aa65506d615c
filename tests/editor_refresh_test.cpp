// The editor's redraw decisions (editor/viewport_refresh.h), without a window: a slow scene is
// drawn with simplified meshes and at reduced resolution while dragging, the full frame follows
// the drag's end with no further input, a change outside a drag is refined after a pause, fast
// scenes and the setting turned off are drawn in full.
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "editor/viewport_refresh.h"

namespace glint {
namespace {

using Input = ViewportRefresh::Input;

Input change(double now, bool dragging) { return {now, true, false, dragging, true}; }
Input idle(double now, bool dragging = false) { return {now, false, false, dragging, true}; }

// A refresh that has drawn one full frame taking `milliseconds`.
ViewportRefresh afterFullFrame(double milliseconds) {
    ViewportRefresh refresh;
    const RefreshPlan first = refresh.plan({0.0, true, true, false, true});
    EXPECT_TRUE(first.render);
    EXPECT_EQ(first.detail, MeshDetail::Full);
    refresh.rendered(first, milliseconds, false);
    return refresh;
}

TEST(ViewportRefresh, ADragOfASlowSceneDrawsSimplifiedMeshesThenTheFullFrame) {
    ViewportRefresh refresh = afterFullFrame(1200.0);  // a million triangles
    EXPECT_TRUE(refresh.fullFramesAreSlow());
    // The first frame of the drag: the resolution follows from the full frame's cost.
    RefreshPlan plan = refresh.plan(change(10.0, true));
    EXPECT_TRUE(plan.render);
    EXPECT_EQ(plan.detail, MeshDetail::Simplified);
    EXPECT_EQ(plan.pixelScale, 4);
    refresh.rendered(plan, 8.0, true);
    // Faster than the budget: the next frame of the drag gets more pixels.
    plan = refresh.plan(change(10.1, true));
    EXPECT_EQ(plan.detail, MeshDetail::Simplified);
    EXPECT_EQ(plan.pixelScale, 2);
    refresh.rendered(plan, 20.0, true);
    // Holding still mid-drag draws nothing and waits for input.
    EXPECT_FALSE(refresh.plan(idle(10.2, true)).render);
    EXPECT_GT(refresh.secondsToRefine(10.2), 1e8);
    // Released: the full frame comes on the next loop iterations, with no new input, in bands
    // (about one per frame budget, at most kMostRefineBands), one an iteration.
    for (int band = 0; band < ViewportRefresh::kMostRefineBands; ++band) {
        plan = refresh.plan(idle(10.3 + 0.1 * band));
        EXPECT_TRUE(plan.render);
        EXPECT_EQ(plan.detail, MeshDetail::Full);
        EXPECT_EQ(plan.pixelScale, 1);
        EXPECT_EQ(plan.band, band);
        EXPECT_EQ(plan.bands, ViewportRefresh::kMostRefineBands);
        EXPECT_DOUBLE_EQ(refresh.secondsToRefine(10.3 + 0.1 * band), 0.0);
        refresh.rendered(plan, 150.0, false);
        EXPECT_EQ(refresh.refining(), band + 1 < plan.bands);
    }
    EXPECT_FALSE(refresh.plan(idle(11.5)).render);
}

// A material's slider redraws only that material's objects (gl/renderer.h) once a frame at the
// drag's scale was drawn whole: such a drag keeps its scale, going to ½ from ¼ when a frame there
// would fit the budget, and the next drag starts there; the full frame's time stays the whole one's.
TEST(ViewportRefresh, ADragThatRedrawsOnlyAMaterialKeepsItsScale) {
    ViewportRefresh refresh = afterFullFrame(345.0);
    RefreshPlan plan = refresh.plan(change(10.0, true));
    EXPECT_EQ(plan.pixelScale, 4);  // ½ would take about 86 ms
    refresh.rendered(plan, 35.0, false);  // whole, over the budget
    plan = refresh.plan(change(10.1, true));
    EXPECT_EQ(plan.pixelScale, 4);  // kept: the next may redraw only the changes
    refresh.rendered(plan, 6.0, false, true);
    plan = refresh.plan(change(10.2, true));
    EXPECT_EQ(plan.pixelScale, 2);  // about 24 ms there
    refresh.rendered(plan, 80.0, false);
    for (double now : {10.3, 10.4}) {
        plan = refresh.plan(change(now, true));
        EXPECT_EQ(plan.pixelScale, 2);
        refresh.rendered(plan, 30.0, false, true);
    }
    // Released: the full frame, in bands, redraws only the changes too; its time is not a whole frame's.
    do {
        plan = refresh.plan(idle(10.5));
        EXPECT_EQ(plan.pixelScale, 1);
        refresh.rendered(plan, 10.0, false, true);
    } while (refresh.refining());
    EXPECT_EQ(plan.band + 1, ViewportRefresh::kMostRefineBands);
    EXPECT_TRUE(refresh.fullFramesAreSlow());
    EXPECT_EQ(refresh.plan(change(11.0, true)).pixelScale, 2);
}

// The bands of a refined full frame share out the rows where it has its work (the changed objects'
// rectangle), top first; together they are every row once.
TEST(ViewportRefresh, TheBandsShareOutTheBusyRows) {
    using Rows = std::vector<std::pair<int, int>>;
    const auto rowsOf = [](int bands, int height, std::optional<RowBand> busy) {
        Rows rows;
        for (int band = 0; band < bands; ++band) {
            const RowBand r = refineBandRows(band, bands, height, busy);
            rows.emplace_back(r.first, r.count);
        }
        return rows;
    };
    // No busy rows known: even bands of the whole height.
    EXPECT_EQ(rowsOf(4, 100, std::nullopt), (Rows{{75, 25}, {50, 25}, {25, 25}, {0, 25}}));
    // Rows 30-89 busy: 20 each, the first band also the rows above, the last those below.
    EXPECT_EQ(rowsOf(3, 100, RowBand{30, 60}), (Rows{{70, 30}, {50, 20}, {0, 50}}));
    // Busy rows reaching past the frame are clipped to it; fewer busy rows than bands: even bands.
    EXPECT_EQ(rowsOf(2, 100, RowBand{60, 100}), (Rows{{80, 20}, {0, 80}}));
    EXPECT_EQ(rowsOf(4, 100, RowBand{10, 3}), rowsOf(4, 100, std::nullopt));
    EXPECT_EQ(rowsOf(1, 100, RowBand{30, 60}), (Rows{{0, 100}}));
}

TEST(ViewportRefresh, ADragDuringTheBandsAbandonsThem) {
    ViewportRefresh refresh = afterFullFrame(200.0);
    RefreshPlan plan = refresh.plan(change(1.0, true));
    refresh.rendered(plan, 30.0, false);
    plan = refresh.plan(idle(1.1));  // released
    EXPECT_EQ(plan.bands, 7);  // 200 ms in 33 ms budgets
    refresh.rendered(plan, 30.0, false);
    EXPECT_TRUE(refresh.refining());
    // A new drag before the second band: a reduced frame at once, the bands left.
    plan = refresh.plan(change(1.2, true));
    EXPECT_EQ(plan.bands, 1);
    EXPECT_EQ(plan.pixelScale, 2);
    refresh.rendered(plan, 30.0, false);
    EXPECT_FALSE(refresh.refining());
    // Released again: the bands start over, and the whole frame's time is what the next drag plans with.
    plan = refresh.plan(idle(1.3));
    EXPECT_EQ(plan.band, 0);
    for (int band = 0; band < plan.bands; ++band) {
        plan = band == 0 ? plan : refresh.plan(idle(1.3));
        refresh.rendered(plan, 40.0, false);
    }
    EXPECT_FALSE(refresh.refining());
    EXPECT_FALSE(refresh.plan(idle(1.4)).render);
}

TEST(ViewportRefresh, AChangeOutsideADragIsRefinedOnceChangesPause) {
    ViewportRefresh refresh = afterFullFrame(1200.0);
    RefreshPlan plan = refresh.plan(change(5.0, false));  // a wheel tick
    EXPECT_EQ(plan.detail, MeshDetail::Simplified);
    EXPECT_EQ(plan.pixelScale, 1);
    refresh.rendered(plan, 60.0, true);
    EXPECT_NEAR(refresh.secondsToRefine(5.1), ViewportRefresh::kSettleSeconds - 0.1, 1e-9);
    EXPECT_FALSE(refresh.plan(idle(5.1)).render);  // another tick may come
    plan = refresh.plan(change(5.2, false));
    EXPECT_EQ(plan.detail, MeshDetail::Simplified);
    refresh.rendered(plan, 60.0, true);
    plan = refresh.plan(idle(5.2 + ViewportRefresh::kSettleSeconds + 0.01));
    EXPECT_TRUE(plan.render);
    EXPECT_EQ(plan.detail, MeshDetail::Full);
    for (int band = 0; band < plan.bands; ++band) refresh.rendered(band == 0 ? plan : refresh.plan(idle(5.5)), 150.0, false);
    EXPECT_GT(refresh.secondsToRefine(6.0), 1e8);
}

TEST(ViewportRefresh, FastScenesAreAlwaysDrawnInFull) {
    ViewportRefresh refresh = afterFullFrame(12.0);
    EXPECT_FALSE(refresh.fullFramesAreSlow());
    for (bool dragging : {true, false}) {
        const RefreshPlan plan = refresh.plan(change(1.0, dragging));
        EXPECT_TRUE(plan.render);
        EXPECT_EQ(plan.detail, MeshDetail::Full);
        EXPECT_EQ(plan.pixelScale, 1);
        refresh.rendered(plan, 12.0, false);
    }
}

TEST(ViewportRefresh, ADragIsNoCoarserThanHalfResolutionUnlessHalfWouldBeFarOverBudget) {
    // 200 ms in full: ⌈√(200 / 33)⌉ = 3 would meet the budget, but ½ (about 50 ms) is drawn.
    ViewportRefresh refresh = afterFullFrame(200.0);
    EXPECT_EQ(refresh.plan(change(1.0, true)).pixelScale, ViewportRefresh::kCoarsestPixelScale);
    // 400 ms in full: ½ would take about 100 ms, over twice the budget, so ⌈√(400 / 33)⌉ = 4.
    refresh = afterFullFrame(400.0);
    EXPECT_EQ(refresh.plan(change(1.0, true)).pixelScale, ViewportRefresh::kCoarsestPixelScaleOfSlowScenes);
}

TEST(ViewportRefresh, WithTheSettingOffADragOnlyLowersTheResolution) {
    ViewportRefresh refresh = afterFullFrame(300.0);
    Input input = change(1.0, true);
    input.simplifyWhileDragging = false;
    const RefreshPlan plan = refresh.plan(input);
    EXPECT_EQ(plan.detail, MeshDetail::Full);
    EXPECT_EQ(plan.pixelScale, 4);  // ⌈√(300 / 33)⌉ = 4
    refresh.rendered(plan, 25.0, false);
    EXPECT_TRUE(refresh.plan(idle(1.1)).render);  // the full-resolution frame follows
}

TEST(ViewportRefresh, AStandInNotYetMadeLeavesTheFrameFull) {
    // Simplified asked for, nothing simplified drawn (the worker is not done): at full
    // resolution that frame is already the full one, and nothing is redrawn after it.
    ViewportRefresh refresh = afterFullFrame(1200.0);
    const RefreshPlan plan = refresh.plan(change(2.0, false));
    refresh.rendered(plan, 1200.0, false);
    EXPECT_FALSE(refresh.plan(idle(3.0)).render);
}

TEST(ViewportRefresh, AFrameWithGenericStandInProgramsIsRefinedOnlyOnceTheProgramsArrive) {
    ViewportRefresh refresh = afterFullFrame(20.0);  // a fast scene
    // A model switch drawn with the generic programs while the specialised ones compile.
    RefreshPlan plan = refresh.plan(change(5.0, false));
    EXPECT_TRUE(plan.render);
    refresh.rendered(plan, 30.0, true);
    Input waiting = idle(6.0);
    waiting.waitingForPrograms = true;
    EXPECT_FALSE(refresh.plan(waiting).render);  // long after the pause, still waiting
    EXPECT_GT(refresh.secondsToRefine(6.0, true), 1e8);  // the programs' arrival wakes the loop
    plan = refresh.plan(idle(6.5));  // arrived
    EXPECT_TRUE(plan.render);
    EXPECT_EQ(plan.pixelScale, 1);
    refresh.rendered(plan, 20.0, false);
    EXPECT_FALSE(refresh.plan(idle(7.0)).render);
}

}  // namespace
}  // namespace glint
