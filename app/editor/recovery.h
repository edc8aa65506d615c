// Recovery of unsaved work: where the recovery file lives, what it holds (the scene and the path
// it belongs to) and how it is read back. The file is written by autosave and by the crash
// guard (crash_guard.h); this file does not decide when.
//
// Location: $GLINT_STATE_DIR if set (tests), else $XDG_STATE_HOME/glint, else
// ~/.local/state/glint. Each running editor has its own file there, recovery-PID.json, and holds
// a lock on recovery-PID.lock while it runs, so two editors open at once never overwrite or
// remove each other's work. A file whose lock nobody holds belonged to an editor that crashed or
// was killed: the next start offers it.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

std::string stateDirectory();       // created on demand by writeRecovery / settings
std::string recoveryFilePath();     // this editor's: stateDirectory()/recovery-PID.json

// Removes what editors no longer running left beside their recovery files: lock files and
// half-written copies (.json.crash, .json.tmp-PID). An editor runs while it holds its lock (an
// flock, released by the kernel however the process ends), so a reused process id never makes a
// dead editor's lock look alive, and a live editor's lock is never taken. Their recovery files
// stay, offered by orphanedRecoveryFiles.
void removeStaleRecoveryLeftovers();
// The recovery files of editors no longer running, newest first (recovery.json, written by
// Glint before per-editor files, included). Call before lockRecoveryFile: a file left under this
// process's own id by an earlier process is one of them.
std::vector<std::string> orphanedRecoveryFiles();
// Takes this editor's lock, held until unlockRecoveryFile or the process's end, however it ends;
// an error when the state directory is not writable.
Status lockRecoveryFile();
void unlockRecoveryFile();  // at a clean exit: removes the lock file
// Removes an orphaned recovery file and its lock file, once the user discarded or recovered it.
void removeRecoveryFile(const std::string& path);

// The recovery document: {"format": "glint-recovery", "version": 1, "scene_path": ..., "scene": {...}}.
std::string recoveryDocument(const Scene& scene, const std::string& scenePath);

struct RecoveredWork {
    Scene scene;
    std::string scenePath;     // the file the work belongs to; empty for a scene never saved
    std::string recoveryPath;  // the recovery file it was read from
};
// Reads a recovery file; a damaged one gives a Diagnostic naming it.
Result<RecoveredWork> loadRecovery(const std::string& path);

// Makes sure the directory holding `path` exists (like mkdir -p).
Status ensureParentDirectory(const std::string& path);

}  // namespace glint
