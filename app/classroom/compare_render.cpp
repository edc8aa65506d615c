// Rendering and compositing the compare panes (see compare_render.h).
#include "classroom/compare_render.h"

#include <algorithm>

#include "image/text_label.h"

namespace glint {
namespace {

// Copies the pane's part of its own render into the composite.
void compareCopyPane(const RenderedImages& rendered, const ComparePane& pane, RenderedImages& composite) {
    for (int row = 0; row < pane.target.height; ++row) {
        const size_t from = (static_cast<size_t>(pane.sourceY + row) * pane.renderWidth + pane.sourceX) * 3;
        const size_t to = (static_cast<size_t>(pane.target.y + row) * composite.display.width + pane.target.x) * 3;
        const size_t count = static_cast<size_t>(pane.target.width) * 3;
        std::copy_n(rendered.radiance.pixels.begin() + from, count, composite.radiance.pixels.begin() + to);
        std::copy_n(rendered.display.pixels.begin() + from, count, composite.display.pixels.begin() + to);
    }
}

void compareFillRect(DisplayImage& image, const PixelRect& rect, glm::u8vec3 color) {
    for (int y = rect.y; y < rect.y + rect.height; ++y)
        for (int x = rect.x; x < rect.x + rect.width; ++x)
            for (int c = 0; c < 3; ++c) image.pixels[(static_cast<size_t>(y) * image.width + x) * 3 + c] = color[c];
}

}  // namespace

Result<std::vector<RenderedImages>> renderComparePanes(Renderer& renderer, const std::vector<ComparePaneScene>& panes,
                                                       const CompareGeometry& geometry) {
    std::vector<RenderedImages> rendered;
    bool& keepRadiance = renderer.options().keepRadiance;
    const bool kept = keepRadiance;
    keepRadiance = true;  // the composite holds the panes' radiance too
    for (size_t i = 0; i < geometry.panes.size(); ++i) {
        const ComparePane& pane = geometry.panes[i];
        if (pane.target.width == 0 || pane.target.height == 0) {  // the divider sits at an edge
            rendered.push_back({});
            continue;
        }
        const Status status = renderer.renderRadiance(panes[i].scene, pane.renderWidth, pane.renderHeight);
        if (!status) {
            keepRadiance = kept;
            return status.error();
        }
        renderer.displayOffscreen(panes[i].scene.display);
        rendered.push_back({renderer.readRadiance(), renderer.readDisplay()});
    }
    keepRadiance = kept;
    return rendered;
}

Result<RenderedImages> compositeCompare(const std::vector<RenderedImages>& rendered, const std::vector<ComparePaneScene>& panes,
                                        const CompareGeometry& geometry, int width, int height) {
    RenderedImages composite{RadianceImage(width, height), DisplayImage(width, height)};
    for (size_t i = 0; i < geometry.panes.size(); ++i) {
        const ComparePane& pane = geometry.panes[i];
        if (pane.target.width > 0 && pane.target.height > 0) compareCopyPane(rendered.at(i), pane, composite);
    }
    for (const PixelRect& line : geometry.dividers) compareFillRect(composite.display, line, kDividerColor);
    auto font = LabelFont::load();
    if (!font) return font.error();
    const float textHeight = std::clamp(static_cast<float>(height) / 16.0f, 10.0f, 28.0f);
    for (size_t i = 0; i < geometry.panes.size(); ++i) {
        const PixelRect& target = geometry.panes[i].target;
        if (panes[i].label.empty() || target.width < 8) continue;
        const int margin = kDividerThickness + 3;
        font->draw(composite.display, target.x + margin + 1, target.y + 4, panes[i].label, textHeight, {0, 0, 0}, target.width - 2 * margin);
        font->draw(composite.display, target.x + margin, target.y + 3, panes[i].label, textHeight, {255, 255, 255}, target.width - 2 * margin);
    }
    return composite;
}

Result<RenderedImages> renderCompare(Renderer& renderer, const std::vector<ComparePaneScene>& panes, CompareLayout layout,
                                     int width, int height, float divider) {
    const CompareGeometry geometry = compareGeometry(layout, static_cast<int>(panes.size()), width, height, divider);
    auto rendered = renderComparePanes(renderer, panes, geometry);
    if (!rendered) return rendered.error();
    return compositeCompare(*rendered, panes, geometry, width, height);
}

}  // namespace glint
