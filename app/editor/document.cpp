// Document actions (see document.h).
// Sections: scenes · materials · unsaved-changes guard · recovery and autosave.
#include "editor/document.h"

#include <filesystem>
#include <system_error>

#include "classroom/lesson_document.h"
#include "runtime/brdf_probe.h"
#include "editor/crash_guard.h"
#include "editor/environment_loading.h"
#include "editor/mesh_loading.h"
#include "editor/asset_open.h"
#include "editor/interchange_open.h"
#include "editor/custom_brdf_editor.h"
#include "interchange/bparam_file.h"
#include "interchange/custom_brdf.h"
#include "interchange/asset.h"
#include "editor/settings.h"
#include "scene/scene_json.h"
#include "util/file_io.h"
#include "util/text.h"

namespace glint {

// --- scenes ---------------------------------------------------------------------------------

void openSceneFile(EditorState& state, const std::string& path) {
    auto loaded = loadScene(path, EnvironmentMapLoading::Later);  // the map is made on a worker (environment_loading.h)
    if (!loaded) {
        state.errorMessage = "Could not open the scene; your work is unchanged.\n\n" + loaded.error().format();
        return;
    }
    if (Status probed = probeSceneBrdfs(*loaded, brdfProbeTimeoutSeconds()); !probed) {  // .brdf materials
        state.errorMessage = "Could not open the scene; your work is unchanged.\n\n" + probed.error().format();
        return;
    }
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    state.session.replace(std::move(*loaded), absolute);
    state.selectedObject = 0;
    state.selectedLight = 0;
    noteRecentFile(state.settings, absolute);
    state.statusMessage = "Opened " + absolute;
}

bool saveSceneTo(EditorState& state, const std::string& path) {
    if (isLessonFile(state, path)) {
        state.errorMessage = "Lessons are course material and stay as shipped: save your version under another name.\n\n" + path;
        return false;
    }
    state.session.settle(false);
    if (Status saved = glint::saveScene(state.session.scene(), path); !saved) {
        state.errorMessage = "Could not save the scene.\n\n" + saved.error().format();
        return false;
    }
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    state.session.markSaved(absolute);
    noteRecentFile(state.settings, absolute);
    state.statusMessage = "Saved " + absolute;
    return true;
}

void saveScene(EditorState& state) {
    if (state.session.path().empty()) requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, "untitled.json");
    else saveSceneTo(state, state.session.path());
}

void newScene(EditorState& state) {
    state.session.replace(defaultScene(), "");
    state.selectedObject = 0;
    state.selectedLight = 0;
    state.statusMessage = "New scene";
}

// --- materials ------------------------------------------------------------------------------

void openMaterialFile(EditorState& state, const std::string& path) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) {
        state.errorMessage = "The scene has no object to put the material on.";
        return;
    }
    auto loaded = loadMaterial(path);
    if (const CustomMaterial* custom = loaded ? loaded->custom() : nullptr)  // a .brdf material: proven to finish before it is drawn
        if (Status probed = probeCustomBrdf(*custom->brdf, custom->values, brdfProbeTimeoutSeconds()); !probed)
            loaded = probed.error();
    if (!loaded) {
        state.errorMessage = "Could not open the material; your work is unchanged.\n\n" + loaded.error().format();
        return;
    }
    const int materialIndex = scene.objects[state.selectedObject].materialIndex;
    state.session.change("Open material").materials[materialIndex] = std::move(*loaded);
    state.session.settle(false);
    state.statusMessage = "Material from " + path;
}

bool saveMaterialTo(EditorState& state, const std::string& path) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) return false;
    const Material& material = scene.materials[scene.objects[state.selectedObject].materialIndex];
    if (Status saved = glint::saveMaterial(material, path); !saved) {
        state.errorMessage = "Could not save the material.\n\n" + saved.error().format();
        return false;
    }
    state.statusMessage = "Saved material " + path;
    return true;
}

