// The classroom's compare view rendered: each pane's scene (compare_scenes.h) rendered with the
// same renderer at its pane's size (compare_layout.h), then composited into one radiance image and
// one 8-bit image with the divider lines and a label per pane drawn over the 8-bit image. The two
// steps are separate so that dragging the split's divider only composites again.
// Used by `glint render --compare …` and the editor's Compare view. No layout maths here.
#pragma once

#include <string>
#include <vector>

#include "classroom/compare_layout.h"
#include "runtime/headless.h"

namespace glint {

struct ComparePaneScene {
    Scene scene;
    std::string label;  // drawn at the pane's top-left corner ("" for none)
};

inline constexpr glm::u8vec3 kDividerColor{255, 200, 0};  // amber, visible on light and dark scenes

// Each pane's scene rendered at its pane's render size (empty images for zero-sized panes).
Result<std::vector<RenderedImages>> renderComparePanes(Renderer& renderer, const std::vector<ComparePaneScene>& panes,
                                                       const CompareGeometry& geometry);

// The panes' renders (from renderComparePanes with a geometry of the same render sizes) cut to
// `geometry` and composited, dividers and labels drawn. Fails only when the label font is missing.
Result<RenderedImages> compositeCompare(const std::vector<RenderedImages>& rendered, const std::vector<ComparePaneScene>& panes,
                                        const CompareGeometry& geometry, int width, int height);

// Both steps.
Result<RenderedImages> renderCompare(Renderer& renderer, const std::vector<ComparePaneScene>& panes, CompareLayout layout,
                                     int width, int height, float divider);

}  // namespace glint
