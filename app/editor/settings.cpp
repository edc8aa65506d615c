// Editor settings file (see settings.h).
#include "editor/settings.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "editor/recovery.h"
#include "util/file_io.h"

namespace glint {
namespace {

std::string settingsPath() { return stateDirectory() + "/settings.json"; }

}  // namespace

Settings loadSettings() {
    Settings settings;
    auto text = readTextFile(settingsPath());
    if (!text) return settings;
    const nlohmann::json document = nlohmann::json::parse(*text, nullptr, false);
    if (!document.is_object()) return settings;
    if (auto recent = document.find("recent_files"); recent != document.end() && recent->is_array())
        for (const auto& entry : *recent)
            if (entry.is_string() && settings.recentFiles.size() < Settings::kMaxRecentFiles)
                settings.recentFiles.push_back(entry.get<std::string>());
    if (auto scale = document.find("ui_scale"); scale != document.end() && scale->is_number()) {
        const float value = scale->get<float>();
        if (value >= 0.75f && value <= 3.0f) settings.uiScale = value;
    }
    if (auto presenting = document.find("presentation_mode"); presenting != document.end() && presenting->is_boolean())
        settings.presentationMode = presenting->get<bool>();
    if (auto scale = document.find("presentation_scale"); scale != document.end() && scale->is_number()) {
        const float value = scale->get<float>();
        if (value >= 1.5f && value <= 3.0f) settings.presentationScale = value;
    }
    if (auto simplify = document.find("simplify_meshes_while_dragging"); simplify != document.end() && simplify->is_boolean())
        settings.simplifyMeshesWhileDragging = simplify->get<bool>();
    if (auto outside = document.find("allow_outside_references"); outside != document.end() && outside->is_boolean())
        settings.allowOutsideReferences = outside->get<bool>();
    return settings;
}

void saveSettings(const Settings& settings) {
    const nlohmann::json document = {{"recent_files", settings.recentFiles}, {"ui_scale", settings.uiScale},
                                     {"presentation_mode", settings.presentationMode},
                                     {"presentation_scale", settings.presentationScale},
                                     {"simplify_meshes_while_dragging", settings.simplifyMeshesWhileDragging},
                                     {"allow_outside_references", settings.allowOutsideReferences}};
    if (ensureParentDirectory(settingsPath())) (void)writeFileAtomically(settingsPath(), document.dump(2) + "\n");
}

void noteRecentFile(Settings& settings, const std::string& path) {
    auto& recent = settings.recentFiles;
    recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
    recent.insert(recent.begin(), path);
    if (recent.size() > Settings::kMaxRecentFiles) recent.resize(Settings::kMaxRecentFiles);
    saveSettings(settings);
}

}  // namespace glint
