// `glint thumbnails DIR -o OUTDIR [--size N] [--jobs N] [--columns N]`: renders every material
// (and scene) file in DIR headless, one PNG each (materials on the preview stage), and a
// labelled contact sheet, all in one process.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 all written, 1 some files could not be rendered (the rest were),
// 2 nothing could be done (bad arguments, unreadable directory, no context, no font).
void addThumbnailsCommand(CLI::App& glint);

}  // namespace glint
