// Classroom lessons (core/classroom/lessons.h): the shipped list holds the lessons in the
// lecture's order, each with a note and a probe point, and every scene loads; a broken list is refused with file:line:column; stepping
// stays inside the list. Rendering every lesson headless is tests/lessons_cli_test.sh.
#include <gtest/gtest.h>

#include <filesystem>

#include "classroom/lessons.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

using test::dataPath;

TEST(Lessons, ShippedListHasTheLectureOrderAndEverySceneLoads) {
    auto list = loadLessonList(dataPath("../lessons/lessons.json"));
    ASSERT_TRUE(list.ok()) << list.error().format();
    const char* const expectedStarts[] = {"Lambert", "Phong", "Blinn", "Symmetric Blinn", "Cook-Torrance",
                                          "Fresnel", "Refraction", "White-out", "Radiometry", "The rendering equation",
                                          "Spot lights", "Oren-Nayar", "Anisotropy", "Beer-Lambert", "Gamma",
                                          "Flat, Gouraud", "Spectral dispersion", "The standard surface"};
    ASSERT_EQ(list->lessons.size(), std::size(expectedStarts));
    for (size_t index = 0; index < list->lessons.size(); ++index) {
        const Lesson& lesson = list->lessons[index];
        EXPECT_EQ(lesson.title.rfind(expectedStarts[index], 0), 0u) << lesson.title;
        EXPECT_FALSE(lesson.note.empty()) << lesson.title;
        EXPECT_TRUE(lesson.probePoint.has_value()) << lesson.title << ": every lesson starts the probe somewhere";
        auto scene = loadScene(lesson.scenePath);
        EXPECT_TRUE(scene.ok()) << lesson.title << ": " << scene.error().format();
    }
}

TEST(Lessons, DefaultPathFindsTheShippedListOrTheEnvironmentsChoice) {
    EXPECT_TRUE(std::filesystem::exists(defaultLessonListPath())) << defaultLessonListPath();
    ::setenv("GLINT_LESSONS", "/somewhere/else.json", 1);
    EXPECT_EQ(defaultLessonListPath(), "/somewhere/else.json");
    ::unsetenv("GLINT_LESSONS");
}

TEST(Lessons, BrokenListsAreRefusedWithALocation) {
    auto unknownKey = parseLessonList(R"({"format": "glint-lessons", "version": 1,
  "lessons": [{"title": "A", "scene": "a.json", "slide": 3}]})", "list.json");
    ASSERT_FALSE(unknownKey.ok());
    EXPECT_NE(unknownKey.error().format().find("list.json:2:"), std::string::npos) << unknownKey.error().format();
    EXPECT_NE(unknownKey.error().format().find("slide"), std::string::npos);
    auto noScene = parseLessonList(R"({"format": "glint-lessons", "version": 1, "lessons": [{"title": "A"}]})", "list.json");
    ASSERT_FALSE(noScene.ok());
    EXPECT_NE(noScene.error().format().find("scene"), std::string::npos);
    EXPECT_FALSE(parseLessonList(R"({"format": "glint-scene", "version": 1, "lessons": []})", "list.json").ok());
    EXPECT_FALSE(parseLessonList(R"({"format": "glint-lessons", "version": 1, "lessons": []})", "list.json").ok());
    auto probeOutside = parseLessonList(R"({"format": "glint-lessons", "version": 1,
  "lessons": [{"title": "A", "scene": "a.json", "probe": [0.5, 1.5]}]})", "list.json");
    ASSERT_FALSE(probeOutside.ok());
    EXPECT_NE(probeOutside.error().format().find("probe"), std::string::npos) << probeOutside.error().format();
    auto relative = parseLessonList(R"({"format": "glint-lessons", "version": 1, "lessons": [{"title": "A", "scene": "x/a.json"}]})",
                                    "/course/lessons.json");
    ASSERT_TRUE(relative.ok());
    EXPECT_EQ(relative->lessons[0].scenePath, "/course/x/a.json");
}

TEST(Lessons, SteppingStaysInsideTheList) {
    EXPECT_EQ(nextLessonIndex(0, 8), 1);
    EXPECT_EQ(nextLessonIndex(7, 8), 7);
    EXPECT_EQ(previousLessonIndex(0, 8), 0);
    EXPECT_EQ(previousLessonIndex(5, 8), 4);
    EXPECT_EQ(nextLessonIndex(0, 0), 0);
}

}  // namespace
}  // namespace glint
