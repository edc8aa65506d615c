// The file browser modal (see file_browser.h), on std::filesystem.
#include "editor/panels/file_browser.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "editor/key_events.h"
#include "geometry/mesh_import.h"
#include "interchange/import_formats.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

const char* titleFor(FilePurpose purpose) {
    switch (purpose) {
        case FilePurpose::OpenScene: return "Open scene###FileBrowser";
        case FilePurpose::SaveSceneAs: return "Save scene as###FileBrowser";
        case FilePurpose::OpenMaterial: return "Open material###FileBrowser";
        case FilePurpose::SaveMaterialAs: return "Save material as###FileBrowser";
        case FilePurpose::SaveScreenshot: return "Save screenshot (.png or .exr)###FileBrowser";
        case FilePurpose::OpenMesh: return "Open mesh (adds an object)###FileBrowser";
        case FilePurpose::OpenTexture: return "Open texture image###FileBrowser";
        case FilePurpose::OpenBrdf: return "Open BRDF Explorer file (.brdf, .bparam)###FileBrowser";
        case FilePurpose::SaveBparamAs: return "Save parameter values as (.bparam)###FileBrowser";
        case FilePurpose::OpenEnvironment: return "Open environment (.hdr or .exr)###FileBrowser";
        case FilePurpose::ExportMaterial: return "Export material as (.gltf, .mtl or .mtlx)###FileBrowser";
    }
    return "###FileBrowser";
}

