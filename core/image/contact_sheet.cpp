// Contact sheet assembly (see contact_sheet.h).
#include "image/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glint {

DisplayImage contactSheet(const std::vector<LabelledImage>& images, int columns, const LabelFont& font) {
    if (images.empty()) return DisplayImage(1, 1);
    const int count = static_cast<int>(images.size());
    if (columns <= 0) columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    columns = std::min(columns, count);
    const int rows = (count + columns - 1) / columns;
    const int tileWidth = images[0].image->width, tileHeight = images[0].image->height;
    const float labelHeight = std::clamp(tileWidth / 14.0f, 10.0f, 18.0f);  // pixels
    const int margin = 8, labelSpace = static_cast<int>(std::ceil(labelHeight * 1.5f));
    const int cellWidth = tileWidth + margin, cellHeight = tileHeight + labelSpace + margin;

    DisplayImage sheet(columns * cellWidth + margin, rows * cellHeight + margin);
    std::fill(sheet.pixels.begin(), sheet.pixels.end(), uint8_t{32});
    for (int index = 0; index < count; ++index) {
        const DisplayImage& tile = *images[index].image;
        const int left = margin + (index % columns) * cellWidth, top = margin + (index / columns) * cellHeight;
        for (int y = 0; y < std::min(tile.height, tileHeight); ++y)
            std::memcpy(&sheet.pixels[(static_cast<size_t>(top + y) * sheet.width + left) * 3],
                        &tile.pixels[static_cast<size_t>(y) * tile.width * 3], static_cast<size_t>(std::min(tile.width, tileWidth)) * 3);
        font.draw(sheet, left, top + tileHeight + static_cast<int>(labelHeight * 0.2f), images[index].label, labelHeight,
                  {230, 230, 230}, tileWidth);
    }
    return sheet;
}

}  // namespace glint
