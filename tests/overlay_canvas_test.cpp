// The headless ImGui canvas: what is drawn lands where it was drawn (top row first), over the
// image underneath, in the headless OSMesa context. Not a test of any particular overlay.
#include <gtest/gtest.h>
#include <array>
#include <imgui.h>

#include "classroom/overlay_canvas.h"
#include "gpu_test_support.h"

namespace glint {
namespace {

using test::sharedHeadless;

std::array<int, 3> canvasPixel(const DisplayImage& image, int x, int y) {
    const size_t at = (static_cast<size_t>(y) * image.width + x) * 3;
    return {image.pixels[at], image.pixels[at + 1], image.pixels[at + 2]};
}

TEST(OverlayCanvas, DrawsOverTheImageUnderneathTopRowFirst) {
    sharedHeadless();  // makes the OSMesa context current and loads GL
    auto canvas = OverlayCanvas::create(13.0f);
    ASSERT_TRUE(canvas) << canvas.error().format();
    DisplayImage under(64, 48);
    for (size_t i = 0; i < under.pixels.size(); i += 3) under.pixels[i + 2] = 200;  // blue
    (*canvas)->begin(64, 48);
    ImGui::GetBackgroundDrawList()->AddRectFilled(ImVec2(4, 4), ImVec2(20, 12), IM_COL32(255, 0, 0, 255));
    ImGui::GetBackgroundDrawList()->AddText(ImVec2(30, 30), IM_COL32(255, 255, 255, 255), "θ");
    auto composite = (*canvas)->finish(under);
    ASSERT_TRUE(composite) << composite.error().format();
    ASSERT_EQ(composite->width, 64);
    ASSERT_EQ(composite->height, 48);
    EXPECT_EQ(canvasPixel(*composite, 10, 8), (std::array<int, 3>{255, 0, 0}));   // the rectangle, near the top
    EXPECT_EQ(canvasPixel(*composite, 10, 40), (std::array<int, 3>{0, 0, 200}));  // the image underneath
    int brightPixels = 0;  // the glyph drew something white-ish near (30..45, 30..47)
    for (int y = 30; y < 48; ++y)
        for (int x = 30; x < 46; ++x) brightPixels += canvasPixel(*composite, x, y)[0] > 128;
    EXPECT_GT(brightPixels, 3);
    EXPECT_EQ(ImGui::GetCurrentContext(), nullptr);  // the previous (no) context is current again
}

}  // namespace
}  // namespace glint
