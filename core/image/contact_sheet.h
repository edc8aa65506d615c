// A contact sheet: equally sized images in a grid, each with its label underneath, on a dark
// background. Pure image assembly; the thumbnails come from the caller.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "image/text_label.h"

namespace glint {

struct LabelledImage {
    std::string label;
    const DisplayImage* image = nullptr;  // all of one size
};

// `columns` images a row (0: about square); labels are drawn with `font`.
DisplayImage contactSheet(const std::vector<LabelledImage>& images, int columns, const LabelFont& font);

}  // namespace glint
