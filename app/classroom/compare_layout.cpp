// The compare view's pane and divider rectangles (see compare_layout.h).
#include "classroom/compare_layout.h"

#include <algorithm>
#include <cmath>

namespace glint {

CompareGeometry compareGeometry(CompareLayout layout, int paneCount, int width, int height, float divider) {
    CompareGeometry geometry;
    const int half = kDividerThickness / 2;
    if (layout == CompareLayout::Split) {
        const int split = std::clamp(static_cast<int>(std::lround(divider * static_cast<float>(width))), 0, width);
        geometry.panes.push_back({{0, 0, split, height}, width, height, 0, 0});
        geometry.panes.push_back({{split, 0, width - split, height}, width, height, split, 0});
        geometry.dividers.push_back({std::clamp(split - half, 0, std::max(0, width - kDividerThickness)), 0,
                                     std::min(kDividerThickness, width), height});
    } else if (layout == CompareLayout::Grid) {
        const int left = width / 2, top = height / 2;
        const int columnWidths[2] = {left, width - left}, rowHeights[2] = {top, height - top};
        for (int i = 0; i < paneCount && i < 4; ++i) {
            const int column = i % 2, row = i / 2;
            const PixelRect target{column * left, row * top, columnWidths[column], rowHeights[row]};
            geometry.panes.push_back({target, target.width, target.height, 0, 0});
        }
        geometry.dividers.push_back({std::max(0, left - half), 0, std::min(kDividerThickness, width), height});
        geometry.dividers.push_back({0, std::max(0, top - half), width, std::min(kDividerThickness, height)});
    } else {
        for (int i = 0; i < paneCount; ++i) {
            const int begin = width * i / paneCount, end = width * (i + 1) / paneCount;
            geometry.panes.push_back({{begin, 0, end - begin, height}, end - begin, height, 0, 0});
            if (i > 0) geometry.dividers.push_back({std::max(0, begin - half), 0, std::min(kDividerThickness, width), height});
        }
    }
    return geometry;
}

int paneAt(const CompareGeometry& geometry, int x, int y) {
    for (size_t i = 0; i < geometry.panes.size(); ++i) {
        const PixelRect& target = geometry.panes[i].target;
        if (x >= target.x && x < target.x + target.width && y >= target.y && y < target.y + target.height)
            return static_cast<int>(i);
    }
    return -1;
}

}  // namespace glint
