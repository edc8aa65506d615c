// The Environment section of the display panel: none, a built-in (studio, sky, uniform white) or
// an HDR file picked with the file browser; rotation about +y, intensity and whether the map
// shows as the background. Each change is one undo step through the edit API; a file that cannot
// be used is refused with a message and the scene stays as it was.
#include <imgui.h>

#include "environment/environment_source.h"
#include "editor/panels/file_browser.h"
#include "editor/panels/panels.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"

namespace glint {

void openEnvironmentFile(EditorState& state, const std::string& path) {
    Environment environment = state.session.scene().environment;
    environment.kind = EnvironmentKind::File;
    environment.file = path;
    if (Status loaded = loadEnvironment(environment); !loaded) {
        state.errorMessage = "Could not use the environment image; your scene is unchanged.\n\n" + loaded.error().format();
        return;
    }
    state.session.change("Environment file").environment = std::move(environment);
    state.session.settle(false);
    state.statusMessage = "Environment from " + path;
}

void drawEnvironmentSection(EditorState& state) {
    static std::string refusal;
    const Environment& current = state.session.scene().environment;
    ImGui::Separator();
    ImGui::TextUnformatted("Environment");
    int kind = static_cast<int>(current.kind);
    if (comboBox("Environment", &kind, "none\0HDR file…\0studio\0sky\0uniform white\0")) {
        if (kind == static_cast<int>(EnvironmentKind::File)) {
            requestFileBrowser(state.fileBrowser, FilePurpose::OpenEnvironment, current.file);
        } else if (kind != static_cast<int>(current.kind)) {
            Environment environment = current;
            environment.kind = static_cast<EnvironmentKind>(kind);
            if (Status loaded = loadEnvironment(environment); !loaded) state.errorMessage = loaded.error().format();
            else state.session.change("Environment").environment = std::move(environment);
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Light from every direction: an equirectangular .hdr/.exr, or a built-in that needs no file");
    if (current.kind == EnvironmentKind::None) return;
    if (current.kind == EnvironmentKind::File) {
        ImGui::TextWrapped("%s", current.file.c_str());
        if (ImGui::Button("Choose file…"))
            requestFileBrowser(state.fileBrowser, FilePurpose::OpenEnvironment, current.file);
    }
    Environment environment = current;
    bool changed = false;
    changed |= editNumbers("Rotation", &environment.rotationDegrees, 1,
                           [](float* typed) { return ImGui::SliderFloat("Rotation", typed, -180.0f, 180.0f, "%.1f°"); });
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Turns the map about +y (degrees)");
    changed |= boundedDrag("Intensity", environment.intensity, 0.0f, 1e6f, "%.3f", refusal,
                           "Scale on the map's radiance, W/(sr·m²) per map unit (white: L itself)");
    changed |= ImGui::Checkbox("Show as background", &environment.showAsBackground);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Off: the background above stays; the map still lights the scene and shows in reflections");
    if (!refusal.empty()) ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s", refusal.c_str());
    if (changed) state.session.change("Edit environment").environment = environment;
}

}  // namespace glint
