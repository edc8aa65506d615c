// Environment maps made on a worker thread, one at a time, while the editor keeps drawing (a
// 1024×512 HDR file takes seconds); the Environment section and the status bar show the progress.
// A choice (Display ▸ Environment, a dropped .hdr/.exr) becomes one undo step when its map is ready;
// until then the scene, its history, the recovery file and Save keep the previous environment. A
// newer choice supersedes it; opening another scene, New, a lesson or recovered work cancels it.
// The environment a scene names (read with EnvironmentMapLoading::Later) is drawn without its map
// until it is ready, then the map joins every state naming it, no step and nothing unsaved. A file
// that cannot be used shows its located message (a named one stays named, unlit, as if cancelled).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "editor/editor_state.h"
#include "editor/worker_job.h"
#include "environment/environment_source.h"

namespace glint {

class EnvironmentLoadJob : public WorkerJob<Result<std::shared_ptr<const EnvironmentMap>>> {
public:
    // Starts making the map of `kind` (reading `file`, absolute, for kind File) on a new thread: a
    // choice made after `replacements` (EditSession::replacements), or the one the scene names.
    EnvironmentLoadJob(EnvironmentKind kind, std::string file, bool choice, std::uint64_t replacements);
    // "precomputing NAME 43%": the status bar's words and the progress bar's.
    std::string progressText() const {
        return "precomputing " + environmentName(kind, file) + " " + std::to_string(static_cast<int>(100.0f * progress())) + "%";
    }

    const EnvironmentKind kind;
    const std::string file;
    const bool choice;
    const std::uint64_t replacements;
};

// Starts making the map for a choice of environment (a file relative to the working directory is
// made absolute), cancelling the job running.
void startEnvironmentLoad(EditorState& state, EnvironmentKind kind, const std::string& file = {});
// Each frame: cancels a choice made for a scene since replaced, starts making the map of the
// environment the scene names when it has none yet, and lands a finished map (or shows its error).
// Returns true while a map is still being made (the loop keeps drawing frames for the progress bar).
bool pollEnvironmentLoad(EditorState& state);

}  // namespace glint
