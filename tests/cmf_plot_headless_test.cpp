// The CIE matching-function plot drawn headless (app/classroom/cmf_plot.h through the overlay
// canvas, in an OSMesa context of its own): each curve's colour is found where its tabulated peak
// should be. 320×200 pixels. Built into editor_tests, which links the app library.
#include <gtest/gtest.h>
#include <imgui.h>

#include "classroom/cmf_plot.h"
#include "classroom/overlay_canvas.h"
#include "gpu_test_support.h"

namespace glint {
namespace {

// True when a pixel within `radius` of `centre` has `channel` clearly above the other two.
bool cmfPlotTestHasColourNear(const DisplayImage& image, ImVec2 centre, int channel, int radius) {
    for (int y = static_cast<int>(centre.y) - radius; y <= static_cast<int>(centre.y) + radius; ++y)
        for (int x = static_cast<int>(centre.x) - radius; x <= static_cast<int>(centre.x) + radius; ++x) {
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
            const uint8_t* pixel = &image.pixels[(static_cast<size_t>(y) * image.width + x) * 3];
            if (pixel[channel] > 150 && pixel[channel] > pixel[(channel + 1) % 3] + 60 && pixel[channel] > pixel[(channel + 2) % 3] + 60)
                return true;
        }
    return false;
}

TEST(CmfPlot, CurvesPeakWhereTheCieTableDoes) {
    test::sharedHeadless();
    const float fontSize = 12.0f;
    auto canvas = OverlayCanvas::create(fontSize);
    ASSERT_TRUE(canvas) << canvas.error().format();
    const ImVec2 size(320.0f, 200.0f);
    (*canvas)->begin(320, 200);
    drawCmfPlot(ImGui::GetBackgroundDrawList(), ImVec2(0.0f, 0.0f), size, fontSize);
    auto image = (*canvas)->finish(DisplayImage{});
    ASSERT_TRUE(image) << image.error().format();
    // CIE 1931: x̄(600) = 1.062, ȳ(555) = 1.000, z̄(445) = 1.783.
    EXPECT_TRUE(cmfPlotTestHasColourNear(*image, cmfPlotPoint({0, 0}, size, fontSize, 600.0f, 1.062f), 0, 3));
    EXPECT_TRUE(cmfPlotTestHasColourNear(*image, cmfPlotPoint({0, 0}, size, fontSize, 555.0f, 1.0f), 1, 3));
    EXPECT_TRUE(cmfPlotTestHasColourNear(*image, cmfPlotPoint({0, 0}, size, fontSize, 445.0f, 1.783f), 2, 3));
    // And no curve runs through the empty upper left (x̄, ȳ, z̄ are all below 0.1 at 700 nm).
    EXPECT_FALSE(cmfPlotTestHasColourNear(*image, cmfPlotPoint({0, 0}, size, fontSize, 700.0f, 1.0f), 0, 3));
}

}  // namespace
}  // namespace glint
