// FramePlan: what one radiance frame draws, decided once, before any GL call, from the scene, the
// render options and what the renderer's targets hold: the passes that run, the pixels they keep
// to, and what the programs they need depend on. The renderer draws by it (gl/renderer.cpp), and
// asks it which programs a frame will need (Renderer::programsReady). No GL here.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "gl/renderer_options.h"
#include "render/material_change.h"
#include "render/visibility.h"
#include "scene/scene.h"

namespace glint {

// What a frame writes into: its size, MSAA samples and images.
struct FrameTargets {
    int width = 0, height = 0, samples = 1;
    bool radianceWritten = false;  // the float radiance image
    bool fused = false;            // the display-encoded 8-bit image, in the radiance pass
    bool operator==(const FrameTargets&) const = default;
};

// A frame a draw target holds (RendererOptions::redrawOnlyChanges).
struct HeldFrame {
    Scene scene;
    FrameTargets targets;
    bool standIns = false;  // simplified meshes or provisional shadow maps (set once drawn)
    // Pixels drawn since from a newer scene (bands of a frame that redrew only changes).
    std::optional<PixelRegion> newer;
};

// What the renderer holds when a frame begins.
struct HeldState {
    const HeldFrame* frame = nullptr;  // the frame the draw target holds; null: none
    bool resolveHeld = false;          // the single-sample target holds the last MSAA resolve
    bool backdropHeld = false;         // a transmission backdrop captured at this frame's size
};

// The frame asked for: its size, the samples its target allocated and the rows it draws.
struct FrameRequest {
    int width = 0, height = 0, samples = 1;
    RowBand rows;  // count 0: every row
};

// What a frame draws, pass by pass (planFrame).
struct FramePlan {
    FrameTargets targets;
    std::optional<DisplaySettings> fusedDisplay;  // the settings the radiance pass encodes with, when fused

    // Object indices in drawing order: the opaque ones first, then, from `firstTransmissive` on,
    // those that transmit light, which look up the backdrop of the opaque ones.
    std::vector<size_t> drawOrder;
    size_t firstTransmissive = 0;
    // The opaque pass covers the whole frame and is copied into the transmission backdrop before
    // the first transmissive object (a whole frame, or the band with the top row).
    bool capturesBackdrop = false;
    // Transmissive objects see a backdrop (captured now, or by the band above); else none is kept.
    bool showsBackdrop = false;

    // The changed materials' objects, when only they are redrawn over a held frame.
    std::optional<MaterialChange> change;
    // The pixels drawn, cleared and resolved (a band, the changed rectangle), after the backdrop's
    // opaque pass, which covers the frame; none: all.
    std::optional<PixelRegion> region;
    // Only the changed objects are drawn, no clear and no background: the region holds the
    // held frame's pixels.
    bool objectsOnly = false;
    // The MSAA resolve covers the whole frame: the single-sample target does not hold the last one.
    bool resolvesWholeFrame = false;
    // The pixels whose picture may change (Renderer::drawnPixels); none: all.
    std::optional<PixelRegion> drawnPixels;

    // The background is one value at every pixel and drawn as a clear (constant, no environment
    // shown, no dither pattern in a fused image), not in a frame that captures the backdrop.
    bool clearsBackground = false;
    // The background program runs: any other background, after the opaque objects.
    bool drawsBackgroundPass = false;

    bool changesOnly() const { return change.has_value(); }
    // Whether the object at `position` in drawOrder is drawn over the transmission backdrop.
    bool seesBackdrop(size_t position) const { return position >= firstTransmissive && showsBackdrop; }
};

// The plan of a frame of `scene`. Pure: the same inputs give the same plan.
FramePlan planFrame(const Scene& scene, const FrameRequest& request, const RendererOptions& options, const HeldState& held);

}  // namespace glint
