// Choosing an environment in the editor without freezing it: the map is read and its lighting
// precomputed on a worker thread (core/environment/environment_source.h) while the editor keeps
// drawing with the environment it had, showing the progress in the Environment section and the
// status bar. A newer choice supersedes a running one (cancelled, its result dropped). When the map
// is ready the choice becomes one undo step, so the scene, its undo history, the recovery file and
// Save never hold a choice without its map: until then they keep the previous environment (a
// choice still running when the editor closes is not saved). A file that cannot be used arrives as
// the usual located message and leaves the scene as it was.
#pragma once

#include <memory>
#include <string>

#include "editor/editor_state.h"
#include "editor/worker_job.h"
#include "environment/environment_source.h"

namespace glint {

class EnvironmentLoadJob : public WorkerJob<Result<std::shared_ptr<const EnvironmentMap>>> {
public:
    // Starts making the map of `kind` (reading `file`, absolute, for kind File) on a new thread.
    EnvironmentLoadJob(EnvironmentKind kind, std::string file);
    EnvironmentKind kind() const { return kind_; }
    const std::string& file() const { return file_; }
    // What the progress bar names: the file's name, or the built-in's.
    std::string name() const;

private:
    EnvironmentKind kind_;
    std::string file_;
};

// Starts making the map for a choice of environment (a file relative to the working directory is
// made absolute), cancelling one still running.
void startEnvironmentLoad(EditorState& state, EnvironmentKind kind, const std::string& file = {});
// Each frame: once the map is ready, the choice becomes the scene's environment (keeping its
// rotation, intensity and background setting) in one undo step; or the error shows. Returns true
// while a map is still being made (the loop keeps drawing frames for the progress bar).
bool pollEnvironmentLoad(EditorState& state);

}  // namespace glint
