// ViewportRefresh: when the editor redraws its viewport, and at what cost. The editor redraws
// only on change. While the user drags (a slider, a colour, a light handle, the camera) and a
// full frame takes longer than the frame budget, each frame is drawn at reduced resolution and at
// MeshDetail::Simplified (large meshes' stand-ins, changed shadow maps coarser: gl/renderer.h);
// a change outside a drag (a wheel zoom, a key) is first drawn simplified at full resolution. The full frame follows by
// itself: on the first frame after the drag ends, or once no change came for kSettleSeconds; when
// full frames are slow, in horizontal bands, top first, one a loop iteration, so that input
// arriving meanwhile waits for one band, not the whole frame (and a change abandons the rest).
// Pure bookkeeping: it renders nothing and reads no input (tests/editor_refresh_test.cpp).
#pragma once

#include <optional>

#include "gl/gpu_mesh_cache.h"
#include "render/visibility.h"

namespace glint {

// What one loop iteration should draw.
struct RefreshPlan {
    bool render = false;
    int pixelScale = 1;  // each rendered pixel covers pixelScale² screen pixels
    MeshDetail detail = MeshDetail::Full;
    int band = 0;   // the band this plan draws, of
    int bands = 1;  // the bands its full frame is drawn in (1: the whole frame at once)
};

class ViewportRefresh {
public:
    static constexpr double kFrameBudgetMilliseconds = 33.0;
    // A drag frame is no coarser than ½ resolution (coarser previews hide what the drag changes;
    // the specialised programs, gl/shader_specialisation.h, make ½ fast on llvmpipe), unless a
    // frame at ½ would take more than twice the budget (a million shadowed triangles): then down to ¼.
    static constexpr int kCoarsestPixelScale = 2;
    static constexpr int kCoarsestPixelScaleOfSlowScenes = 4;
    // A frame drawn with generic programs while the specialised ones compile (gl/renderer.h), which
    // are several times slower, is drawn at no finer than this.
    static constexpr int kStandInPixelScale = 4;
    // A change outside a drag counts as part of an interaction for this long [s]: wheel ticks and
    // key repeats come faster.
    static constexpr double kSettleSeconds = 0.25;
    // A slow full frame after reduced ones is split into about one band per frame budget, at most this many.
    static constexpr int kMostRefineBands = 8;

    struct Input {
        double nowSeconds = 0.0;
        bool sceneChanged = false;  // the scene is not the one last drawn
        bool sizeChanged = false;   // the viewport is not the size last drawn
        bool dragging = false;      // a gesture is in progress (ImGui item active, camera or handle drag)
        bool simplifyWhileDragging = true;  // the user's setting (Settings::simplifyMeshesWhileDragging)
        // The frame on screen waits for programs compiling in the background (gl/renderer.h): it
        // is not refined until they arrive.
        bool waitingForPrograms = false;
    };

    RefreshPlan plan(const Input& input);
    // After the planned frame was drawn: its render time, whether it drew a stand-in (a simplified
    // mesh, a generic program), and whether it drew only a changed material's objects (gl/renderer.h;
    // its time says nothing about a whole frame's).
    void rendered(const RefreshPlan& plan, double renderMilliseconds, bool drewStandIns, bool drewChangesOnly = false);
    // Seconds until a frame drawn with stand-ins is due for its full-detail redraw (for the event
    // wait); a large number when none is due or it waits for programs.
    double secondsToRefine(double nowSeconds, bool waitingForPrograms = false) const;
    // Whether full frames are slow enough that the stand-ins are worth making ahead of a drag.
    bool fullFramesAreSlow() const { return fullFrameMilliseconds_ > kFrameBudgetMilliseconds; }
    // Whether a full frame is part drawn: its bands so far are shown over the reduced frame.
    bool refining() const { return nextBand_ > 0; }

private:
    double fullFrameMilliseconds_ = 0.0;  // the last full-detail, full-resolution frame
    // The last frame drawn during an interaction: the next one's resolution follows from it.
    double interactiveMilliseconds_ = 0.0;
    int interactiveScale_ = 1;
    bool interactiveMeasured_ = false;
    bool interactiveChangesOnly_ = false;  // it drew only a changed material's objects
    bool interactiveScaleIsNew_ = false;   // its scale was not the one before's
    double lastChangeSeconds_ = -1e9;  // the last change outside a drag
    bool dragging_ = false;
    bool shownReduced_ = false;  // the frame on screen is not the full one
    int nextBand_ = 0;  // of the full frame being refined (0: none)
    int bands_ = 1;     // its bands
    double bandsMilliseconds_ = 0.0;  // its bands' render times so far
};

// The rows of band `band` of `bands` of a full frame `height` rows high, top first (bands together:
// every row once). The rows `busy` (where the frame has its work: the changed objects' rectangle;
// none: all) are split evenly among the bands; the first band also takes the rows above them, the
// last those below. Each band has a row at least when height ≥ bands.
RowBand refineBandRows(int band, int bands, int height, std::optional<RowBand> busy);

}  // namespace glint