bool matchesFilter(const fs::path& path, const std::vector<std::string>& extensions) {
    const std::string extension = path.extension().string();
    return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

struct Listing {
    std::vector<std::string> directories, files;
};

Listing listDirectory(const std::string& directory, const std::vector<std::string>& extensions) {
    Listing listing;
    std::error_code error;
    for (fs::directory_iterator it(directory, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code statError;
        if (it->is_directory(statError)) listing.directories.push_back(name);
        else if (matchesFilter(it->path(), extensions)) listing.files.push_back(name);
    }
    std::sort(listing.directories.begin(), listing.directories.end());
    std::sort(listing.files.begin(), listing.files.end());
    return listing;
}

// Resolves the typed path against the current directory; a directory is entered instead.
std::optional<std::string> confirm(FileBrowser& browser) {
    if (browser.typedPath.empty()) {
        browser.error = "type a file name or pick a file";
        return std::nullopt;
    }
    fs::path chosen = fs::path(browser.typedPath);
    if (chosen.is_relative()) chosen = fs::path(browser.directory) / chosen;
    chosen = chosen.lexically_normal();
    std::error_code error;
    if (fs::is_directory(chosen, error)) {
        browser.directory = chosen.string();
        browser.typedPath.clear();
        ++browser.pathFieldGeneration;
        browser.error.clear();
        return std::nullopt;
    }
    if (purposeSaves(browser.purpose)) {
        if (!chosen.has_extension() && !browser.extensions.empty()) chosen += browser.extensions.front();
        if (!fs::is_directory(chosen.parent_path(), error)) {
            browser.error = "no such folder: " + chosen.parent_path().string();
            return std::nullopt;
        }
    } else if (!fs::exists(chosen, error)) {
        browser.error = "no such file: " + chosen.string();
        return std::nullopt;
    }
    browser.error.clear();
    return chosen.string();
}

}  // namespace

bool purposeSaves(FilePurpose purpose) {
    return purpose == FilePurpose::SaveSceneAs || purpose == FilePurpose::SaveMaterialAs || purpose == FilePurpose::SaveBparamAs ||
           purpose == FilePurpose::SaveScreenshot || purpose == FilePurpose::ExportMaterial;
}

void requestFileBrowser(FileBrowser& browser, FilePurpose purpose, const std::string& startPath) {
    browser.requested = true;
    ++browser.pathFieldGeneration;  // typedPath is set below
    browser.purpose = purpose;
    browser.extensions = purpose == FilePurpose::SaveScreenshot ? std::vector<std::string>{".png", ".exr"}
                         : purpose == FilePurpose::OpenTexture
                             ? std::vector<std::string>{".png", ".jpg", ".jpeg", ".exr", ".hdr", ".tif", ".tiff"}
                         : purpose == FilePurpose::OpenEnvironment ? std::vector<std::string>{".hdr", ".exr"}
                         : purpose == FilePurpose::OpenBrdf     ? std::vector<std::string>{".brdf", ".bparam"}
                         : purpose == FilePurpose::SaveBparamAs ? std::vector<std::string>{".bparam"}
                         : purpose == FilePurpose::ExportMaterial ? std::vector<std::string>{".gltf", ".mtl", ".mtlx"}
                                                                : std::vector<std::string>{".json"};
    if (purpose == FilePurpose::OpenMesh) {
        browser.extensions.clear();
        for (const std::string& extension : meshFileExtensions()) browser.extensions.push_back("." + extension);
    }
    if (purpose == FilePurpose::OpenScene || purpose == FilePurpose::OpenMaterial)  // .mtl, .gltf, ...
        for (const ImportFormat& format : importFormats()) browser.extensions.push_back(format.extension);
    browser.error.clear();
    std::error_code error;
    fs::path start = startPath.empty() ? fs::current_path(error) : fs::absolute(startPath, error);
    browser.typedPath.clear();
    if (!fs::is_directory(start, error)) {
        if (purposeSaves(purpose)) browser.typedPath = start.filename().string();
        start = start.parent_path();
    }
    browser.directory = start.lexically_normal().string();
}

std::optional<std::string> drawFileBrowser(FileBrowser& browser) {
    const char* title = titleFor(browser.purpose);
    if (browser.requested) {
        ImGui::OpenPopup(title);
        browser.requested = false;
    }
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowSize(ImVec2(viewport->Size.x * 0.6f, viewport->Size.y * 0.7f), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    std::optional<std::string> chosen;
    if (!ImGui::BeginPopupModal(title, nullptr)) return chosen;

    ImGui::TextWrapped("Folder: %s", browser.directory.c_str());
    if (ImGui::Button("Up")) {
        browser.directory = fs::path(browser.directory).parent_path().string();
        if (browser.directory.empty()) browser.directory = "/";
    }
    ImGui::SameLine();
    std::string filter;
    for (const std::string& extension : browser.extensions) filter += (filter.empty() ? "*" : ", *") + extension;
    ImGui::TextDisabled("showing folders and %s", filter.c_str());

    const Listing listing = listDirectory(browser.directory, browser.extensions);
    const float footer = ImGui::GetFrameHeightWithSpacing() * 2.5f + (browser.error.empty() ? 0 : ImGui::GetTextLineHeightWithSpacing());
    ImGui::BeginChild("listing", ImVec2(0, -footer), true);
    for (const std::string& name : listing.directories) {
        if (ImGui::Selectable((name + "/").c_str(), false, ImGuiSelectableFlags_AllowDoubleClick) &&
            ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            browser.directory = (fs::path(browser.directory) / name).string();
        }
    }
    for (const std::string& name : listing.files) {
        if (ImGui::Selectable(name.c_str(), browser.typedPath == name, ImGuiSelectableFlags_AllowDoubleClick)) {
            browser.typedPath = name;
            ++browser.pathFieldGeneration;
            if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = confirm(browser);
        }
    }
    if (listing.directories.empty() && listing.files.empty()) ImGui::TextDisabled("(nothing to show)");
    ImGui::EndChild();

    ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 12.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::PushID(browser.pathFieldGeneration);
    const bool entered = ImGui::InputText("##path", &browser.typedPath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::PopID();
    ImGui::SameLine();
    const bool pressed = ImGui::Button(purposeSaves(browser.purpose) ? "Save" : "Open");
    // Both Enter presses are taken even when the text field already confirmed: one left over would
    // dismiss, in this same frame, the error dialog that opening the chosen file may raise.
    const bool enterPressed = takeKeyPress(GLFW_KEY_ENTER);
    const bool keypadEnterPressed = takeKeyPress(GLFW_KEY_KP_ENTER);
    if (entered || pressed || enterPressed || keypadEnterPressed) chosen = confirm(browser);
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || takeKeyPress(GLFW_KEY_ESCAPE)) ImGui::CloseCurrentPopup();
    if (!browser.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", browser.error.c_str());
    if (chosen) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return chosen;
}

}  // namespace glint
