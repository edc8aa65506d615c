// The editor's lesson window, lesson stepping and the title-and-note overlay (lessons_view.h).
// Lessons open read-only (lesson_document.h) behind guardUnsavedChanges, like File ▸ Open.
#include "classroom/lessons_view.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <string>
#include <string_view>

#include "classroom/lesson_document.h"
#include "editor/document.h"
#include "editor/key_events.h"
#include "editor/window_placement.h"

namespace glint {

void ensureLessonList(EditorState& state) {
    ClassroomState& classroom = state.classroom;
    if (classroom.lessonListLoaded) return;
    classroom.lessonListLoaded = true;
    auto list = loadLessonList(classroom.lessonListPath.empty() ? defaultLessonListPath() : classroom.lessonListPath);
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
    // A broken lesson file leaves the work and the lesson index as they were.
    guardUnsavedChanges(state, "opening lesson " + std::to_string(index + 1),
                        [index](EditorState& s) { openLessonDocument(s, index); });
}

void handleLessonKeys(EditorState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
    ClassroomState& classroom = state.classroom;
    const int count = static_cast<int>(classroom.lessonList.lessons.size());
    const bool inLesson = openLessonIndex(state) >= 0;
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

namespace {

void drawLessonList(EditorState& state) {
    ClassroomState& classroom = state.classroom;
    if (!classroom.lessonListError.empty()) {
        ImGui::TextWrapped("The lesson list could not be read:\n%s", classroom.lessonListError.c_str());
        return;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", classroom.lessonList.path.c_str());
    const auto& lessons = classroom.lessonList.lessons;
    const int open = openLessonIndex(state);
    for (int index = 0; index < static_cast<int>(lessons.size()); ++index) {
        // A selectable row as tall as its title wrapped to the window's width.
        const std::string label = std::to_string(index + 1) + ". " + lessons[index].title;
        const ImVec2 start = ImGui::GetCursorPos();
        const float height = ImGui::CalcTextSize(label.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x).y;
        ImGui::PushID(index);
        const bool clicked = ImGui::Selectable("##lesson", index == open, ImGuiSelectableFlags_None, ImVec2(0.0f, height));
        const bool hovered = ImGui::IsItemHovered();
        ImGui::PopID();
        const ImVec2 after = ImGui::GetCursorPos();
        ImGui::SetCursorPos(start);
        ImGui::TextUnformatted(label.c_str());  // wraps: the text wrap position is the window's edge
        ImGui::SetCursorPos(after);
        if (clicked) openLesson(state, index);
        if (hovered && !lessons[index].note.empty()) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
            ImGui::TextUnformatted(lessons[index].note.c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
    }
    ImGui::Separator();
    if (open >= 0) {
        if (ImGui::Button("Revert lesson")) revertLesson(state);
        ImGui::SameLine();
        if (ImGui::Button("Save as…")) requestFileBrowser(state.fileBrowser, FilePurpose::SaveSceneAs, "my_lesson.json");
    }
    ImGui::TextWrapped("PageDown / Right: next lesson · PageUp / Left: previous. Lessons are read-only course material: "
                       "your edits stay in this session (Revert lesson restores the lesson), Save as… keeps a copy elsewhere. "
                       "Moving the camera is never an edit.");
    ImGui::PopTextWrapPos();
    ImGui::Checkbox("Show the lesson note over the viewport", &classroom.showLessonNote);
}

}  // namespace

void drawLessonWindows(EditorState& state, float viewportLeft, float viewportTop, float viewportWidth, float viewportHeight) {
    ClassroomState& classroom = state.classroom;
    const float fontSize = ImGui::GetFontSize();
    if (classroom.showLessonWindow) {
        ensureLessonList(state);
        if (beginPlacedWindow("Lessons", &classroom.showLessonWindow, {ImVec2(26.0f, 22.0f), ImVec2(16.0f, 10.0f)})) drawLessonList(state);
        ImGui::End();
    }
    const auto& lessons = classroom.lessonList.lessons;
    const int index = openLessonIndex(state);
    if (index < 0 || !classroom.showLessonNote) return;
    const Lesson& lesson = lessons[index];
    // In a corner of the viewport, at most 45 % of its width and height (longer notes scroll): top
    // left, else the corner that covers least of the probe's arrows and angles, then of windows.
    // It stays in its corner until another is clearly better.
    static float noteHeight = 0.0f;  // last frame's, to choose the corner
    static int cornerShown = 0;
    const float margin = fontSize * 0.4f;
    const float width = std::min(fontSize * 26.0f, viewportWidth * 0.45f);
    const float leftX = viewportLeft + margin, rightX = viewportLeft + viewportWidth - margin - width;
    const float topY = viewportTop + margin, bottomY = viewportTop + viewportHeight - margin - noteHeight;
    const ScreenRect corners[] = {{leftX, topY, width, noteHeight}, {rightX, topY, width, noteHeight},
                                  {rightX, bottomY, width, noteHeight}, {leftX, bottomY, width, noteHeight}};
    constexpr std::string_view kNote = "lesson note";
    constexpr std::string_view kProbeOverlay[] = {"probe arrows", "probe angles"};
    float taken[4];
    for (int i = 0; i < 4; ++i) taken[i] = screenAreaTaken(corners[i], kNote, kProbeOverlay);
    int best = 0;
    for (int i = 1; i < 4; ++i)
        if (taken[i] < taken[best] - 1.0f) best = i;
    if (taken[best] < taken[cornerShown] * 0.5f - 1.0f) cornerShown = best;
    ImGui::SetNextWindowPos(ImVec2(corners[cornerShown].x, corners[cornerShown].y));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, viewportHeight * 0.45f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_AlwaysAutoResize;
    if (ImGui::Begin("##lesson note", nullptr, flags)) {
        ImGui::PushTextWrapPos(0.0f);  // titles and notes wrap at the window's edge
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.0f, 1.0f), "Lesson %d/%d: %s", index + 1, static_cast<int>(lessons.size()),
                           lesson.title.c_str());
        ImGui::TextUnformatted(lesson.note.c_str());
        ImGui::TextDisabled("PageDown: next · PageUp: previous");
        ImGui::PopTextWrapPos();
        noteHeight = ImGui::GetWindowHeight();
        reserveScreenRect("lesson note", {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(),
                                          ImGui::GetWindowHeight()});
    }
    ImGui::End();
}

}  // namespace glint
