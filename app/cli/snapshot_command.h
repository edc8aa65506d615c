// `glint snapshot SUITE [--out DIR] [--update] [--update-case NAME]... [--jobs N] [--shard I/N]`:
// renders every case of a snapshot suite headless in one process and compares it with its
// golden; writes failing images, an HTML report and JUnit XML. Suite format: docs/snapshot-testing.md.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 all passed, 1 some case failed or errored, 2 the run could not
// happen (bad arguments, bad suite or manifest, no OpenGL context, output not writable).
void addSnapshotCommand(CLI::App& glint);

}  // namespace glint
