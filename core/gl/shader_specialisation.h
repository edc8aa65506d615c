// Program specialisation: the #define prelude that makes what a frame keeps fixed compile-time
// constants of the programs that draw it — the lights' kinds and shadow maps (the first lights and
// the shadowed ones unrolled, each reading its own map, then a loop per kind), whether there
// is an environment, whether it is shown and its peak lights' count, the background's kind, the
// fused display's choices (transfer, tone map, dither) and a built-in material's enum and bool
// parameters. The GLSL compiler then drops the branches, loops and uniform reads a generic program
// runs at every pixel (llvmpipe runs shaders on the CPU, so that code costs as much as the shading
// itself). A symbol left undefined keeps the generic, uniform-driven code (shaders/common/*.glsl
// read both ways), so a new fixed choice is one more line here and one #ifdef where it is read. The text is part of a program's cache key
// (SurfaceVariant::specialisation): a change of what it names compiles a new program once, and
// continuous values (colours, roughness, light positions) stay uniforms, so drags never compile.
#pragma once

#include <optional>
#include <string>

#include "gl/frame_uniforms.h"
#include "gl/shadow_maps.h"
#include "scene/scene.h"

namespace glint {

// Lights summed unrolled (with constant LightBlock offsets) before the rest are looped over: a looped
// light costs llvmpipe about a fifth more (its values are gathered lane by lane), an unrolled one
// grows the program (docs/performance.md, "Many lights").
inline constexpr int kMaxUnrolledLights = 8;
// Loops, each over a run of lights of one kind, before the looped lights are summed as any kind.
inline constexpr int kMaxLightRuns = 6;

// The frame's part: the lights (as packed, with their shadow-map slots) followed by
// backgroundSpecialisation().
std::string frameSpecialisation(const FrameUniforms& frame, const ShadowBlockStd140& shadows, const Environment& environment,
                                const std::optional<DisplaySettings>& fusedDisplay);

// What the background pass reads of the frame: environment, background kind and, when the display
// chain is fused into the radiance pass, its choices; not the lights, so that moving, adding or
// shadowing a light reuses the background's program.
std::string backgroundSpecialisation(const FrameUniforms& frame, const Environment& environment,
                                     const std::optional<DisplaySettings>& fusedDisplay);

// The display chain's choices (transfer, tone map, dither) for display_encode.glsl: the fused
// radiance passes' and the display pass's.
std::string displaySpecialisation(const DisplaySettings& display);

// A built-in model's enum and bool parameters, and its layer weights (scalars named *_weight) that
// are 0, by name (GLINT_PARAM_<name>, read by the generated loadMaterialParams(),
// gl/material_glsl.h): a layer weighted 0 (OpenPBR's coat, fuzz, thin film) is compiled out.
std::string materialSpecialisation(const AnalyticMaterial& material);

}  // namespace glint
