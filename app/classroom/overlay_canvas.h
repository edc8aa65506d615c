// Draws ImGui content (plots, labels, vectors) without a window, so every classroom overlay and
// plot the editor shows can also be rendered headless (`glint render --overlay …`). It owns an
// ImGui context of its own and renders it with the OpenGL3 backend into an offscreen framebuffer
// of the GL context current at create() (HeadlessRenderer's OSMesa context). Not for the editor's
// own frames, which use the editor's context.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "image/image.h"
#include "util/diagnostic.h"

struct ImGuiContext;
struct ImFont;

namespace glint {

class OverlayCanvas {
public:
    // Needs a current GL 4.1 core context whose functions glad has loaded. fontPixelSize is the
    // font's height in pixels: DejaVu Sans (Greek letters, ², ·) when installed, else ImGui's
    // built-in font.
    static Result<std::unique_ptr<OverlayCanvas>> create(float fontPixelSize = 16.0f);
    // The same font at several heights [px], the first the default; font(i) is the i-th, for
    // ImGui::PushFont between begin() and finish().
    static Result<std::unique_ptr<OverlayCanvas>> create(std::span<const float> fontPixelSizes);
    ImFont* font(size_t index) const { return fonts_.at(index); }
    ~OverlayCanvas();
    OverlayCanvas(const OverlayCanvas&) = delete;
    OverlayCanvas& operator=(const OverlayCanvas&) = delete;

    // Starts a frame of width×height pixels and makes the canvas's ImGui context current: between
    // begin() and finish(), ImGui calls (ImGui::GetBackgroundDrawList(), or windows placed with
    // SetNextWindowPos) draw into the canvas.
    void begin(int width, int height);
    // Ends the frame and draws it over `under` (an image of the frame's size; an empty image means
    // an opaque black background). Returns the composite; restores the previous ImGui context.
    Result<DisplayImage> finish(const DisplayImage& under);

private:
    OverlayCanvas() = default;
    ImGuiContext* context_ = nullptr;
    std::vector<ImFont*> fonts_;
    ImGuiContext* previousContext_ = nullptr;
    int width_ = 0, height_ = 0;
};

}  // namespace glint
