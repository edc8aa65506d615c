// When and how the viewport is redrawn (see viewport_refresh.h).
#include "editor/viewport_refresh.h"

#include <algorithm>
#include <cmath>

namespace glint {

RefreshPlan ViewportRefresh::plan(const Input& input) {
    // A full frame being refined goes on band by band while nothing changes; a change abandons it.
    if (nextBand_ > 0 && !input.sceneChanged && !input.sizeChanged && !input.dragging) {
        RefreshPlan plan;
        plan.render = true;
        plan.band = nextBand_;
        plan.bands = bands_;
        return plan;
    }
    nextBand_ = 0;
    if (input.sceneChanged && !input.dragging) lastChangeSeconds_ = input.nowSeconds;
    const bool wasDragging = dragging_;
    dragging_ = input.dragging;
    // A drag ends its interaction at once (the release is the last input); other changes after
    // a pause, as nothing tells when the next one comes.
    const bool interacting = input.dragging || input.nowSeconds - lastChangeSeconds_ < kSettleSeconds;
    RefreshPlan plan;
    plan.render = input.sceneChanged || input.sizeChanged || (shownReduced_ && !interacting && !input.waitingForPrograms);
    if (plan.render && !interacting && shownReduced_ && !input.sizeChanged && fullFramesAreSlow())
        plan.bands = std::min(kMostRefineBands, static_cast<int>(std::ceil(fullFrameMilliseconds_ / kFrameBudgetMilliseconds)));
    bands_ = plan.bands;
    if (!plan.render || !interacting || !fullFramesAreSlow()) return plan;
    if (input.simplifyWhileDragging) plan.detail = MeshDetail::Simplified;
    const bool newScaleOverBudget = interactiveScaleIsNew_ && wasDragging && interactiveMilliseconds_ > kFrameBudgetMilliseconds;
    if (input.dragging && interactiveMeasured_ && (interactiveChangesOnly_ || newScaleOverBudget)) {
        // Frames that redraw only a changed material's objects keep their scale (at another, the
        // first frame is drawn whole), and so does the drag's frame after a slow one at a new
        // scale, which may be one.
        // Coarser when such a frame takes twice the budget; ½ when one there would fit it.
        plan.pixelScale = interactiveScale_;
        const double milliseconds = interactiveChangesOnly_ ? interactiveMilliseconds_ : 0.0;
        const double atHalf = milliseconds * interactiveScale_ * interactiveScale_ / (kCoarsestPixelScale * kCoarsestPixelScale);
        if (milliseconds > 2.0 * kFrameBudgetMilliseconds)
            plan.pixelScale = std::min(2 * interactiveScale_, kCoarsestPixelScaleOfSlowScenes);
        else if (interactiveChangesOnly_ && interactiveScale_ > kCoarsestPixelScale && atHalf <= kFrameBudgetMilliseconds)
            plan.pixelScale = kCoarsestPixelScale;
    } else if (input.dragging) {
        // Frame cost taken as proportional to the pixels drawn: the scale that brings the last
        // interactive frame (or, before any, the last full one) within the budget.
        const double milliseconds = interactiveMeasured_ ? interactiveMilliseconds_ : fullFrameMilliseconds_;
        const int scale = interactiveMeasured_ ? interactiveScale_ : 1;
        const double wanted = std::ceil(scale * std::sqrt(milliseconds / kFrameBudgetMilliseconds));
        const double atHalf = milliseconds * scale * scale / (kCoarsestPixelScale * kCoarsestPixelScale);
        const int coarsest = atHalf > 2.0 * kFrameBudgetMilliseconds ? kCoarsestPixelScaleOfSlowScenes : kCoarsestPixelScale;
        plan.pixelScale = static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(coarsest)));
    }
    return plan;
}

void ViewportRefresh::rendered(const RefreshPlan& plan, double renderMilliseconds, bool drewStandIns, bool drewChangesOnly) {
    if (plan.bands > 1) {
        bandsMilliseconds_ = (plan.band == 0 ? 0.0 : bandsMilliseconds_) + renderMilliseconds;
        nextBand_ = plan.band + 1 < plan.bands ? plan.band + 1 : 0;
        if (nextBand_ > 0) return;  // the reduced frame is still partly on screen
        renderMilliseconds = bandsMilliseconds_;  // the whole frame's
    }
    shownReduced_ = plan.pixelScale > 1 || drewStandIns;
    if (shownReduced_ || plan.detail == MeshDetail::Simplified) {
        // Drawn for an interaction (with stand-ins or not yet: then it was the full mesh).
        interactiveMilliseconds_ = renderMilliseconds;
        interactiveScaleIsNew_ = !interactiveMeasured_ || plan.pixelScale != interactiveScale_;
        interactiveScale_ = plan.pixelScale;
        interactiveChangesOnly_ = drewChangesOnly;
        interactiveMeasured_ = true;
    }
    if (!shownReduced_ && !drewChangesOnly) fullFrameMilliseconds_ = renderMilliseconds;
}

double ViewportRefresh::secondsToRefine(double nowSeconds, bool waitingForPrograms) const {
    if (nextBand_ > 0) return 0.0;  // the next band
    // A drag's end is an input event itself, and so is a program's arrival.
    if (!shownReduced_ || dragging_ || waitingForPrograms) return 1e9;
    return std::max(0.0, lastChangeSeconds_ + kSettleSeconds - nowSeconds);
}

RowBand refineBandRows(int band, int bands, int height, std::optional<RowBand> busy) {
    int low = busy ? std::clamp(busy->first, 0, height) : 0;
    int high = busy ? std::clamp(busy->first + busy->count, low, height) : height;
    if (high - low < bands) {  // too few busy rows to give each band some
        low = 0;
        high = height;
    }
    const auto boundary = [&](int k) { return k == 0 ? height : k == bands ? 0 : high - (high - low) * k / bands; };
    return {boundary(band + 1), boundary(band) - boundary(band + 1)};
}

}  // namespace glint
