// The file browser: an ImGui modal listing a directory (folders first, files filtered by
// extension), with a typed path field, for opening and saving scenes, materials and
// screenshots, and opening environment images. It only picks a path; it reads and writes no file.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace glint {

enum class FilePurpose {
    OpenScene, SaveSceneAs, OpenMaterial, SaveMaterialAs, SaveScreenshot, OpenMesh, OpenTexture, OpenBrdf, SaveBparamAs,
    OpenEnvironment, ExportMaterial
};

struct FileBrowser {
    bool requested = false;  // open the modal on the next frame
    FilePurpose purpose = FilePurpose::OpenScene;
    std::string directory;               // absolute
    std::vector<std::string> extensions; // e.g. {".json"}; the first is added to typed names when saving
    std::string typedPath;               // the path field (a name, or a relative or absolute path)
    // Grows whenever the editor itself sets typedPath, and the field takes a new id: Dear ImGui
    // 1.86 keeps a field's undo history across activations of the same id even when its text
    // changed in between, and Ctrl+Z in the field then writes outside the text (found by the
    // monkey soak: AddressSanitizer, heap-buffer-overflow in STB_TEXTEDIT_INSERTCHARS).
    int pathFieldGeneration = 0;
    std::string error;                   // e.g. "no such directory"
};

// Asks for the modal; `startPath` is a file or directory to start in ("" = current directory).
void requestFileBrowser(FileBrowser& browser, FilePurpose purpose, const std::string& startPath);
// Draws the modal when open; returns the chosen absolute path on the frame the user confirms.
std::optional<std::string> drawFileBrowser(FileBrowser& browser);

bool purposeSaves(FilePurpose purpose);

}  // namespace glint
