// The frame plan (see frame_plan.h): each decision a function of the inputs and the ones before it.
#include "gl/frame_plan.h"

#include <algorithm>

#include "render/transmission_backdrop.h"

namespace glint {
namespace {

// Opaque objects first, each group in scene order.
void planDrawOrder(const Scene& scene, FramePlan& plan) {
    plan.drawOrder.resize(scene.objects.size());
    for (size_t i = 0; i < plan.drawOrder.size(); ++i) plan.drawOrder[i] = i;
    const auto opaque = [&](size_t i) { return !transmitsLight(scene.materials.at(scene.objects[i].materialIndex)); };
    const auto first = std::stable_partition(plan.drawOrder.begin(), plan.drawOrder.end(), opaque);
    plan.firstTransmissive = static_cast<size_t>(first - plan.drawOrder.begin());
}

// What a frame that holds `held` must redraw (RendererOptions::redrawOnlyChanges): the pixels of
// the changed materials' objects, and those drawn since from a newer scene.
std::optional<MaterialChange> changeFrom(const HeldFrame* held, const Scene& scene, const FrameTargets& targets) {
    if (!held || held->standIns || held->targets != targets) return std::nullopt;
    std::optional<MaterialChange> change = materialChange(held->scene, scene, targets.width, targets.height);
    if (change && held->newer) change->rect = boundsOf(change->rect, *held->newer);
    return change;
}

void planRedraw(const Scene& scene, const FrameRequest& request, const RendererOptions& options, const HeldState& held,
                FramePlan& plan) {
    if (options.redrawOnlyChanges) plan.change = changeFrom(held.frame, scene, plan.targets);
    if (plan.change) plan.region = plan.change->rect;
    if (request.rows.count > 0)
        plan.region = intersectionOf(plan.region.value_or(PixelRegion{0, 0, request.width, request.height}),
                                     {0, request.rows.first, request.width, request.rows.count});
    plan.objectsOnly = plan.change && (!held.frame->newer || intersectionOf(*plan.region, *held.frame->newer).empty());
    plan.resolvesWholeFrame = request.samples > 1 && plan.change && !held.resolveHeld;
    // The backdrop's opaque pass draws every pixel.
    if (!plan.capturesBackdrop && !plan.resolvesWholeFrame) plan.drawnPixels = plan.region;
}

void planBackground(const Scene& scene, FramePlan& plan) {
    const bool environmentShown = scene.environment.enabled() && scene.environment.showAsBackground;
    const bool dithered = plan.fusedDisplay && plan.fusedDisplay->dither != Dither::None;
    // Not when the backdrop is captured: its opaque objects are drawn over a clear of zero coverage.
    const bool uniform =
        !plan.capturesBackdrop && scene.background.kind == BackgroundKind::Constant && !environmentShown && !dithered;
    plan.clearsBackground = uniform && !plan.objectsOnly;
    plan.drawsBackgroundPass = !uniform && (plan.capturesBackdrop || !plan.objectsOnly);
}

}  // namespace

FramePlan planFrame(const Scene& scene, const FrameRequest& request, const RendererOptions& options, const HeldState& held) {
    FramePlan plan;
    planDrawOrder(scene, plan);
    const bool backdropNeeded = options.transmissionBackdrop && drawsTransmissionBackdrop(scene);
    const RowBand& rows = request.rows;
    plan.capturesBackdrop = backdropNeeded && (rows.count == 0 || rows.first + rows.count >= request.height);
    plan.showsBackdrop = backdropNeeded && (plan.capturesBackdrop || held.backdropHeld);
    // The levels ramp is drawn by the display pass.
    if (options.fuseDisplay && request.samples == 1 && !scene.display.levelsRamp) plan.fusedDisplay = scene.display;
    // The float image is written unless the render is fused and nobody reads it; the backdrop is copied from it.
    const bool radianceWritten = options.keepRadiance || !plan.fusedDisplay || plan.capturesBackdrop;
    plan.targets = {request.width, request.height, request.samples, radianceWritten, plan.fusedDisplay.has_value()};
    planRedraw(scene, request, options, held, plan);
    planBackground(scene, plan);
    return plan;
}

}  // namespace glint
