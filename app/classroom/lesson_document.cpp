// Lessons as read-only documents (see lesson_document.h).
#include "classroom/lesson_document.h"

#include <filesystem>
#include <system_error>

#include "classroom/lessons_view.h"
#include "editor/probe_panel.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

std::string normalisedPath(const std::string& path) { return std::filesystem::absolute(path).lexically_normal().string(); }

// The scene's JSON with the lesson's own camera and overlays: what changes with an edit other
// than looking around (orbit, zoom, the wireframe and normals overlays: W, N).
std::string sceneWithoutViewChanges(const Scene& scene, const Scene& lesson) {
    Scene copy = scene;
    copy.camera = lesson.camera;
    copy.display.overlays = lesson.display.overlays;
    return sceneToJson(copy).dump();
}

}  // namespace

bool openLessonDocument(EditorState& state, int index) {
    ClassroomState& classroom = state.classroom;
    const std::string path = classroom.lessonList.lessons.at(index).scenePath;
    auto loaded = loadScene(path, EnvironmentMapLoading::Later);
    if (!loaded) {
        state.errorMessage = "Could not open the lesson; your work is unchanged.\n\n" + loaded.error().format();
        return false;
    }
    classroom.lessonOriginal = *loaded;
    classroom.lessonOriginalJson = sceneToJson(*loaded).dump();
    classroom.lessonScenePath = normalisedPath(path);
    state.session.replace(std::move(*loaded), "");  // no path: Ctrl+S goes to Save as
    state.selectedObject = 0;
    state.selectedLight = 0;
    classroom.lessonIndex = index;
    classroom.lessonDocument = state.session.documentGeneration();
    classroom.showLessonNote = true;
    if (const auto& point = classroom.lessonList.lessons[index].probePoint) showProbeAt(*point);
    state.statusMessage = "Lesson " + std::to_string(index + 1) + " (read-only: Save as… keeps your version)";
    return true;
}

int openLessonIndex(const EditorState& state) {
    const ClassroomState& classroom = state.classroom;
    return classroom.lessonDocument == state.session.documentGeneration() ? classroom.lessonIndex : -1;
}

void followLessonDocument(EditorState& state) {
    if (state.classroom.lessonIndex >= 0 && openLessonIndex(state) < 0) state.classroom.lessonIndex = -1;
}

bool hasUnsavedWork(const EditorState& state) {
    if (!state.session.dirty()) return false;
    if (openLessonIndex(state) < 0) return true;
    const ClassroomState& classroom = state.classroom;
    if (classroom.lessonEditsRevision != state.session.revision()) {  // one comparison per change
        classroom.lessonEditsRevision = state.session.revision();
        classroom.lessonEdited =
            sceneWithoutViewChanges(state.session.scene(), classroom.lessonOriginal) != classroom.lessonOriginalJson;
    }
    return classroom.lessonEdited;
}

void revertLesson(EditorState& state) {
    const int index = openLessonIndex(state);
    if (index < 0) return;
    state.session.replace(state.classroom.lessonOriginal, "");
    state.classroom.lessonDocument = state.session.documentGeneration();
    state.statusMessage = "Lesson " + std::to_string(index + 1) + " as shipped";
}

bool isLessonFile(EditorState& state, const std::string& path) {
    ensureLessonList(state);
    const std::string target = normalisedPath(path);
    const LessonList& list = state.classroom.lessonList;
    std::error_code error;
    const auto same = [&](const std::string& candidate) {
        return !candidate.empty() && (normalisedPath(candidate) == target || std::filesystem::equivalent(candidate, target, error));
    };
    if (same(list.path)) return true;
    for (const Lesson& lesson : list.lessons)
        if (same(lesson.scenePath)) return true;
    return false;
}

std::string lessonDocumentName(const EditorState& state) {
    const int index = openLessonIndex(state);
    if (index < 0) return {};
    return "Lesson " + std::to_string(index + 1) + " — " +
           std::filesystem::path(state.classroom.lessonScenePath).filename().string() + " (read-only)";
}

}  // namespace glint
