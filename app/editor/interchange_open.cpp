// Interchange files into the editor's scene (see interchange_open.h).
#include "editor/interchange_open.h"

#include <string>
#include <utility>
#include <vector>

#include "interchange/import_formats.h"
#include "scene/scene.h"

namespace glint {
namespace {

// Why `imported` cannot go into the scene as it is now, or empty.
std::string refusal(const EditorState& state, const ImportedFile& imported) {
    const Scene& scene = state.session.scene();
    if (!imported.materials.empty() && scene.objects.empty())
        return "The scene has no object to put the material on; your work is unchanged.";
    if (scene.lights.size() + imported.lights.size() > static_cast<size_t>(kMaxLights))
        return "The file's " + std::to_string(imported.lights.size()) + " lights and the scene's " +
               std::to_string(scene.lights.size()) + " are too many: " + lightLimitExplanation() + ". Your work is unchanged.";
    return {};
}

// Material `index` of `imported` onto the selected object, its lights into the scene: one step.
void apply(EditorState& state, const std::string& path, const ImportedFile& imported, size_t index) {
    if (std::string refused = refusal(state, imported); !refused.empty()) {
        state.errorMessage = std::move(refused);
        return;
    }
    const Scene& scene = state.session.scene();
    const int materialIndex = imported.materials.empty() ? -1 : scene.objects[state.selectedObject].materialIndex;
    Scene& changed = state.session.change("Open " + path);
    if (materialIndex >= 0) changed.materials[materialIndex] = imported.materials[index].material;
    for (const Light& light : imported.lights) changed.lights.push_back(light);
    state.session.settle(false);
    std::string summary = "Opened " + path;
    if (!imported.materials.empty()) summary += ": material '" + imported.materials[index].material.name + "'";
    if (imported.materials.size() > 1)
        summary += " (" + std::to_string(index + 1) + " of " + std::to_string(imported.materials.size()) + ")";
    if (!imported.lights.empty()) summary += ", " + std::to_string(imported.lights.size()) + " light(s)";
    state.statusMessage = summary;
    // Warnings about the file and the material used; the other materials' are not this open's.
    if (const std::vector<Diagnostic> warnings = warningsFor(imported, index); !warnings.empty()) {
        std::string text = "Opened " + path + " with warnings:\n";
        for (const Diagnostic& warning : warnings) text += "\n" + warning.format();
        state.errorMessage = text;
    }
}

}  // namespace

bool openInterchangeFile(EditorState& state, const std::string& path) {
    const ImportFormat* format = findImportFormat(path);
    if (!format) return false;
    auto imported = format->load(path);
    if (!imported) {
        state.errorMessage = "Could not open the " + std::string(format->description) +
                             "; your work is unchanged.\n\n" + imported.error().format();
        return true;
    }
    if (imported->materials.size() > 1) {
        if (std::string refused = refusal(state, *imported); !refused.empty()) state.errorMessage = std::move(refused);
        else state.materialChoice = MaterialChoice{path, std::move(*imported)};
        return true;
    }
    apply(state, path, *imported, 0);
    return true;
}

void takeMaterialChoice(EditorState& state, size_t index) {
    if (!state.materialChoice) return;
    const MaterialChoice choice = std::move(*state.materialChoice);
    state.materialChoice.reset();
    if (index < choice.file.materials.size()) apply(state, choice.path, choice.file, index);
}

void cancelMaterialChoice(EditorState& state) {
    if (!state.materialChoice) return;
    state.statusMessage = "Did not open " + state.materialChoice->path;
    state.materialChoice.reset();
}

}  // namespace glint
