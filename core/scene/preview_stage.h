// The standard preview stage: one material on a unit sphere resting on a grey plane, lit by
// three lights (a directional key, a point fill, a directional rim) over a neutral background.
// Used where a material file is rendered without a scene (snapshots, thumbnails); not a scene file.
#pragma once

#include "scene/scene.h"

namespace glint {

// The stage with `material` on the sphere, at width×height pixels.
Scene previewStage(const Material& material, int width, int height);

}  // namespace glint
