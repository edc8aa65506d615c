// Recovery of unsaved work: where the recovery file lives, what it holds (the scene and the path
// it belongs to) and how it is read back. The file is written by autosave and by the crash
// guard (crash_guard.h); this file does not decide when.
//
// Location: $GLINT_STATE_DIR if set (tests), else $XDG_STATE_HOME/glint, else
// ~/.local/state/glint; the file is recovery.json in that directory.
#pragma once

#include <string>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

std::string stateDirectory();       // created on demand by writeRecovery / settings
std::string recoveryFilePath();     // stateDirectory()/recovery.json

// The recovery document: {"format": "glint-recovery", "version": 1, "scene_path": ..., "scene": {...}}.
std::string recoveryDocument(const Scene& scene, const std::string& scenePath);

struct RecoveredWork {
    Scene scene;
    std::string scenePath;  // the file the work belongs to; empty for a scene never saved
};
// Reads a recovery file; a damaged one gives a Diagnostic naming it.
Result<RecoveredWork> loadRecovery(const std::string& path);

// Makes sure the directory holding `path` exists (like mkdir -p).
Status ensureParentDirectory(const std::string& path);

}  // namespace glint
