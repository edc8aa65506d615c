// Classroom hooks (classroom_editor.h): dispatches to lessons_view, presentation and the colour
// windows; holds no state of its own.
#include "classroom/classroom_editor.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "classroom/cmf_plot.h"
#include "classroom/lesson_document.h"
#include "classroom/lessons_view.h"
#include "classroom/presentation.h"
#include "classroom/spectral_view.h"
#include "editor/key_events.h"

namespace glint {

void drawClassroom(EditorState& state, float viewportLeft, float viewportTop, float viewportWidth, float viewportHeight) {
    followLessonDocument(state);  // Ctrl+N, another file or Save as: the lesson and its note go
    drawLessonWindows(state, viewportLeft, viewportTop, viewportWidth, viewportHeight);
    handleLessonKeys(state);
    if (!ImGui::GetIO().WantTextInput && keyPressed(GLFW_KEY_F11)) togglePresentationMode(state);
    drawCmfWindow(state.classroom.showCmfWindow);
    drawSpectralWindow(state);
}

void drawClassroomViewMenuItems(EditorState& state) {
    ImGui::Separator();
    if (ImGui::MenuItem("Lessons…", "L", state.classroom.showLessonWindow)) {
        state.classroom.showLessonWindow = !state.classroom.showLessonWindow;
        if (state.classroom.showLessonWindow) ensureLessonList(state);
    }
    if (ImGui::MenuItem("Presentation mode", "F11", state.settings.presentationMode)) togglePresentationMode(state);
    float scale = state.settings.presentationScale;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    if (ImGui::SliderFloat("Presentation scale", &scale, kPresentationScaleMin, kPresentationScaleMax, "%.2f×") &&
        scale >= kPresentationScaleMin && scale <= kPresentationScaleMax)
        state.settings.presentationScale = scale;
    if (ImGui::IsItemDeactivatedAfterEdit()) saveSettings(state.settings);
    ImGui::MenuItem("Colour matching functions", nullptr, &state.classroom.showCmfWindow);
    ImGui::MenuItem("Spectral render", nullptr, &state.classroom.showSpectralWindow);
}

}  // namespace glint