void openDroppedFile(EditorState& state, const std::string& path) {
    state.lastOpenedPath = path;
    if (isBrdfFilePath(path)) return openBrdfFile(state, path);  // BRDF Explorer files
    if (isBparamFilePath(path)) return openBparamFile(state, path);
    // An .obj, a .gltf or .glb with meshes: the asset, replacing the scene (File ▸ Open mesh… adds
    // a file as one mesh object instead).
    if (isAssetFile(path)) return openAssetGuarded(state, path);
    // .mtl, a .gltf of materials and lights: a material (and glTF lights), by extension
    // (interchange/import_formats.h).
    if (openInterchangeFile(state, path)) return;
    if (isMeshFile(path)) {  // a new object, loaded in the background; not added again once references are allowed
        state.lastOpenedPath.clear();
        return startMeshLoad(state, path);
    }
    if (const std::string extension = lowerExtension(path); extension == "hdr" || extension == "exr")
        return startEnvironmentLoad(state, EnvironmentKind::File, path);  // the environment, made on a worker
    auto text = readTextFile(path);
    if (text && text->find("\"glint-material\"") != std::string::npos) openMaterialFile(state, path);
    else openSceneGuarded(state, path);
}

// --- unsaved-changes guard ------------------------------------------------------------------

void openSceneGuarded(EditorState& state, const std::string& path) {
    state.pendingOpenPath = path;
    guardUnsavedChanges(state, "opening " + path, nullptr);
}

void guardUnsavedChanges(EditorState& state, const std::string& what, std::function<void(EditorState&)> action) {
    state.actionAfterPrompt = std::move(action);
    state.actionAfterPromptName = what;
    if (hasUnsavedWork(state)) state.unsavedPromptRequested = true;  // camera moves in a lesson do not count
    else runActionAfterPrompt(state);
}

void runActionAfterPrompt(EditorState& state) {
    auto action = state.actionAfterPrompt;
    state.actionAfterPrompt = nullptr;
    if (!state.pendingOpenPath.empty()) {
        const std::string path = std::move(state.pendingOpenPath);
        state.pendingOpenPath.clear();
        openSceneFile(state, path);
    }
    if (action) action(state);
}

void requestQuit(EditorState& state) {
    guardUnsavedChanges(state, "closing Glint", [](EditorState& s) { s.quitNow = true; });
}

// --- recovery and autosave ------------------------------------------------------------------

void startRecovery(EditorState& state) {
    removeStaleRecoveryLeftovers();
    const std::vector<std::string> orphans = orphanedRecoveryFiles();  // before this editor's own lock
    const std::string path = recoveryFilePath();
    // The crash handler cannot create directories: the state directory must exist beforehand.
    if (Status locked = lockRecoveryFile(); !locked)
        state.statusMessage = "No crash recovery: " + locked.error().format();
    installCrashGuard(path);
    for (const std::string& orphan : orphans) {
        auto recovered = loadRecovery(orphan);
        if (recovered) state.recoveryOffer.push_back(std::move(*recovered));
        else
            state.errorMessage = "A recovery file was found but cannot be read; it is kept for you to inspect.\n\n" +
                                 recovered.error().format();
    }
}

double autosave(EditorState& state, double nowSeconds, double autosaveIntervalSeconds) {
    const EditSession& session = state.session;
    if (session.settledRevision() == state.autosavedRevision) return 1e9;
    // Something changed since the last write. The crash copy follows at once (cheap: no disk).
    if (state.crashCopyRevision != session.settledRevision()) {
        publishCrashCopy(hasUnsavedWork(state) ? recoveryDocument(session.scene(), session.path()) : std::string());
        state.crashCopyRevision = session.settledRevision();
    }
    if (!state.recoveryOffer.empty()) return 1e9;  // never overwrite work the user has not decided on
    const double wait = state.lastAutosaveSeconds + autosaveIntervalSeconds - nowSeconds;
    if (wait > 0) return wait;
    const std::string path = recoveryFilePath();
    if (hasUnsavedWork(state)) {
        Status written = ensureParentDirectory(path);
        if (written) written = writeFileAtomically(path, recoveryDocument(session.scene(), session.path()));
        if (!written) state.statusMessage = "Autosave failed: " + written.error().format();
        else state.wroteRecovery = true;
    } else if (state.wroteRecovery) {
        std::error_code error;
        std::filesystem::remove(path, error);  // back at the saved state: nothing to recover
        state.wroteRecovery = false;
    }
    state.autosavedRevision = session.settledRevision();
    state.lastAutosaveSeconds = nowSeconds;
    return 1e9;
}

void finishRecovery(EditorState& state) {
    uninstallCrashGuard();
    // Only a file this editor wrote goes: one the user never answered, or one that could not be
    // read, stays for the next start or for inspection.
    if (state.wroteRecovery) {
        std::error_code error;
        std::filesystem::remove(recoveryFilePath(), error);
    }
    unlockRecoveryFile();
}

}  // namespace glint
