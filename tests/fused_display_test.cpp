// The fused display (RendererOptions::fuseDisplay, shaders/common/display_output.glsl): the 8-bit
// image written in the radiance pass is byte for byte the one the separate display pass makes from
// the float image, for every tone map and encoding, sky and objects; a display with other
// settings than the fused ones still runs the pass. Not the CPU twin (gpu_reference_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test_support.h"

namespace glint {
namespace {

Scene skyScene() {
    Scene scene = defaultScene();
    scene.background.kind = BackgroundKind::Sky;  // the background pass writes the display too
    return scene;
}

// The display image through the separate display pass, fusing switched off for the call.
DisplayImage throughDisplayPass(const Scene& scene, int width, int height) {
    Renderer& renderer = test::sharedHeadless().renderer();
    renderer.options().fuseDisplay = false;
    EXPECT_TRUE(renderer.renderRadiance(scene, width, height).ok());
    renderer.displayOffscreen(scene.display);
    DisplayImage image = renderer.readDisplay();
    renderer.options().fuseDisplay = true;
    return image;
}

TEST(FusedDisplay, EqualsTheDisplayPassForEveryToneMapAndEncoding) {
    Scene scene = skyScene();
    for (ToneMap toneMap : {ToneMap::None, ToneMap::Reinhard, ToneMap::AcesFilmic, ToneMap::PbrNeutral})
        for (Transfer transfer : {Transfer::Srgb, Transfer::Gamma}) {
            scene.display = {1.5f, transfer, 1.8f, toneMap};
            auto fused = test::sharedHeadless().render(scene, 96, 64);
            ASSERT_TRUE(fused.ok()) << fused.error().format();
            const DisplayImage expected = throughDisplayPass(scene, 96, 64);
            EXPECT_EQ(fused->display.pixels, expected.pixels) << "tone map " << static_cast<int>(toneMap);
        }
}

TEST(FusedDisplay, OtherSettingsThanTheFusedOnesRunTheDisplayPass) {
    Scene scene = skyScene();
    Renderer& renderer = test::sharedHeadless().renderer();
    ASSERT_TRUE(renderer.renderRadiance(scene, 64, 64).ok());  // fused at 0 EV
    scene.display.exposureStops = 2.0f;
    renderer.displayOffscreen(scene.display);
    EXPECT_EQ(renderer.readDisplay().pixels, throughDisplayPass(scene, 64, 64).pixels);
}

TEST(FusedDisplay, MsaaRendersKeepTheDisplayPass) {
    Scene scene = skyScene();
    scene.msaaSamples = 4;
    auto rendered = test::sharedHeadless().render(scene, 64, 64);
    ASSERT_TRUE(rendered.ok()) << rendered.error().format();
    EXPECT_EQ(rendered->display.pixels, throughDisplayPass(scene, 64, 64).pixels);
    // And a fused render after an MSAA one is whole again.
    scene.msaaSamples = 1;
    auto fused = test::sharedHeadless().render(scene, 64, 64);
    ASSERT_TRUE(fused.ok());
    EXPECT_EQ(fused->display.pixels, throughDisplayPass(scene, 64, 64).pixels);
}

// RendererOptions::keepRadiance off (PNG renders, `glint bench`): the fused render writes the 8-bit
// image alone, the same bytes, with objects, a sky, or nothing but the background (whose frame then
// clears no depth either: the frame after it, with objects, is whole again).
TEST(FusedDisplay, WithoutTheFloatImageTheDisplayIsTheSame) {
    Scene empty = defaultScene();
    empty.objects.clear();
    for (const Scene& scene : {defaultScene(), skyScene(), empty, defaultScene()}) {
        auto kept = test::sharedHeadless().render(scene, 96, 64, true);
        auto alone = test::sharedHeadless().render(scene, 96, 64, false);
        ASSERT_TRUE(kept.ok() && alone.ok());
        EXPECT_TRUE(alone->radiance.pixels.empty());
        EXPECT_EQ(alone->display.pixels, kept->display.pixels);
    }
    // Unfused (MSAA) renders write the float image all the same: the display pass reads it.
    Scene msaa = skyScene();
    msaa.msaaSamples = 4;
    auto alone = test::sharedHeadless().render(msaa, 64, 64, false);
    ASSERT_TRUE(alone.ok());
    EXPECT_EQ(alone->display.pixels, throughDisplayPass(msaa, 64, 64).pixels);
    test::sharedHeadless().renderer().options().keepRadiance = true;  // as the other tests expect
}

// The editor refines a slow full frame in bands of rows (Renderer::renderRadiance's RowBand): the
// bands together are the whole frame, float and 8-bit, fused or through MSAA and the display pass.
TEST(FusedDisplay, AFrameDrawnInBandsIsTheWholeFrame) {
    Renderer& renderer = test::sharedHeadless().renderer();
    for (int samples : {1, 4}) {
        Scene scene = skyScene();
        scene.msaaSamples = samples;
        ASSERT_TRUE(renderer.renderRadiance(scene, 96, 64).ok());
        renderer.displayOffscreen(scene.display);
        const RadianceImage wholeRadiance = renderer.readRadiance();
        const DisplayImage wholeDisplay = renderer.readDisplay();
        Scene other = scene;  // other pixels in the targets: a red background, no object
        other.objects.clear();
        other.background.kind = BackgroundKind::Constant;
        other.background.color = {1.0f, 0.0f, 0.0f};
        ASSERT_TRUE(renderer.renderRadiance(other, 96, 64).ok());
        for (const RowBand rows : {RowBand{40, 24}, RowBand{13, 27}})
            ASSERT_TRUE(renderer.renderRadiance(scene, 96, 64, MeshDetail::Full, rows).ok());
        // Two bands: the bottom 13 rows (last in the top-first readback) still hold the other scene.
        renderer.displayOffscreen(scene.display);
        const DisplayImage partial = renderer.readDisplay();
        const size_t bandStart = static_cast<size_t>(64 - 13) * 96 * 3;
        EXPECT_TRUE(std::equal(partial.pixels.begin(), partial.pixels.begin() + bandStart, wholeDisplay.pixels.begin()));
        EXPECT_FALSE(std::equal(partial.pixels.begin() + bandStart, partial.pixels.end(), wholeDisplay.pixels.begin() + bandStart));
        ASSERT_TRUE(renderer.renderRadiance(scene, 96, 64, MeshDetail::Full, RowBand{0, 13}).ok());
        renderer.displayOffscreen(scene.display);
        EXPECT_EQ(renderer.readRadiance().pixels, wholeRadiance.pixels) << samples << " samples";
        EXPECT_EQ(renderer.readDisplay().pixels, wholeDisplay.pixels) << samples << " samples";
    }
}

// The editor redraws only the objects of a changed material (RendererOptions::redrawOnlyChanges): the
// frame is the whole frame, float and 8-bit, fused or through MSAA and the display pass, also after
// a frame without MSAA (a drag's, at its reduced size, or at the same size into the resolve target),
// and when drawn in bands.
TEST(FusedDisplay, AFrameRedrawnWhereAMaterialChangedIsTheWholeFrame) {
    Renderer& renderer = test::sharedHeadless().renderer();
    for (int samples : {1, 4}) {
        Scene before = defaultScene();  // studio light, a shadowed key light, the floor, a sky
        before.msaaSamples = samples;
        Scene after = before;
        paramValues(after.materials[0])[0] = 0.1f;
        ASSERT_TRUE(renderer.renderRadiance(after, 96, 64).ok());
        renderer.displayOffscreen(after.display);
        const RadianceImage wholeRadiance = renderer.readRadiance();
        const DisplayImage wholeDisplay = renderer.readDisplay();
        const long long wholeTriangles = renderer.trianglesDrawn();
        renderer.options().redrawOnlyChanges = true;
        Scene small = before;
        small.msaaSamples = 1;
        // A drag's frame at half size between them keeps its own targets: the sphere alone is drawn.
        ASSERT_TRUE(renderer.renderRadiance(before, 96, 64).ok());
        if (samples > 1) {
            ASSERT_TRUE(renderer.renderRadiance(small, 48, 32).ok());
        }
        ASSERT_TRUE(renderer.renderRadiance(after, 96, 64).ok());
        EXPECT_TRUE(renderer.drewOnlyChanges());
        EXPECT_TRUE(renderer.drawnPixels().has_value()) << "the sphere's rectangle";
        EXPECT_LT(renderer.trianglesDrawn(), wholeTriangles) << "the floor's pixels are held";
        renderer.displayOffscreen(after.display);
        EXPECT_EQ(renderer.readRadiance().pixels, wholeRadiance.pixels) << samples << " samples";
        EXPECT_EQ(renderer.readDisplay().pixels, wholeDisplay.pixels) << samples << " samples";
        if (samples > 1) {  // a frame without MSAA drew into the resolve target: all of it is resolved
            ASSERT_TRUE(renderer.renderRadiance(before, 96, 64).ok());
            ASSERT_TRUE(renderer.renderRadiance(small, 96, 64).ok());
            ASSERT_TRUE(renderer.renderRadiance(after, 96, 64).ok());
            EXPECT_TRUE(renderer.drewOnlyChanges());
            EXPECT_FALSE(renderer.drawnPixels().has_value()) << "every pixel, through MSAA";
            renderer.displayOffscreen(after.display);
            EXPECT_EQ(renderer.readRadiance().pixels, wholeRadiance.pixels) << "after a frame in the resolve target";
            EXPECT_EQ(renderer.readDisplay().pixels, wholeDisplay.pixels) << "after a frame in the resolve target";
        }
        // In bands (the full frame after a drag): one band of a third value, then the whole frame
        // of `after` again, the first band's pixels included.
        Scene third = before;
        paramValues(third.materials[0])[0] = 0.9f;
        ASSERT_TRUE(renderer.renderRadiance(before, 96, 64).ok());
        ASSERT_TRUE(renderer.renderRadiance(third, 96, 64, MeshDetail::Full, RowBand{32, 32}).ok());
        for (const RowBand rows : {RowBand{40, 24}, RowBand{0, 40}})
            ASSERT_TRUE(renderer.renderRadiance(after, 96, 64, MeshDetail::Full, rows).ok());
        renderer.displayOffscreen(after.display);
        EXPECT_EQ(renderer.readRadiance().pixels, wholeRadiance.pixels) << samples << " samples, in bands";
        EXPECT_EQ(renderer.readDisplay().pixels, wholeDisplay.pixels) << samples << " samples, in bands";
        renderer.options().redrawOnlyChanges = false;
    }
}

}  // namespace
}  // namespace glint
