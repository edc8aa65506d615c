// UiDamage: where ImGui's frame draws differently from the frame before, so that the editor draws
// and presents only there (the window keeps its pixels between frames where the platform presents
// regions: GlfwPlatform::presentsRegions). On llvmpipe every UI pixel is a textured, blended
// fragment shaded on the CPU, the side columns cover about a third of a 1920×1080 window, and
// while a slider moves only its row and the status bar's text change. Each draw list (a window's,
// the light handles' background list) is compared with the same list in the frame before: one
// that is new, gone, drawn with another texture than the font atlas (an image may change under
// the same id) or changed in structure (vertex count, indices, commands) damages its bounds
// before and after; one whose vertices alone changed, the bounds of its triangles that moved.
#pragma once

#include <imgui.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "render/visibility.h"

namespace glint {

class UiDamage {
public:
    // Adds to `damage` the rectangles (framebuffer pixels, lower-left origin) where `data` draws
    // differently from the frame before, and keeps `data`'s lists to compare the next frame with.
    void collect(const ImDrawData& data, std::vector<PixelRegion>& damage);
    // Draws the lists of `data` that reach `rect`, within it only (their clip rectangles cut to it
    // for the call), in order, as ImGui_ImplOpenGL3_RenderDrawData would there.
    static void drawWithin(ImDrawData& data, const PixelRegion& rect);

private:
    struct Entry {
        std::uint64_t structure = 0;  // vertex count, indices, commands (0: drawn with another texture)
        std::vector<ImDrawVert> vertices;
        PixelRegion bounds;
        std::uint64_t frame = 0;  // the last frame that drew the list
    };
    std::unordered_map<const ImDrawList*, Entry> entries_;
    std::uint64_t frame_ = 0;
};

// Merges the rectangles that overlap into their bounds, until none do.
void mergeOverlapping(std::vector<PixelRegion>& rects);

}  // namespace glint
