// The frame plan (gl/frame_plan.h), without GL: each decision the renderer draws by — drawing
// order, transmission backdrop, fused display, float image, partial redraw, MSAA resolve and
// background — from the scene, the options and what the renderer holds.
#include <gtest/gtest.h>

#include "gl/frame_plan.h"

namespace glint {
namespace {

constexpr int kFrameWidth = 320, kFrameHeight = 240;
constexpr FrameRequest kWholeFrame{kFrameWidth, kFrameHeight, 1, {}};

// The default scene (the sphere, material 0, over the floor, material 1) before a constant
// background (its own is a sky).
Scene stageScene() {
    Scene scene = defaultScene();
    scene.background.kind = BackgroundKind::Constant;
    return scene;
}

// The stage with a glass sphere.
Scene glassSphereScene() {
    Scene scene = stageScene();
    scene.materials[0] = Material::withDefaults("glass", BrdfModel::Glass);
    return scene;
}

// The scene with the sphere's material changed.
Scene sphereMaterialChanged(const Scene& before) {
    Scene after = before;
    paramValues(after.materials[0])[0] = 0.1f;
    return after;
}

RendererOptions redrawingChanges() {
    RendererOptions options;
    options.redrawOnlyChanges = true;
    return options;
}

// A frame of `scene` as the default options draw it at kFrameWidth × kFrameHeight without MSAA.
HeldFrame heldFrameOf(const Scene& scene) { return {scene, {kFrameWidth, kFrameHeight, 1, true, false}}; }

TEST(FramePlan, DrawsOpaqueObjectsBeforeTransmissiveOnes) {
    const FramePlan opaque = planFrame(stageScene(), kWholeFrame, {}, {});
    EXPECT_EQ(opaque.drawOrder, (std::vector<size_t>{0, 1}));
    EXPECT_EQ(opaque.firstTransmissive, 2u);
    const FramePlan glass = planFrame(glassSphereScene(), kWholeFrame, {}, {});
    EXPECT_EQ(glass.drawOrder, (std::vector<size_t>{1, 0})) << "the floor, then the glass sphere";
    EXPECT_EQ(glass.firstTransmissive, 1u);
    EXPECT_FALSE(glass.seesBackdrop(0));
    EXPECT_TRUE(glass.seesBackdrop(1));
}

TEST(FramePlan, CapturesTheBackdropInTheWholeFrameOrTheTopBand) {
    const Scene scene = glassSphereScene();
    EXPECT_TRUE(planFrame(scene, kWholeFrame, {}, {}).capturesBackdrop);
    const FramePlan top = planFrame(scene, {kFrameWidth, kFrameHeight, 1, {kFrameHeight - 40, 40}}, {}, {});
    EXPECT_TRUE(top.capturesBackdrop);
    EXPECT_FALSE(top.drawnPixels) << "its opaque pass draws every pixel";
    const FramePlan below = planFrame(scene, {kFrameWidth, kFrameHeight, 1, {0, 40}}, {}, {});
    EXPECT_FALSE(below.capturesBackdrop);
    EXPECT_FALSE(below.showsBackdrop) << "no backdrop held";
    const FramePlan belowHeld = planFrame(scene, {kFrameWidth, kFrameHeight, 1, {0, 40}}, {}, {.backdropHeld = true});
    EXPECT_FALSE(belowHeld.capturesBackdrop);
    EXPECT_TRUE(belowHeld.showsBackdrop) << "the band above captured it";
    ASSERT_TRUE(belowHeld.drawnPixels);
    EXPECT_EQ(belowHeld.drawnPixels->height, 40);
}

TEST(FramePlan, ShowsNoBackdropWhenSwitchedOffOrNothingIsOpaque) {
    RendererOptions off;
    off.transmissionBackdrop = false;
    const FramePlan switchedOff = planFrame(glassSphereScene(), kWholeFrame, off, {.backdropHeld = true});
    EXPECT_FALSE(switchedOff.capturesBackdrop);
    EXPECT_FALSE(switchedOff.showsBackdrop);
    EXPECT_FALSE(switchedOff.seesBackdrop(1));
    Scene allGlass = glassSphereScene();
    allGlass.materials[1] = Material::withDefaults("glass floor", BrdfModel::Glass);
    EXPECT_FALSE(planFrame(allGlass, kWholeFrame, {}, {}).showsBackdrop);
}

TEST(FramePlan, FusesTheDisplayOnlyWithoutMsaaOrLevelsRamp) {
    RendererOptions fused;
    fused.fuseDisplay = true;
    Scene scene = stageScene();
    EXPECT_FALSE(planFrame(scene, kWholeFrame, {}, {}).fusedDisplay) << "off by default";
    EXPECT_TRUE(planFrame(scene, kWholeFrame, fused, {}).targets.fused);
    EXPECT_FALSE(planFrame(scene, {kFrameWidth, kFrameHeight, 4, {}}, fused, {}).fusedDisplay) << "MSAA";
    scene.display.levelsRamp = true;
    EXPECT_FALSE(planFrame(scene, kWholeFrame, fused, {}).fusedDisplay) << "the display pass draws the ramp";
}

TEST(FramePlan, WritesTheFloatImageUnlessFusedAndNotKept) {
    RendererOptions options;
    options.keepRadiance = false;
    EXPECT_TRUE(planFrame(stageScene(), kWholeFrame, options, {}).targets.radianceWritten) << "not fused";
    options.fuseDisplay = true;
    EXPECT_FALSE(planFrame(stageScene(), kWholeFrame, options, {}).targets.radianceWritten);
    EXPECT_TRUE(planFrame(glassSphereScene(), kWholeFrame, options, {}).targets.radianceWritten)
        << "the backdrop is copied from it";
    options.keepRadiance = true;
    EXPECT_TRUE(planFrame(stageScene(), kWholeFrame, options, {}).targets.radianceWritten);
}

TEST(FramePlan, RedrawsOnlyTheChangedObjectsOverTheHeldFrame) {
    const Scene before = stageScene();
    const HeldFrame held = heldFrameOf(before);
    const FramePlan plan = planFrame(sphereMaterialChanged(before), kWholeFrame, redrawingChanges(), {.frame = &held});
    ASSERT_TRUE(plan.changesOnly());
    EXPECT_EQ(plan.change->materials, (std::vector<bool>{true, false}));
    ASSERT_TRUE(plan.region);
    EXPECT_EQ(plan.region->width, plan.change->rect.width);
    EXPECT_TRUE(plan.objectsOnly);
    ASSERT_TRUE(plan.drawnPixels);
    EXPECT_EQ(plan.drawnPixels->width, plan.change->rect.width);
    EXPECT_FALSE(plan.clearsBackground) << "the held frame's background stays";
    EXPECT_FALSE(plan.drawsBackgroundPass);
}

TEST(FramePlan, RedrawsEverythingWhenTheHeldFrameDoesNotServe) {
    const Scene before = stageScene();
    const Scene after = sphereMaterialChanged(before);
    HeldFrame held = heldFrameOf(before);
    EXPECT_FALSE(planFrame(after, kWholeFrame, {}, {.frame = &held}).change) << "the option is off";
    EXPECT_FALSE(planFrame(after, {kFrameWidth, kFrameHeight, 4, {}}, redrawingChanges(), {.frame = &held}).change) << "other samples";
    held.standIns = true;
    const FramePlan standIns = planFrame(after, kWholeFrame, redrawingChanges(), {.frame = &held});
    EXPECT_FALSE(standIns.change) << "drawn with stand-ins";
    EXPECT_FALSE(standIns.region);
    EXPECT_FALSE(standIns.objectsOnly);
    EXPECT_TRUE(standIns.clearsBackground);
}

TEST(FramePlan, BandOfAChangeDrawsWholeObjectsWhereANewerSceneWasDrawn) {
    const Scene before = stageScene();
    const Scene after = sphereMaterialChanged(before);
    HeldFrame held = heldFrameOf(before);
    const FrameRequest band{kFrameWidth, kFrameHeight, 1, {0, kFrameHeight / 2}};
    const FramePlan plain = planFrame(after, band, redrawingChanges(), {.frame = &held});
    ASSERT_TRUE(plain.region);
    EXPECT_GE(plain.region->y, 0);
    EXPECT_LE(plain.region->y + plain.region->height, kFrameHeight / 2) << "within the band";
    held.newer = PixelRegion{0, 0, kFrameWidth, kFrameHeight / 2};  // the band drawn since from a newer scene
    const FramePlan newer = planFrame(after, band, redrawingChanges(), {.frame = &held});
    ASSERT_TRUE(newer.changesOnly());
    EXPECT_EQ(newer.region->width, kFrameWidth) << "the changed rectangle grows to hold the newer pixels";
    EXPECT_FALSE(newer.objectsOnly) << "those pixels are drawn whole";
    EXPECT_TRUE(newer.clearsBackground);
}

TEST(FramePlan, ResolvesTheWholeFrameWhenTheResolveIsNotHeld) {
    const Scene before = stageScene();
    HeldFrame held = heldFrameOf(before);
    held.targets.samples = 4;
    const FrameRequest msaa{kFrameWidth, kFrameHeight, 4, {}};
    const Scene after = sphereMaterialChanged(before);
    const FramePlan notHeld = planFrame(after, msaa, redrawingChanges(), {.frame = &held});
    ASSERT_TRUE(notHeld.changesOnly());
    EXPECT_TRUE(notHeld.resolvesWholeFrame);
    EXPECT_FALSE(notHeld.drawnPixels);
    const FramePlan resolveHeld = planFrame(after, msaa, redrawingChanges(), {.frame = &held, .resolveHeld = true});
    EXPECT_FALSE(resolveHeld.resolvesWholeFrame);
    EXPECT_TRUE(resolveHeld.drawnPixels);
}

TEST(FramePlan, ClearsAUniformBackgroundAndDrawsAnyOther) {
    Scene scene = stageScene();
    const FramePlan constant = planFrame(scene, kWholeFrame, {}, {});
    EXPECT_TRUE(constant.clearsBackground);
    EXPECT_FALSE(constant.drawsBackgroundPass);
    RendererOptions fused;
    fused.fuseDisplay = true;
    scene.display.dither = Dither::Bayer4;
    const FramePlan dithered = planFrame(scene, kWholeFrame, fused, {});
    EXPECT_FALSE(dithered.clearsBackground) << "a dither pattern is not one value";
    EXPECT_TRUE(dithered.drawsBackgroundPass);
    EXPECT_TRUE(planFrame(scene, kWholeFrame, {}, {}).clearsBackground) << "unfused: the display pass dithers";
    scene = defaultScene();
    EXPECT_EQ(scene.background.kind, BackgroundKind::Sky);
    EXPECT_TRUE(planFrame(scene, kWholeFrame, {}, {}).drawsBackgroundPass);
    const FramePlan backdrop = planFrame(glassSphereScene(), kWholeFrame, {}, {});
    EXPECT_FALSE(backdrop.clearsBackground) << "the backdrop's opaque pass is drawn over zero coverage";
    EXPECT_TRUE(backdrop.drawsBackgroundPass);
}

}  // namespace
}  // namespace glint
