// UiLayerCache: puts ImGui's frame on screen without drawing again the windows that did not change.
// On llvmpipe every UI pixel is a textured, alpha-blended fragment shaded on the CPU, and the side
// columns cover about a third of a 1920×1080 window: drawing them every frame cost more than the
// viewport's reduced-resolution render while dragging. A plain window (not a popup, tooltip or
// child) drawn only with the font atlas, overlapping neither the viewport nor a window drawn before
// it, depends on nothing but its own draw list: it is drawn into an offscreen copy of the screen
// when its vertices, indices or commands change (only the triangles' bounds whose vertices moved,
// when nothing else did: a slider's row), and otherwise copied from there (an unscaled copy,
// no shading). Such a window is cut to its rectangle (its border's anti-aliased fringe reached one
// pixel beyond). Everything else is drawn as ImGui_ImplOpenGL3_RenderDrawData would, in order.
#pragma once

#include <glad/gl.h>
#include <imgui.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace glint {

class UiLayerCache {
public:
    UiLayerCache() = default;
    ~UiLayerCache();
    UiLayerCache(const UiLayerCache&) = delete;
    UiLayerCache& operator=(const UiLayerCache&) = delete;

    // Draws `data` into the default framebuffer, whose pixels outside `viewport` (ImGui's
    // coordinates: x, y, width, height) were cleared to `clearColor` this frame.
    void draw(ImDrawData* data, const ImVec4& viewport, const float clearColor[4]);
    // Windows drawn into the copy, and copied from it unchanged, by the last draw() (GLINT_LOG_FRAMES).
    int listsRedrawn() const { return listsRedrawn_; }
    int listsCopied() const { return listsCopied_; }

private:
    struct Entry {
        std::uint64_t structure = 0;  // of the list as last drawn: its vertex count, indices, commands
        std::vector<ImDrawVert> vertices;  // and its vertices
        std::uint64_t frame = 0;  // the last frame that drew the list
    };
    void ensureTarget(int width, int height);

    GLuint framebuffer_ = 0, texture_ = 0;
    int width_ = 0, height_ = 0;
    std::unordered_map<const ImDrawList*, Entry> entries_;
    std::uint64_t frame_ = 0;
    int listsRedrawn_ = 0, listsCopied_ = 0;
};

}  // namespace glint
