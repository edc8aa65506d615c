// Headless runs (`glint render`, `glint FILE` without a display, snapshots, thumbnails) say on
// stderr when an environment map's precompute is slow: nothing for one done within 0.5 s (or
// GLINT_PROGRESS_AFTER_SECONDS), then "precomputing NAME N%" as a ProgressLine
// (runtime/progress_line.h: live on a terminal, a line every few percent otherwise).
#pragma once

namespace glint {

// Installs the report for every map loaded from here on (environment/environment_source.h).
void reportSlowEnvironmentPrecomputes();

}  // namespace glint
