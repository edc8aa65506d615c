// The Environment section of the display panel: none, a built-in (studio, sky, uniform white) or
// an HDR file picked with the file browser; rotation about +y, intensity and whether the map
// shows as the background. Each change is one undo step through the edit API. A chosen map is
// made on a worker thread (editor/environment_loading.h): a progress bar with Cancel shows here
// meanwhile, and a file that cannot be used is refused with a message, the scene as it was.
#include <imgui.h>

#include "editor/environment_loading.h"
#include "editor/panels/file_browser.h"
#include "editor/panels/panels.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"

namespace glint {

namespace {

// The map being made: its name, a progress bar and Cancel.
void drawEnvironmentProgress(EditorState& state) {
    EnvironmentLoadJob& job = *state.environmentLoad;
    ImGui::ProgressBar(job.progress(), ImVec2(-1.0f, 0.0f), job.progressText().c_str());
    if (job.cancelRequested()) ImGui::TextDisabled("Cancelling…");
    else if (ImGui::Button("Cancel##environment")) job.cancel();
}

}  // namespace

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
            startEnvironmentLoad(state, static_cast<EnvironmentKind>(kind));
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Light from every direction: an equirectangular .hdr/.exr, or a built-in that needs no file");
    if (state.environmentLoad) drawEnvironmentProgress(state);
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
