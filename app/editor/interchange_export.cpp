// Exporting the selected material from the editor (see interchange_export.h).
#include "editor/interchange_export.h"

#include "interchange/export_formats.h"
#include "util/file_io.h"

namespace glint {

bool exportMaterialTo(EditorState& state, const std::string& path) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) return false;
    const ImportedMaterial selected{scene.materials[scene.objects[state.selectedObject].materialIndex], {}};
    auto written = exportMaterials({&selected, 1}, scene.lights, path);
    if (!written) {
        state.errorMessage = "Could not export the material.\n\n" + written.error().format();
        return false;
    }
    if (Status saved = writeFileAtomically(path, written->text); !saved) {
        state.errorMessage = "Could not export the material.\n\n" + saved.error().format();
        return false;
    }
    state.statusMessage = "Exported material '" + selected.material.name + "' to " + path;
    if (!written->warnings.empty()) {
        std::string text = "Exported " + path + ", but the format cannot hold everything:\n";
        for (const Diagnostic& warning : written->warnings) text += "\n" + warning.format();
        state.errorMessage = text;
    }
    return true;
}

}  // namespace glint
