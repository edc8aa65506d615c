// `glint bench [--frames N] [--quick] [--json FILE]`: times the standard scenes (bench_scenes.h)
// at 1280×720, each against the bare shading pass of the same material and lights measured in
// the same run (a ratio), then the headless cold start, thumbnails per second and peak memory.
// Prints an aligned table; --json writes the same figures for comparison over time.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 measured, 1 a scene or child process failed, 2 bad arguments or no
// context.
void addBenchCommand(CLI::App& glint);

}  // namespace glint
