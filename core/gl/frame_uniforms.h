// Packs a scene's camera, background and lights into the std140 FrameBlock and LightBlock
// (uniform_blocks.h) for one frame. No GL calls: the renderer uploads what this returns.
#pragma once

#include "gl/uniform_blocks.h"
#include "scene/scene.h"

namespace glint {

struct FrameUniforms {
    FrameBlockStd140 frame{};
    LightBlockStd140 lights{};
};

// Enabled delta lights go to LightBlock in order (at most kMaxLights); ambient lights are summed
// into FrameBlock.ambientRadiance.
FrameUniforms packFrameUniforms(const Scene& scene, int width, int height);

}  // namespace glint
