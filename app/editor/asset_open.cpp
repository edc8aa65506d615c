// Assets into the editor (see asset_open.h).
#include "editor/asset_open.h"

#include "editor/document.h"
#include "editor/mesh_loading.h"

namespace glint {

void openAssetGuarded(EditorState& state, const std::string& path) {
    guardUnsavedChanges(state, "opening " + path,
                        [path](EditorState& guarded) { startMeshLoad(guarded, path, MeshLoadKind::Asset); });
}

void openLoadedAsset(EditorState& state, const std::string& path, const Asset& asset) {
    const Scene& current = state.session.scene();
    state.session.replace(assetStage(asset, current.width, current.height), "");
    state.selectedObject = 0;
    state.selectedLight = 0;
    state.statusMessage = "Opened " + path + ": " + assetSummary(asset);
    if (!asset.warnings.empty()) {
        std::string text = "Opened " + path + " with warnings:\n";
        for (const Diagnostic& warning : asset.warnings) text += "\n" + warning.format();
        state.errorMessage = text;
    }
}

}  // namespace glint
