// The layout maths of the classroom's compare view: where each pane of a split (two panes and a
// draggable divider), a 2×2 grid or a row (side by side) lies in the output image, which part of
// its own render it shows, and where the divider lines go. Pure integers; no rendering here
// (app/classroom/compare_render.h composites the panes).
#pragma once

#include <vector>

namespace glint {

// Split: every pane is rendered at the full output size with the same camera and the divider
// chooses, per column, whose pixels show (a wipe: one object, two materials, left and right).
// Grid: up to four panes, each a whole render at a quarter of the size. Row: N panes side by
// side, each a whole render of 1/N of the width (the interpolation lesson).
enum class CompareLayout { Split, Grid, Row };

struct PixelRect {
    int x = 0, y = 0;  // top-left corner [pixels], y down as in the images
    int width = 0, height = 0;
};

struct ComparePane {
    PixelRect target;        // where the pane lands in the output image
    int renderWidth = 0;     // the size its scene is rendered at
    int renderHeight = 0;
    int sourceX = 0;         // the top-left of `target` within that render
    int sourceY = 0;
};

struct CompareGeometry {
    std::vector<ComparePane> panes;   // in pane order (grid: row by row)
    std::vector<PixelRect> dividers;  // lines drawn over the composite
};

inline constexpr int kDividerThickness = 2;  // [pixels]

// Panes of `paneCount` (split: 2; grid: 1..4; row: ≥ 1) in a width × height image; `divider` in
// [0,1] is the split's divider position as a fraction of the width (unused by the other layouts).
// A pane may be zero pixels wide when the divider sits at an edge.
CompareGeometry compareGeometry(CompareLayout layout, int paneCount, int width, int height, float divider);

// The pane under pixel (x, y), or −1 (an empty grid cell).
int paneAt(const CompareGeometry& geometry, int x, int y);

}  // namespace glint
