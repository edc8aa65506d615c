// Interchange files into the editor's scene (see interchange_open.h).
#include "editor/interchange_open.h"

#include "interchange/import_formats.h"

namespace glint {

bool openInterchangeFile(EditorState& state, const std::string& path) {
    const ImportFormat* format = findImportFormat(path);
    if (!format) return false;
    auto imported = format->load(path);
    if (!imported) {
        state.errorMessage = "Could not open the " + std::string(format->description) +
                             "; your work is unchanged.\n\n" + imported.error().format();
        return true;
    }
    const Scene& scene = state.session.scene();
    if (!imported->materials.empty() && scene.objects.empty()) {
        state.errorMessage = "The scene has no object to put the material on; your work is unchanged.";
        return true;
    }
    if (scene.lights.size() + imported->lights.size() > static_cast<size_t>(kMaxLights)) {
        state.errorMessage = "The file's " + std::to_string(imported->lights.size()) + " lights would pass the limit of " +
                             std::to_string(kMaxLights) + " lights per scene; your work is unchanged.";
        return true;
    }
    const int materialIndex = imported->materials.empty() ? -1 : scene.objects[state.selectedObject].materialIndex;
    Scene& changed = state.session.change("Open " + path);
    if (materialIndex >= 0) changed.materials[materialIndex] = imported->materials.front().material;
    for (const Light& light : imported->lights) changed.lights.push_back(light);
    state.session.settle(false);
    std::string summary = "Opened " + path;
    if (!imported->materials.empty()) summary += ": material '" + imported->materials.front().material.name + "'";
    if (imported->materials.size() > 1)
        summary += " (first of " + std::to_string(imported->materials.size()) + ")";
    if (!imported->lights.empty()) summary += ", " + std::to_string(imported->lights.size()) + " light(s)";
    state.statusMessage = summary;
    // Warnings about the file and the material used; the other materials' are not this open's.
    if (const std::vector<Diagnostic> warnings = warningsFor(*imported, 0); !warnings.empty()) {
        std::string text = "Opened " + path + " with warnings:\n";
        for (const Diagnostic& warning : warnings) text += "\n" + warning.format();
        state.errorMessage = text;
    }
    return true;
}

}  // namespace glint
