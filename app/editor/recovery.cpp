// The recovery file's location, writer and reader (see recovery.h).
#include "editor/recovery.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "util/file_io.h"

namespace glint {

std::string stateDirectory() {
    if (const char* override = std::getenv("GLINT_STATE_DIR"); override && *override) return override;
    if (const char* xdg = std::getenv("XDG_STATE_HOME"); xdg && *xdg) return std::string(xdg) + "/glint";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.local/state/glint";
    return ".glint-state";
}

std::string recoveryFilePath() { return stateDirectory() + "/recovery.json"; }

std::string recoveryDocument(const Scene& scene, const std::string& scenePath) {
    nlohmann::json document = {{"format", "glint-recovery"}, {"version", 1}, {"scene_path", scenePath},
                               {"scene", sceneToJson(scene)}};
    return document.dump(2) + "\n";
}

Result<RecoveredWork> loadRecovery(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    const nlohmann::json document = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || !document.is_object() || document.value("format", "") != "glint-recovery" ||
        !document.contains("scene") || !document["scene"].is_object() ||
        !document.contains("scene_path") || !document["scene_path"].is_string())
        return makeError("not a Glint recovery file (damaged or from another program)", {path});
    auto scene = parseScene(document["scene"].dump(2), path + " (scene)");
    if (!scene) return scene.error();
    return RecoveredWork{std::move(*scene), document["scene_path"].get<std::string>()};
}

Status ensureParentDirectory(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (parent.empty()) return success();
    std::error_code error;
    std::filesystem::create_directories(parent, error);
    if (error) return makeError("cannot create the directory: " + error.message(), {parent.string()});
    return success();
}

}  // namespace glint
