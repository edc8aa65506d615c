// ViewportPresenter: the viewport from the scene to the screen, one loop iteration at a time. It
// renders what ViewportRefresh plans (reduced frames while dragging, the full frame after, in
// bands when full frames are slow), keeps the frame on screen while programs compile in the
// background, and puts on screen only what changed: the pixels the render drew and where the UI
// changed (UiDamage); all of the window where it does not keep its pixels, or after it was
// exposed, resized, or the viewport moved. While a full frame is refined in bands, the reduced
// frame before it shows where no band is drawn yet.
// The decisions are pure functions (screenDamage, viewportPaint: tests/viewport_presenter_test.cpp);
// the class holds what lasts between iterations and does the GL.
#pragma once

#include <chrono>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "editor/editor_state.h"
#include "editor/ui_damage.h"
#include "editor/viewport_refresh.h"
#include "gl/render_target.h"
#include "gl/renderer.h"
#include "platform/glfw_platform.h"

namespace glint {

// --- the pure part ----------------------------------------------------------------------------

// What screenDamage needs of an iteration. Regions are framebuffer pixels, lower-left origin;
// `rows` and `drawnPixels` are rendered pixels (each `scale`² screen pixels).
struct DamageInput {
    std::vector<PixelRegion> ui;  // where the UI draws differently (UiDamage)
    bool rendered = false;        // a frame, or a band of one, was rendered
    int band = 0, bands = 1;      // which, of how many (RefreshPlan)
    bool bandsMissing = false;    // a full frame was being refined when this one was rendered
    RowBand rows;                 // the band's rows
    std::optional<PixelRegion> drawnPixels;  // what the render drew (Renderer::drawnPixels)
    int scale = 1;                // of the frame now
    int scaleBefore = 1;          // of the frame on screen before
    PixelRegion viewport;         // what the viewport's copy covers now
    PixelRegion copiedBefore;     // what its copy covered before
    PixelRegion window;           // the whole framebuffer
    bool whole = false;           // all of the window changed
};

// The rectangles to draw again and present, merged where they overlap: the band's rows; the
// pixels a render drew (all of the viewport at a new scale or in place of a frame being refined);
// what a coarser copy reached before; where the UI changed; or the whole window.
std::vector<PixelRegion> screenDamage(const DamageInput& input);

// What one damaged rectangle shows of the viewport: the reduced frame where no band of the full
// frame is drawn yet, and the frame (its bands so far) within `frame`. Empty: not drawn there.
struct ViewportPaint {
    PixelRegion reduced;
    PixelRegion frame;
};

// `rect`'s paint, for a frame of `renderedSize` screen pixels copied to `viewport` (its lower left
// the viewport's), `refinedRows` of them drawn in bands from the top while `refining`.
ViewportPaint viewportPaint(const PixelRegion& rect, const PixelRegion& viewport, glm::ivec2 renderedSize, bool refining,
                            int refinedRows);

// --- the presenter ----------------------------------------------------------------------------

// What one iteration rendered.
struct ViewportRender {
    RefreshPlan plan;              // plan.render: whether anything was
    RowBand rows;                  // the band's rows, of a frame drawn in bands
    bool bandsMissing = false;     // a full frame was being refined before
    int scaleBefore = 1;           // the scale of the frame that was on screen
    bool waitedForPrograms = false;  // the frame on screen stays until programs compile
    double renderMilliseconds = 0.0;
};

// How long putting it on screen took [ms], for the frame log.
struct PresentTimes {
    double displayedMilliseconds = 0.0, uiMilliseconds = 0.0;
    std::chrono::steady_clock::time_point composed;  // the frame drawn, before it was presented
    long long pixelsPresented = 0;
};

class ViewportPresenter {
public:
    ViewportPresenter(Renderer& renderer, GlfwPlatform& platform) : renderer_(renderer), platform_(platform) {}

    // Something else drew with the renderer (a screenshot, a swatch, the compare panes): the next
    // iteration renders afresh.
    void forgetFrame() { renderedSize_ = {0, 0}; }
    // The shaders changed: the scene is drawn again with them.
    void forgetScene() { renderedRevision_ = ~0ull; }
    // Seconds until a frame drawn with stand-ins is due for its full redraw (ViewportRefresh).
    double secondsToRefine(double nowSeconds, bool waitingForPrograms) const {
        return refresh_.secondsToRefine(nowSeconds, waitingForPrograms);
    }

    // Renders what the refresh plan asks of this iteration for a viewport of `viewportPixels`,
    // and notes the frame's figures in `state`.
    ViewportRender render(EditorState& state, glm::ivec2 viewportPixels, bool gesture);
    // Draws the damaged rectangles as the whole frame would be there (the window's colour, the
    // viewport at `lowerLeft`, the UI) and presents them; `exposed`: the window lost its pixels.
    PresentTimes present(const ViewportRender& render, glm::ivec2 framebuffer, glm::ivec2 lowerLeft, glm::ivec2 viewportPixels,
                         bool exposed, bool timed);

private:
    // Whether the frame can be drawn now: programs still compiling in the background may lower
    // its resolution (their generic stand-ins are slower) or keep the frame on screen.
    // `drawn` is `scene` as the plan's scale draws it (`preview`: a copy without MSAA); a new scale changes both.
    bool programsAllow(RefreshPlan& plan, const Scene& scene, Scene& preview, const Scene*& drawn, glm::ivec2 viewportPixels,
                       glm::ivec2& renderPixels);
    // Renders the planned frame (or band) and notes its figures.
    void renderPlanned(EditorState& state, const RefreshPlan& plan, const Scene& drawn, glm::ivec2 viewportPixels,
                       glm::ivec2 renderPixels, ViewportRender& result);
    void paint(const std::vector<PixelRegion>& damage, glm::ivec2 framebuffer, const PixelRegion& viewport, glm::ivec2 lowerLeft);

    Renderer& renderer_;
    GlfwPlatform& platform_;
    ViewportRefresh refresh_;
    UiDamage uiDamage_;
    glm::ivec2 renderedSize_{0, 0};  // the viewport's size when its frame was rendered
    std::uint64_t renderedRevision_ = ~0ull;
    int renderedScale_ = 1;
    DisplaySettings shownDisplay_;  // of the frame last drawn (a change may wait for its programs)
    glm::ivec4 placed_{0, 0, 0, 0};  // where the viewport was put on screen: lower left, size
    PixelRegion viewportCopied_;     // the screen pixels its last (scaled) copy covered
    // Frames drawn whole and swapped after the window was exposed or resized: llvmpipe gives a
    // resized window a new back buffer only at a swap, with no pixels of the frame before.
    int wholeFrames_ = 0;
    // On screen while the full frame is refined in bands: the frame before, at its own resolution
    // (copied as it is, and scaled as it is put on screen, as it was shown).
    RenderTarget reducedFrame_{GL_RGBA8, false};
    int reducedScale_ = 1;
    int refinedRows_ = 0;  // the full frame's rows drawn so far, from the top
    // The full-resolution rows of the changed objects' rectangle of the last frame not drawn in
    // bands that redrew only them (a drag's): the bands of the full frame after it split these rows evenly.
    std::optional<RowBand> changedRows_;
    double refinedMilliseconds_ = 0.0;  // the full frame's bands so far
};

}  // namespace glint
