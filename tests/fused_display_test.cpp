// The fused display (renderer.h setFusedDisplay, shaders/common/display_output.glsl): the 8-bit
// image written in the radiance pass is byte for byte the one the separate display pass makes from
// the float image, for every tone map and encoding, sky and objects; a display with other
// settings than the fused ones still runs the pass. Not the CPU twin (gpu_reference_test.cpp).
#include <gtest/gtest.h>

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
    renderer.setFusedDisplay(false);
    EXPECT_TRUE(renderer.renderRadiance(scene, width, height).ok());
    renderer.displayOffscreen(scene.display);
    DisplayImage image = renderer.readDisplay();
    renderer.setFusedDisplay(true);
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

// Renderer::setRadianceKept(false) (PNG renders, `glint bench`): the fused render writes the 8-bit
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
    test::sharedHeadless().renderer().setRadianceKept(true);  // as the other tests expect
}

}  // namespace
}  // namespace glint
