// Assets into the editor (see asset_open.h).
#include "editor/asset_open.h"

#include "editor/document.h"
#include "interchange/asset.h"

namespace glint {
namespace {

void openAsset(EditorState& state, const std::string& path) {
    auto asset = loadAsset(path);
    if (!asset) {
        state.errorMessage = "Could not open the asset; your work is unchanged.\n\n" + asset.error().format();
        return;
    }
    const Scene& current = state.session.scene();
    state.session.replace(assetStage(*asset, current.width, current.height), "");
    state.selectedObject = 0;
    state.selectedLight = 0;
    state.statusMessage = "Opened " + path + ": " + assetSummary(*asset);
    if (!asset->warnings.empty()) {
        std::string text = "Opened " + path + " with warnings:\n";
        for (const Diagnostic& warning : asset->warnings) text += "\n" + warning.format();
        state.errorMessage = text;
    }
}

}  // namespace

void openAssetGuarded(EditorState& state, const std::string& path) {
    guardUnsavedChanges(state, "opening " + path, [path](EditorState& guarded) { openAsset(guarded, path); });
}

}  // namespace glint
