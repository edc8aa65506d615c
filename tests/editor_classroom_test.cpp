// Classroom mode in the editor without a window: presentation mode's state logic (scale range,
// hidden panels, persisted in settings.json) and stepping through lessons via the normal open path
// (unsaved work is asked about first; the lesson index follows only a scene that opened).
#include <gtest/gtest.h>

#include <filesystem>

#include "classroom/lesson_document.h"
#include "classroom/lessons_view.h"
#include "classroom/presentation.h"
#include "editor/document.h"
#include "editor/settings.h"
#include "editor_test_support.h"

namespace glint {
namespace {

class EditorClassroom : public test::EditorFixture {
protected:
    const char* suiteFolder() const override { return "editor_classroom"; }
    void SetUp() override {
        test::EditorFixture::SetUp();
        ::setenv("GLINT_LESSONS", test::dataPath("../lessons/lessons.json").c_str(), 1);
    }
    void TearDown() override {
        ::unsetenv("GLINT_LESSONS");
        test::EditorFixture::TearDown();
    }
};

TEST_F(EditorClassroom, PresentationModeScalesHidesAdvancedPanelsAndPersists) {
    EditorState state;
    state.settings.uiScale = 1.25f;
    EXPECT_FLOAT_EQ(effectiveUiScale(state.settings), 1.25f);
    EXPECT_TRUE(advancedPanelsVisible(state.settings));
    togglePresentationMode(state);
    EXPECT_TRUE(state.settings.presentationMode);
    EXPECT_FLOAT_EQ(effectiveUiScale(state.settings), 2.0f);  // the default presentation scale
    EXPECT_FALSE(advancedPanelsVisible(state.settings));
    // A scale outside 1.5–3 (a hand-edited settings file) is never used as such.
    state.settings.presentationScale = 9.0f;
    EXPECT_FLOAT_EQ(effectiveUiScale(state.settings), kPresentationScaleMax);
    state.settings.presentationScale = 2.5f;
    saveSettings(state.settings);
    const Settings reloaded = loadSettings();
    EXPECT_TRUE(reloaded.presentationMode);
    EXPECT_FLOAT_EQ(reloaded.presentationScale, 2.5f);
    EXPECT_FLOAT_EQ(reloaded.uiScale, 1.25f);
    togglePresentationMode(state);
    EXPECT_FALSE(loadSettings().presentationMode);
    EXPECT_FLOAT_EQ(effectiveUiScale(state.settings), 1.25f);
}

TEST_F(EditorClassroom, LessonsOpenInOrderThroughTheUnsavedChangesGuard) {
    EditorState state;
    openLesson(state, 0);
    ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    ASSERT_EQ(state.classroom.lessonList.lessons.size(), 18u);
    EXPECT_EQ(state.classroom.lessonIndex, 0);
    EXPECT_EQ(state.session.path(), "");  // read-only: Ctrl+S asks for a new name
    EXPECT_EQ(lessonDocumentName(state), "Lesson 1 — 01_lambert.json (read-only)");
    EXPECT_EQ(state.session.scene().materials[0].analytic()->model, BrdfModel::Lambert);

    // Unsaved work: the next lesson waits behind the prompt, and the index stays.
    state.session.change("Edit light").lights[0].power = 10.0f;
    openLesson(state, 1);
    EXPECT_TRUE(state.unsavedPromptRequested);
    EXPECT_EQ(state.classroom.lessonIndex, 0);
    // "Don't save" runs the waiting action: lesson 2 (Phong) opens.
    state.unsavedPromptRequested = false;
    runActionAfterPrompt(state);
    EXPECT_EQ(state.classroom.lessonIndex, 1);
    EXPECT_EQ(state.session.scene().materials[0].analytic()->model, BrdfModel::Phong);
    EXPECT_FALSE(state.session.dirty());
}

TEST_F(EditorClassroom, ABrokenLessonSceneLeavesTheLessonAndTheWorkAsTheyWere) {
    const std::string good = write("good.json", R"({"format": "glint-scene", "version": 1, "objects": []})");
    write("broken.json", R"({"format": "glint-scene", "version": 1, "lights": [{"type": "point", "power": -1}]})");
    const std::string list = write("lessons.json", R"({"format": "glint-lessons", "version": 1, "lessons": [
  {"title": "Good", "scene": "good.json"}, {"title": "Broken", "scene": "broken.json"}]})");
    ::setenv("GLINT_LESSONS", list.c_str(), 1);
    EditorState state;
    openLesson(state, 0);
    ASSERT_EQ(state.classroom.lessonIndex, 0);
    const std::uint64_t document = state.session.documentGeneration();
    openLesson(state, 1);
    EXPECT_FALSE(state.errorMessage.empty());
    EXPECT_EQ(state.classroom.lessonIndex, 0);
    EXPECT_EQ(openLessonIndex(state), 0);
    EXPECT_EQ(state.session.documentGeneration(), document);
}

