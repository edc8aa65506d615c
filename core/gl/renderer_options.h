// RendererOptions: how the renderer draws frames, set by its front (headless renders, the editor,
// `glint bench`) through Renderer::options(). No GL: the frame plan (gl/frame_plan.h) reads it too.
#pragma once

namespace glint {

struct RendererOptions {
    // Fused display (off by default; headless renders turn it on): renders without MSAA also write the
    // display-encoded image into the 8-bit target in the radiance pass itself
    // (shaders/common/display_output.glsl), so that Renderer::displayOffscreen() with the scene's
    // display settings has nothing left to do but the overlays, and displayToScreen() copies it.
    // The float image is written all the same.
    bool fuseDisplay = false;
    // Whether fused renders also write the float radiance image. Off for a render whose float
    // image nobody reads (a PNG render, `glint bench`): a fused render then writes only the 8-bit
    // image, 4 bytes a pixel instead of 20, and readRadiance() and a display pass with other
    // settings are refused until a render that kept it. Unfused renders (MSAA, the levels ramp)
    // always write it.
    bool keepRadiance = true;
    // Specialised programs (gl/shader_specialisation.h): what a frame and a material keep fixed is
    // compiled in as constants, one program per combination, built when first drawn. Off: the
    // generic programs, every choice read from uniforms (`glint bench --generic`).
    bool specialisePrograms = true;
    // The transmission backdrop (gl/transmission_pass.h). Off: transmissive surfaces see only the
    // environment or background, as a frame with no opaque object does.
    bool transmissionBackdrop = true;
    // Redraws only what a material change reaches (off by default; the editor turns it on): when the targets hold a frame of
    // the same scene but for material values, at the same size and samples, drawn with no stand-in
    // (simplified mesh, shadow map drawn for a drag), a frame draws only the pixels of the changed
    // materials' objects (render/material_change.h), a band of rows only those within it, and the
    // rest stays as held. The picture is the whole frame's. Where none of those pixels was drawn
    // since from another scene (a band of the full frame after a drag, a drag frame), only the
    // changed objects are drawn again, over the held frame: each sample passes the depth test
    // (GL_LEQUAL) where the object was drawn before, as its depth is the same, and the other
    // objects and the background in its rectangle are not drawn at all.
    bool redrawOnlyChanges = false;
};

}  // namespace glint
