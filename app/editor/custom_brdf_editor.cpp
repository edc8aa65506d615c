// Editor actions for .brdf and .bparam files (see custom_brdf_editor.h).
// Sections: probing · open and save · hot reload.
#include "editor/custom_brdf_editor.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "runtime/brdf_probe.h"
#include "interchange/bparam_file.h"
#include "util/file_io.h"
#include "util/referenced_file_error.h"
#include "util/text.h"

namespace glint {
namespace {

// --- probing --------------------------------------------------------------------------------

void startProbe(EditorState& state, std::shared_ptr<const CustomBrdf> brdf, std::vector<float> values, bool reload,
                int materialIndex) {
    const double timeout = brdfProbeTimeoutSeconds();
    std::function<void()> wake = state.customBrdfs.wake;
    PendingBrdfProbe pending{brdf, values, reload, materialIndex, {}};
    pending.result = std::async(std::launch::async, [brdf, values, timeout, wake] {
        Status probed = probeCustomBrdf(*brdf, values, timeout);
        if (wake) wake();
        return probed;
    });
    state.customBrdfs.pending = std::move(pending);
    state.statusMessage = "Checking " + brdf->displayName + " (compiles, and finishes within " + formatNumber(timeout) +
                          " s)…";
}

void finishProbe(EditorState& state, PendingBrdfProbe& pending, const Status& verdict) {
    const CustomBrdf& brdf = *pending.brdf;
    state.customBrdfs.seenModification[brdf.file.path] = fileModificationTime(brdf.file.path);
    if (!verdict) {
        const std::string message = brdf.displayName + " was not used:\n" + verdict.error().format();
        if (pending.reload) {
            state.materialPanelMessage = message + "\nThe last good version stays on screen.";
            state.statusMessage = brdf.displayName + " changed but was not used (see the material panel)";
        } else {
            state.errorMessage = message + "\n\nYour material is unchanged.";
            state.statusMessage.clear();
        }
        return;
    }
    const Scene& scene = state.session.scene();
    if (!pending.reload) {
        if (pending.materialIndex >= static_cast<int>(scene.materials.size())) return;
        // The defaults, or a .bparam file's values.
        Material material{scene.materials[pending.materialIndex].name, CustomMaterial{pending.brdf, pending.values}};
        state.session.change("Open " + brdf.displayName).materials[pending.materialIndex] = std::move(material);
        state.statusMessage = "Custom BRDF from " + brdf.file.path;
    } else {
        Scene& changed = state.session.change("Reload " + brdf.displayName);
        for (Material& material : changed.materials) {
            CustomMaterial* custom = material.custom();
            if (!custom || custom->brdf->file.path != brdf.file.path) continue;
            custom->values = carriedValues(custom->brdf->table, custom->values, brdf.table);  // a reloaded file keeps what it can
            custom->brdf = pending.brdf;
        }
        state.materialPanelMessage.clear();
        state.statusMessage = "Reloaded " + brdf.file.path;
    }
    state.session.settle(false);
}

// What a file held that Glint skipped, shown as the open goes on.
void showWarnings(EditorState& state, const std::string& path, const std::vector<Diagnostic>& warnings) {
    if (warnings.empty()) return;
    std::string text = "Opened " + path + " with warnings:\n";
    for (const Diagnostic& warning : warnings) text += "\n" + warning.format();
    state.errorMessage = text;
}

}  // namespace

// --- open and save --------------------------------------------------------------------------

void openBrdfFile(EditorState& state, const std::string& path, std::vector<float> values,
                  const std::vector<Diagnostic>& warnings) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) {
        state.errorMessage = "The scene has no object to put the BRDF on.";
        return;
    }
    if (state.customBrdfs.pending) {
        state.errorMessage = "Another .brdf file is still being checked; try again in a moment.";
        return;
    }
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    auto brdf = loadCustomBrdf(absolute);
    if (!brdf) {
        state.errorMessage = "Could not open the BRDF; your work is unchanged.\n\n" + brdf.error().format();
        return;
    }
    const int materialIndex = scene.objects[state.selectedObject].materialIndex;
    if (values.size() != static_cast<size_t>(packedSize((*brdf)->table))) values = defaultValues((*brdf)->table);
    std::vector<Diagnostic> all = (*brdf)->file.warnings;
    all.insert(all.end(), warnings.begin(), warnings.end());
    startProbe(state, std::move(*brdf), std::move(values), false, materialIndex);
    showWarnings(state, path, all);
}

