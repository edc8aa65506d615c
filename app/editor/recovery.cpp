// The recovery file's location, writer and reader (see recovery.h).
#include "editor/recovery.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"

namespace glint {

std::string stateDirectory() {
    if (const char* override = std::getenv("GLINT_STATE_DIR"); override && *override) return override;
    if (const char* xdg = std::getenv("XDG_STATE_HOME"); xdg && *xdg) return std::string(xdg) + "/glint";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.local/state/glint";
    return ".glint-state";
}

namespace {

std::string lockPathOf(const std::string& recoveryPath) {
    return std::filesystem::path(recoveryPath).replace_extension(".lock").string();
}

int gLockDescriptor = -1;

bool lockedByARunningEditor(const std::string& recoveryPath) {
    const int descriptor = ::open(lockPathOf(recoveryPath).c_str(), O_RDWR | O_CLOEXEC);
    if (descriptor < 0) return false;
    const bool held = ::flock(descriptor, LOCK_EX | LOCK_NB) != 0;
    ::close(descriptor);
    return held;
}

}  // namespace

std::string recoveryFilePath() { return stateDirectory() + "/recovery-" + std::to_string(::getpid()) + ".json"; }

std::vector<std::string> orphanedRecoveryFiles() {
    std::vector<std::pair<std::filesystem::file_time_type, std::string>> found;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(stateDirectory(), error)) {
        const std::string name = entry.path().filename().string();
        const bool recovery = name == "recovery.json" || (name.starts_with("recovery-") && name.ends_with(".json"));
        if (recovery && !lockedByARunningEditor(entry.path().string()))
            found.emplace_back(entry.last_write_time(error), entry.path().string());
    }
    std::sort(found.rbegin(), found.rend());
    std::vector<std::string> paths;
    for (auto& [time, path] : found) paths.push_back(std::move(path));
    return paths;
}

void removeStaleRecoveryLeftovers() {
    std::error_code error;
    std::vector<std::filesystem::path> staleLocks;
    for (const auto& entry : std::filesystem::directory_iterator(stateDirectory(), error)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("recovery-") && name.ends_with(".lock")) staleLocks.push_back(entry.path());
    }
    for (const std::filesystem::path& lock : staleLocks) {
        const int descriptor = ::open(lock.c_str(), O_RDWR | O_CLOEXEC);
        if (descriptor < 0) continue;
        // Removed while this process holds the lock, so an editor that created the file but has
        // not locked it yet finds it gone and makes another (lockRecoveryFile).
        if (::flock(descriptor, LOCK_EX | LOCK_NB) == 0) {
            const std::string temporaryPrefix = lock.stem().string() + ".json.";  // .crash, .tmp-PID
            for (const auto& entry : std::filesystem::directory_iterator(lock.parent_path(), error))
                if (entry.path().filename().string().starts_with(temporaryPrefix)) std::filesystem::remove(entry.path(), error);
            std::filesystem::remove(lock, error);
        }
        ::close(descriptor);
    }
}

Status lockRecoveryFile() {
    unlockRecoveryFile();
    const std::string path = lockPathOf(recoveryFilePath());
    if (Status made = ensureParentDirectory(path); !made) return made;
    // Another editor starting may remove the file between its creation and the lock (as a dead
    // editor's): the lock counts only on the file still found under `path`.
    for (int attempt = 0; attempt < 10; ++attempt) {
        const int descriptor = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (descriptor < 0 || ::flock(descriptor, LOCK_EX) != 0) {
            const int cause = errno;
            if (descriptor >= 0) ::close(descriptor);
            return makeError(std::string("cannot lock: ") + std::strerror(cause), {path});
        }
        struct stat locked{}, named{};
        if (::fstat(descriptor, &locked) == 0 && ::stat(path.c_str(), &named) == 0 && locked.st_dev == named.st_dev &&
            locked.st_ino == named.st_ino) {
            gLockDescriptor = descriptor;
            return success();
        }
        ::close(descriptor);
    }
    return makeError("cannot lock: the lock file kept being removed by other editors starting", {path});
}

void unlockRecoveryFile() {
    if (gLockDescriptor < 0) return;
    std::error_code error;
    std::filesystem::remove(lockPathOf(recoveryFilePath()), error);
    ::close(gLockDescriptor);
    gLockDescriptor = -1;
}

void removeRecoveryFile(const std::string& path) {
    std::error_code error;
    std::filesystem::remove(path, error);
    if (path != recoveryFilePath()) std::filesystem::remove(lockPathOf(path), error);  // never this editor's lock
}

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
    const OutsideReferencesAllowance ownFile;  // Glint wrote it, naming the user's files by absolute path
    auto scene = parseScene(document["scene"].dump(2), path + " (scene)", EnvironmentMapLoading::Later);
    if (!scene) return scene.error();
    return RecoveredWork{std::move(*scene), document["scene_path"].get<std::string>(), path};
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
