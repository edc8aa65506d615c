// The preview stage: one material on a unit sphere resting on a floor, lit by the built-in studio
// environment in front of a grey backdrop and a key light that casts a soft shadow, tone mapped with
// Khronos PBR Neutral, 4× MSAA. The editor's default scene, material renders, thumbnails, contact
// sheets and preset swatches all use it (docs/preview-stage.md). Not a scene file.
#pragma once

#include "scene/scene.h"

namespace glint {

// The stage's exposure: an 18% grey Lambert ball shows as mid grey (docs/preview-stage.md has the
// measurement).
inline constexpr float kPreviewStageExposureStops = -0.25f;

// The stage with `material` on the sphere, at width×height pixels.
Scene previewStage(const Material& material, int width, int height);

}  // namespace glint