void openBparamFile(EditorState& state, const std::string& path) {
    auto text = readTextFile(path);
    auto file = text ? parseBparamFile(*text, path) : Result<BparamFile>(text.error());
    if (!file) {
        state.errorMessage = "Could not read the parameter values; your material is unchanged.\n\n" + file.error().format();
        return;
    }
    const Scene& scene = state.session.scene();
    const int materialIndex = scene.objects.empty() ? -1 : scene.objects[state.selectedObject].materialIndex;
    const CustomMaterial* custom = materialIndex < 0 ? nullptr : scene.materials[materialIndex].custom();
    std::vector<Diagnostic> warnings = file->warnings;
    // A file naming another .brdf than the selected material's (BRDF Explorer's first line
    // `bparam NAME.brdf`) opens that .brdf with its values, as BRDF Explorer does.
    const bool sameBrdf = custom && (file->brdfPath.empty() || std::filesystem::path(file->brdfPath).filename() ==
                                                                   std::filesystem::path(custom->brdf->file.path).filename());
    if (!sameBrdf) {
        auto brdfPath = findBparamBrdf(*file, path);
        if (!brdfPath) {
            state.errorMessage = "A .bparam file holds parameter values for a .brdf material; your work is unchanged.\n\n" +
                                 brdfPath.error().format();
            return;
        }
        auto brdf = loadBrdfFile(*brdfPath);
        if (!brdf) {
            state.errorMessage = "Could not open the BRDF the file names; your work is unchanged.\n\n" +
                                 referencedFileProblem(*brdfPath, brdf.error(), ".brdf file");
            return;
        }
        auto named = makeCustomBrdf(std::move(*brdf));
        std::vector<float> values = applyBparam(*file, *named, defaultValues(named->table), warnings);
        return openBrdfFile(state, *brdfPath, std::move(values), warnings);
    }
    std::vector<float> values = applyBparam(*file, *custom->brdf, custom->values, warnings);
    state.session.change("Open " + std::filesystem::path(path).filename().string()).materials[materialIndex].custom()->values =
        std::move(values);
    state.session.settle(false);
    state.statusMessage = "Parameter values from " + path;
    showWarnings(state, path, warnings);
}

bool saveBparamTo(EditorState& state, const std::string& path) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) return false;
    const CustomMaterial* custom = scene.materials[scene.objects[state.selectedObject].materialIndex].custom();
    if (!custom) {
        state.errorMessage = "The selected material is not a .brdf material; .bparam files hold .brdf parameter values.";
        return false;
    }
    if (Status saved = saveBparam(path, *custom->brdf, custom->values); !saved) {
        state.errorMessage = "Could not save the parameter values.\n\n" + saved.error().format();
        return false;
    }
    state.statusMessage = "Saved parameter values " + path;
    return true;
}

// --- hot reload -----------------------------------------------------------------------------

double pollCustomBrdfs(EditorState& state, double nowSeconds) {
    constexpr double kPollInterval = 0.5;
    CustomBrdfEditorState& brdfs = state.customBrdfs;
    if (brdfs.pending) {
        if (brdfs.pending->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return kPollInterval;
        PendingBrdfProbe finished = std::move(*brdfs.pending);
        brdfs.pending.reset();
        finishProbe(state, finished, finished.result.get());
    }
    bool anyCustom = false;
    for (const Material& material : state.session.scene().materials) anyCustom |= material.custom() != nullptr;
    if (!anyCustom) return 1e9;
    if (nowSeconds - brdfs.lastPollSeconds < kPollInterval) return brdfs.lastPollSeconds + kPollInterval - nowSeconds;
    brdfs.lastPollSeconds = nowSeconds;
    for (const Material& material : state.session.scene().materials) {
        const CustomMaterial* custom = material.custom();
        if (!custom) continue;
        const std::string& path = custom->brdf->file.path;
        const long long modified = fileModificationTime(path);
        auto [seen, added] = brdfs.seenModification.try_emplace(path, modified);
        if (added || modified == seen->second || modified == 0) continue;
        seen->second = modified;
        auto reloaded = loadCustomBrdf(path);
        if (!reloaded) {
            state.materialPanelMessage = custom->brdf->displayName + " changed but cannot be used:\n" +
                                         reloaded.error().format() + "\nThe last good version stays on screen.";
            continue;
        }
        startProbe(state, *reloaded, carriedValues(custom->brdf->table, custom->values, (*reloaded)->table), true, 0);
        break;  // one probe at a time
    }
    return kPollInterval;
}

}  // namespace glint
