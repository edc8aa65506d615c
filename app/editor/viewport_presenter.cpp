// The viewport from the scene to the screen (see viewport_presenter.h).
#include "editor/viewport_presenter.h"

#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace glint {
namespace {

constexpr float kWindowClearColor[4] = {0.1f, 0.1f, 0.11f, 1.0f};  // under the panels

// The scene as a frame at `scale` draws it: a reduced-resolution preview (while dragging) skips
// MSAA, about 1.8x the frame on llvmpipe; the full frame after the drag smooths the edges again.
const Scene& sceneAtScale(const Scene& scene, int scale, Scene& preview) {
    if (scale <= 1 || scene.msaaSamples <= 1) return scene;
    preview = scene;
    preview.msaaSamples = 1;
    return preview;
}

glm::ivec2 pixelsAtScale(glm::ivec2 viewportPixels, int scale) { return (viewportPixels + scale - 1) / scale; }

// The renderer's error, shown in the editor and printed once each time it changes (not each frame).
void noteRenderProblem(EditorState& state, const std::string& problem) {
    if (!problem.empty() && problem != state.renderProblem) std::fprintf(stderr, "glint: %s\n", problem.c_str());
    state.renderProblem = problem;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<PixelRegion> screenDamage(const DamageInput& input) {
    if (input.whole) return {input.window};
    std::vector<PixelRegion> damage = input.ui;
    if (input.rendered) {
        const PixelRegion& viewport = input.viewport;
        const int scale = input.scale;
        // A band: its rows, which showed the reduced frame (all of the viewport for a new frame in
        // place of one being refined, as the reduced frame kept under it is the targets' mix of both).
        if (input.bands > 1 && (input.band > 0 || !input.bandsMissing))
            damage.push_back({viewport.x, viewport.y + input.rows.first * scale, viewport.width, input.rows.count * scale});
        else if (input.bands == 1 && input.drawnPixels && scale == input.scaleBefore && !input.bandsMissing)
            damage.push_back({viewport.x + input.drawnPixels->x * scale, viewport.y + input.drawnPixels->y * scale,
                              input.drawnPixels->width * scale, input.drawnPixels->height * scale});
        else
            damage.push_back(viewport);
        if (input.copiedBefore.width != viewport.width || input.copiedBefore.height != viewport.height)
            damage.push_back(input.copiedBefore);  // a copy at a coarser scale reached further
    }
    mergeOverlapping(damage);
    return damage;
}

ViewportPaint viewportPaint(const PixelRegion& rect, const PixelRegion& viewport, glm::ivec2 renderedSize, bool refining,
                            int refinedRows) {
    const PixelRegion part = intersectionOf(rect, viewport);
    if (part.empty()) return {};
    if (!refining) return {{}, rect};
    const int unrefinedRows = renderedSize.y - refinedRows;
    return {intersectionOf(part, {viewport.x, viewport.y, renderedSize.x, unrefinedRows}),
            intersectionOf(part, {viewport.x, viewport.y + unrefinedRows, renderedSize.x, refinedRows})};
}

ViewportRender ViewportPresenter::render(EditorState& state, glm::ivec2 viewportPixels, bool gesture) {
    ViewportRender result;
    const bool changed = state.session.revision() != renderedRevision_;
    RefreshPlan& plan = result.plan;
    plan = refresh_.plan({glfwGetTime(), changed, viewportPixels != renderedSize_, gesture,
                          state.settings.simplifyMeshesWhileDragging, state.waitingForPrograms});
    Scene preview;
    const Scene* drawn = &sceneAtScale(state.session.scene(), plan.pixelScale, preview);
    glm::ivec2 renderPixels = pixelsAtScale(viewportPixels, plan.pixelScale);
    if (plan.render && !programsAllow(plan, state.session.scene(), preview, drawn, viewportPixels, renderPixels)) {
        plan.render = false;
        state.waitingForPrograms = result.waitedForPrograms = true;
    }
    // What the viewport on screen shows: the targets' frame at this scale, but for a full frame's
    // missing bands (a new frame in place of one being refined is put on screen whole).
    result.scaleBefore = renderedScale_;
    result.bandsMissing = refresh_.refining();
    if (plan.render) renderPlanned(state, plan, *drawn, viewportPixels, renderPixels, result);
    return result;
}

bool ViewportPresenter::programsAllow(RefreshPlan& plan, const Scene& scene, Scene& preview, const Scene*& drawn,
                                      glm::ivec2 viewportPixels, glm::ivec2& renderPixels) {
    // Programs still compiling in the background: a frame with their generic stand-ins is drawn
    // at reduced resolution (they are slower), or, where there is none or the frame would refine
    // a reduced one, the frame on screen stays until they arrive.
    using Ready = Renderer::ProgramsReady;
    Ready ready = renderer_.programsReady(*drawn, renderPixels.x, renderPixels.y);
    if (ready == Ready::WithStandIns && plan.bands == 1 && plan.pixelScale < ViewportRefresh::kStandInPixelScale) {
        plan.pixelScale = ViewportRefresh::kStandInPixelScale;
        drawn = &sceneAtScale(scene, plan.pixelScale, preview);
        renderPixels = pixelsAtScale(viewportPixels, plan.pixelScale);
        ready = renderer_.programsReady(*drawn, renderPixels.x, renderPixels.y);  // without MSAA, say
    }
    // Only where the targets still hold the frame on screen (nothing else drew with the renderer).
    const bool frameKept = renderedSize_ == viewportPixels;
    return !(frameKept && (ready == Ready::No || (ready == Ready::WithStandIns && plan.bands > 1)));
}

void ViewportPresenter::renderPlanned(EditorState& state, const RefreshPlan& plan, const Scene& drawn, glm::ivec2 viewportPixels,
                                      glm::ivec2 renderPixels, ViewportRender& result) {
    const long long shadowMapRenders = renderer_.shadowMapRenders();
    const auto start = std::chrono::steady_clock::now();
    // A full frame drawn in bands, top first: the reduced frame on screen is kept to show under it.
    if (plan.bands > 1) {
        if (plan.band == 0) {
            reducedScale_ = renderedScale_;
            const glm::ivec2 reducedPixels = pixelsAtScale(viewportPixels, reducedScale_);
            reducedFrame_.ensure(reducedPixels.x, reducedPixels.y, 1);
            renderer_.displayToScreen(drawn.display, {0, 0}, 1, reducedFrame_.framebuffer());
        }
        result.rows = refineBandRows(plan.band, plan.bands, renderPixels.y, changedRows_);
        refinedRows_ = renderPixels.y - result.rows.first;
    }
    const Status status = renderer_.renderRadiance(drawn, renderPixels.x, renderPixels.y, plan.detail, result.rows);
    noteRenderProblem(state, !status ? status.error().format() : renderer_.shaderError());
    glFinish();
    result.renderMilliseconds = millisecondsSince(start);
    // A frame drawn in bands shows its bands' time so far, the whole frame's at the last.
    refinedMilliseconds_ = plan.band == 0 ? result.renderMilliseconds : refinedMilliseconds_ + result.renderMilliseconds;
    state.lastRenderMilliseconds = refinedMilliseconds_;
    state.standInProgramsShown = renderer_.standInProgramsDrawn();
    state.waitingForPrograms = state.standInProgramsShown > 0;
    // Only a material's objects redrawn: its time says nothing of a whole frame's.
    refresh_.rendered(plan, result.renderMilliseconds, renderer_.simplifiedMeshesDrawn() > 0 || state.standInProgramsShown > 0,
                      renderer_.drewOnlyChanges());
    if (plan.bands == 1) {  // (a band's drawn pixels are only its own part of the rectangle)
        const std::optional<PixelRegion>& drawnPixels = renderer_.drawnPixels();
        changedRows_.reset();
        if (renderer_.drewOnlyChanges() && drawnPixels)
            changedRows_ = RowBand{drawnPixels->y * plan.pixelScale, drawnPixels->height * plan.pixelScale};
    }
    // Slow full frames: have the large meshes' stand-ins made now, ready for the first drag.
    if (refresh_.fullFramesAreSlow() && state.settings.simplifyMeshesWhileDragging) renderer_.prepareSimplifiedMeshes(state.session.scene());
    state.previewScale = plan.pixelScale;
    state.simplifiedMeshesShown = renderer_.simplifiedMeshesDrawn();
    state.shadowMapsRedrawn = renderer_.shadowMapRenders() != shadowMapRenders;
    state.triangleCount = renderer_.trianglesDrawn();
    state.samplesNote = renderer_.samplesNote(state.session.scene().msaaSamples);
    renderedSize_ = viewportPixels;
    renderedRevision_ = state.session.revision();
    renderedScale_ = plan.pixelScale;
    shownDisplay_ = drawn.display;
}

PresentTimes ViewportPresenter::present(const ViewportRender& render, glm::ivec2 framebuffer, glm::ivec2 lowerLeft,
                                        glm::ivec2 viewportPixels, bool exposed, bool timed) {
    const glm::ivec2 shownSize = (renderedSize_ + renderedScale_ - 1) / renderedScale_ * renderedScale_;  // whole radiance pixels
    DamageInput input;
    uiDamage_.collect(*ImGui::GetDrawData(), input.ui);
    input.rendered = render.plan.render;
    input.band = render.plan.band, input.bands = render.plan.bands;
    input.bandsMissing = render.bandsMissing;
    input.rows = render.rows;
    input.drawnPixels = renderer_.drawnPixels();
    input.scale = renderedScale_, input.scaleBefore = render.scaleBefore;
    input.viewport = {lowerLeft.x, lowerLeft.y, shownSize.x, shownSize.y};
    input.copiedBefore = viewportCopied_;
    input.window = {0, 0, framebuffer.x, framebuffer.y};
    const glm::ivec4 placing{lowerLeft, viewportPixels};
    if (exposed || placing != placed_) wholeFrames_ = 2;
    input.whole = !platform_.presentsRegions() || wholeFrames_ > 0;
    wholeFrames_ = std::max(0, wholeFrames_ - 1);
    placed_ = placing;
    viewportCopied_ = input.viewport;
    const std::vector<PixelRegion> damage = screenDamage(input);

    PresentTimes times;
    const auto start = std::chrono::steady_clock::now();
    paint(damage, framebuffer, input.viewport, lowerLeft);
    if (timed) glFinish();  // so that the log can tell the phases apart
    times.displayedMilliseconds = millisecondsSince(start);
    const auto displayed = std::chrono::steady_clock::now();
    glViewport(0, 0, framebuffer.x, framebuffer.y);
    for (const PixelRegion& rect : damage) UiDamage::drawWithin(*ImGui::GetDrawData(), rect);
    if (timed) glFinish();
    times.uiMilliseconds = millisecondsSince(displayed);
    times.composed = std::chrono::steady_clock::now();
    for (const PixelRegion& rect : damage) times.pixelsPresented += static_cast<long long>(rect.width) * rect.height;
    if (input.whole) platform_.present();
    else for (const PixelRegion& rect : damage) platform_.presentRegion(rect.x, rect.y, rect.width, rect.height);
    return times;
}

// Each changed rectangle drawn as the whole frame would be there: the window's colour under the
// panels, the viewport (over the reduced frame while the full one is refined in bands: the bands
// so far). Scaled, the reduced frame's last column and row may reach past the viewport (up to
// scale − 1 pixels): the scissor keeps it inside.
void ViewportPresenter::paint(const std::vector<PixelRegion>& damage, glm::ivec2 framebuffer, const PixelRegion& viewport,
                              glm::ivec2 lowerLeft) {
    for (const PixelRegion& rect : damage) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, framebuffer.x, framebuffer.y);
        glEnable(GL_SCISSOR_TEST);
        glScissor(rect.x, rect.y, rect.width, rect.height);
        glClearColor(kWindowClearColor[0], kWindowClearColor[1], kWindowClearColor[2], kWindowClearColor[3]);
        glClear(GL_COLOR_BUFFER_BIT);
        const ViewportPaint paint = viewportPaint(rect, viewport, renderedSize_, refresh_.refining(), refinedRows_);
        if (!paint.reduced.empty()) {
            glScissor(paint.reduced.x, paint.reduced.y, paint.reduced.width, paint.reduced.height);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, reducedFrame_.framebuffer());
            glBlitFramebuffer(0, 0, reducedFrame_.width(), reducedFrame_.height(), lowerLeft.x, lowerLeft.y,
                              lowerLeft.x + reducedFrame_.width() * reducedScale_, lowerLeft.y + reducedFrame_.height() * reducedScale_,
                              GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        if (!paint.frame.empty()) {
            glScissor(paint.frame.x, paint.frame.y, paint.frame.width, paint.frame.height);
            renderer_.displayToScreen(shownDisplay_, lowerLeft, renderedScale_);
        }
        glDisable(GL_SCISSOR_TEST);
    }
}

}  // namespace glint