TEST_F(EditorClassroom, CameraMovesInALessonAreNotUnsavedWorkButOtherEditsAre) {
    EditorState state;
    openLesson(state, 0);
    ASSERT_EQ(openLessonIndex(state), 0);
    for (const char* move : {"Move camera", "Zoom", "Edit camera"}) {
        state.session.change(move).camera.position += glm::vec3(0.3f, 0.1f, 0.0f);
        state.session.settle(false);
    }
    EXPECT_TRUE(state.session.dirty());    // the session's undo history has the moves…
    EXPECT_FALSE(hasUnsavedWork(state));  // …but they are looking around, not edits to keep
    openLesson(state, 1);                  // PageDown: no prompt
    EXPECT_FALSE(state.unsavedPromptRequested);
    EXPECT_EQ(openLessonIndex(state), 1);

    state.session.change("Edit light").lights[0].power = 10.0f;
    state.session.settle(false);
    EXPECT_TRUE(hasUnsavedWork(state));
    openLesson(state, 2);
    EXPECT_TRUE(state.unsavedPromptRequested);  // a real edit is asked about
    EXPECT_EQ(openLessonIndex(state), 1);
}

TEST_F(EditorClassroom, LessonFilesAreNeverWrittenAndSaveAsKeepsACopyElsewhere) {
    EditorState state;
    openLesson(state, 0);
    const std::string lessonFile = state.classroom.lessonList.lessons[0].scenePath;
    const auto before = std::filesystem::last_write_time(lessonFile);
    state.session.change("Edit light").lights[0].power = 10.0f;
    saveScene(state);  // Ctrl+S: no path, so the file browser asks for one
    EXPECT_EQ(state.fileBrowser.purpose, FilePurpose::SaveSceneAs);
    EXPECT_FALSE(saveSceneTo(state, lessonFile));  // choosing the lesson itself is refused
    EXPECT_NE(state.errorMessage.find("course material"), std::string::npos) << state.errorMessage;
    EXPECT_FALSE(saveSceneTo(state, state.classroom.lessonList.path));
    EXPECT_EQ(std::filesystem::last_write_time(lessonFile), before);
    EXPECT_EQ(openLessonIndex(state), 0);

    revertLesson(state);  // the lesson as shipped
    EXPECT_FALSE(hasUnsavedWork(state));
    EXPECT_EQ(state.session.scene().lights[0].power, state.classroom.lessonOriginal.lights[0].power);
    EXPECT_EQ(openLessonIndex(state), 0);

    state.errorMessage.clear();
    state.session.change("Edit light").lights[0].power = 12.0f;
    const std::string copy = directory_ + "/my_lesson.json";
    ASSERT_TRUE(saveSceneTo(state, copy)) << state.errorMessage;
    followLessonDocument(state);  // the copy is the user's document now: the lesson and its note go
    EXPECT_EQ(openLessonIndex(state), -1);
    EXPECT_EQ(state.classroom.lessonIndex, -1);
    EXPECT_EQ(std::filesystem::last_write_time(lessonFile), before);
}

TEST_F(EditorClassroom, PresentStartsInPresentationModeOnTheListsFirstLesson) {
    const std::string scene = write("only.json", R"({"format": "glint-scene", "version": 1, "objects": []})");
    const std::string list = write("course.json", R"({"format": "glint-lessons", "version": 1, "lessons": [
  {"title": "Only", "scene": "only.json", "probe": [0.5, 0.5]}]})");
    EditorState state;
    startPresentation(state, list);  // `glint present course.json`
    EXPECT_TRUE(state.settings.presentationMode);
    EXPECT_TRUE(loadSettings().presentationMode);
    EXPECT_EQ(openLessonIndex(state), 0);
    EXPECT_EQ(state.classroom.lessonScenePath, std::filesystem::absolute(scene).lexically_normal().string());
}

TEST_F(EditorClassroom, ANewSceneOrAnotherFileTakesTheLessonNoteAway) {
    EditorState state;
    openLesson(state, 7);
    ASSERT_EQ(openLessonIndex(state), 7);
    guardUnsavedChanges(state, "starting a new scene", newScene);  // Ctrl+N
    followLessonDocument(state);
    EXPECT_EQ(state.classroom.lessonIndex, -1);
    EXPECT_EQ(lessonDocumentName(state), "");

    openLesson(state, 7);
    openSceneFile(state, state.classroom.lessonList.lessons[0].scenePath);  // File ▸ Open, even of a lesson's scene
    followLessonDocument(state);
    EXPECT_EQ(state.classroom.lessonIndex, -1);
}

}  // namespace
}  // namespace glint
