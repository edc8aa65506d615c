// The editor's lesson window, lesson stepping and the title-and-note overlay (lessons_view.h).
// Scenes open through openSceneFile behind guardUnsavedChanges, like File ▸ Open.
#include "classroom/lessons_view.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <filesystem>

#include "editor/document.h"
#include "editor/key_events.h"

namespace glint {

void ensureLessonList(EditorState& state) {
    ClassroomState& classroom = state.classroom;
    if (classroom.lessonListLoaded) return;
    classroom.lessonListLoaded = true;
    auto list = loadLessonList(defaultLessonListPath());
    if (list) classroom.lessonList = std::move(*list);
    else classroom.lessonListError = list.error().format();
}

void openLesson(EditorState& state, int index) {
    ensureLessonList(state);
    const auto& lessons = state.classroom.lessonList.lessons;
    if (lessons.empty()) {
        state.statusMessage = "No lessons: " + state.classroom.lessonListError;
        return;
    }
    if (index < 0 || index >= static_cast<int>(lessons.size())) return;
    const std::string path = lessons[index].scenePath;
    guardUnsavedChanges(state, "opening lesson " + std::to_string(index + 1), [path, index](EditorState& s) {
        openSceneFile(s, path);
        // The index follows the scene only when it opened (a broken lesson file leaves both as they were).
        if (s.session.path() == std::filesystem::absolute(path).lexically_normal().string()) {
            s.classroom.lessonIndex = index;
            s.classroom.showLessonNote = true;
        }
    });
}

void handleLessonKeys(EditorState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
    ClassroomState& classroom = state.classroom;
    const int count = static_cast<int>(classroom.lessonList.lessons.size());
    const bool inLesson = classroom.lessonIndex >= 0;
    // Left/Right belong to ImGui while a widget has the keyboard (slider steps); PageUp/PageDown always step.
    const bool arrowsFree = inLesson && !io.WantCaptureKeyboard;
    if (keyPressed(GLFW_KEY_PAGE_DOWN) || (arrowsFree && keyPressed(GLFW_KEY_RIGHT))) {
        ensureLessonList(state);
        const int total = static_cast<int>(classroom.lessonList.lessons.size());
        openLesson(state, inLesson ? nextLessonIndex(classroom.lessonIndex, total) : 0);
    }
    if (keyPressed(GLFW_KEY_PAGE_UP) || (arrowsFree && keyPressed(GLFW_KEY_LEFT)))
        if (inLesson) openLesson(state, previousLessonIndex(classroom.lessonIndex, count));
    if (!io.WantCaptureKeyboard && keyPressed(GLFW_KEY_L)) {
        classroom.showLessonWindow = !classroom.showLessonWindow;
        if (classroom.showLessonWindow) ensureLessonList(state);
    }
}

void drawLessonWindows(EditorState& state, float viewportLeft, float viewportTop) {
    ClassroomState& classroom = state.classroom;
    const float fontSize = ImGui::GetFontSize();
    if (classroom.showLessonWindow) {
        ensureLessonList(state);
        ImGui::SetNextWindowSize(ImVec2(fontSize * 26.0f, 0.0f), ImGuiCond_Appearing);
        if (ImGui::Begin("Lessons", &classroom.showLessonWindow)) {
            if (!classroom.lessonListError.empty()) {
                ImGui::TextWrapped("The lesson list could not be read:\n%s", classroom.lessonListError.c_str());
            } else {
                ImGui::TextDisabled("%s", classroom.lessonList.path.c_str());
                const auto& lessons = classroom.lessonList.lessons;
                for (int index = 0; index < static_cast<int>(lessons.size()); ++index) {
                    const std::string label = std::to_string(index + 1) + ". " + lessons[index].title;
                    if (ImGui::Selectable(label.c_str(), index == classroom.lessonIndex)) openLesson(state, index);
                    if (ImGui::IsItemHovered() && !lessons[index].note.empty()) ImGui::SetTooltip("%s", lessons[index].note.c_str());
                }
                ImGui::Separator();
                ImGui::TextWrapped("Right / PageDown: next lesson · Left / PageUp: previous. Each lesson is a scene file: "
                                   "edit it and save (Ctrl+S) to change the lesson.");
                ImGui::Checkbox("Show the lesson note over the viewport", &classroom.showLessonNote);
            }
        }
        ImGui::End();
    }
    const auto& lessons = classroom.lessonList.lessons;
    if (classroom.lessonIndex < 0 || classroom.lessonIndex >= static_cast<int>(lessons.size()) || !classroom.showLessonNote) return;
    const Lesson& lesson = lessons[classroom.lessonIndex];
    const float margin = fontSize * 0.6f;
    ImGui::SetNextWindowPos(ImVec2(viewportLeft + margin, viewportTop + margin));
    ImGui::SetNextWindowSize(ImVec2(fontSize * 24.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_AlwaysAutoResize;
    if (ImGui::Begin("##lesson note", nullptr, flags)) {
        ImGui::Text("Lesson %d/%d: %s", classroom.lessonIndex + 1, static_cast<int>(lessons.size()), lesson.title.c_str());
        ImGui::PushTextWrapPos(fontSize * 23.0f);
        ImGui::TextUnformatted(lesson.note.c_str());
        ImGui::PopTextWrapPos();
        ImGui::TextDisabled("← / → previous / next lesson");
    }
    ImGui::End();
}

}  // namespace glint
