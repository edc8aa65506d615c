// Editor settings kept between runs: recent files, the UI scale, presentation mode, whether
// large meshes are simplified while dragging and whether files may name files outside their
// folder, in
// stateDirectory()/settings.json (see app/editor/recovery.h for the directory). A damaged or
// missing file gives the defaults; writes are atomic.
#pragma once

#include <string>
#include <vector>

namespace glint {

struct Settings {
    static constexpr size_t kMaxRecentFiles = 10;
    std::vector<std::string> recentFiles;  // newest first, absolute paths
    float uiScale = 1.0f;                  // HiDPI: font and sizes, 0.75–3
    bool presentationMode = false;         // classroom: large font, high contrast (app/classroom/presentation.h)
    float presentationScale = 2.0f;        // UI scale in presentation mode, 1.5–3
    bool simplifyMeshesWhileDragging = true;  // stand-ins and coarser shadow maps during drags (editor/viewport_refresh.h)
    bool allowOutsideReferences = false;  // read files a file names outside its folder (util/reference_confinement.h)
};

Settings loadSettings();
void saveSettings(const Settings& settings);  // failures are ignored: settings are a convenience
void noteRecentFile(Settings& settings, const std::string& path);  // and saves

}  // namespace glint
