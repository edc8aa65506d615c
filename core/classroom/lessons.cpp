// Lesson list loading (lessons.h): located errors through ObjectReader, scene paths resolved
// against the list's folder, and where the shipped list is found. It does not load the scenes.
#include "classroom/lessons.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "scene/json_document.h"
#include "scene/json_object_reader.h"
#include "util/file_io.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr int kLessonListVersion = 1;

LessonList readLessonList(const JsonDocument& document) {
    ObjectReader root = readRoot(document, "lesson list");
    const std::string format = root.requiredString("format");
    if (format != kLessonListFormat)
        root.fail("format", "expected \"" + std::string(kLessonListFormat) + "\", found \"" + format + "\"");
    const int version = root.integer("version", -1, 1, 1'000'000);
    if (version < 0) root.failHere("the lesson list needs a \"version\" (this Glint reads version 1)");
    if (version > kLessonListVersion)
        root.fail("version", "version " + std::to_string(version) + " is newer than this Glint reads (1)");
    if (!root.has("lessons")) root.failHere("the lesson list needs a \"lessons\" array");
    LessonList list;
    list.path = document.file();
    for (ObjectReader& entry : root.objectArray("lessons")) {
        Lesson lesson;
        lesson.title = entry.requiredString("title");
        if (lesson.title.empty()) entry.fail("title", "a lesson needs a non-empty title");
        if (entry.requiredString("scene").empty()) entry.fail("scene", "a lesson needs a scene file");
        lesson.scenePath = entry.referencedFile("scene").string();
        lesson.note = entry.string("note", "");
        if (entry.has("probe")) lesson.probePoint = entry.vec2("probe", glm::vec2(0.5f), Bounds::between(0.0, 1.0));
        entry.rejectUnknownKeys();
        list.lessons.push_back(std::move(lesson));
    }
    if (list.lessons.empty()) root.fail("lessons", "the lesson list is empty");
    root.rejectUnknownKeys();
    return list;
}

}  // namespace

Result<LessonList> parseLessonList(const std::string& text, const std::string& file) {
    auto document = JsonDocument::parse(text, file);
    if (!document) return document.error();
    try {
        return readLessonList(*document);
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    }
}

Result<LessonList> loadLessonList(const std::string& path) { return parseTextFile(path, parseLessonList); }

std::string defaultLessonListPath() {
    if (const char* chosen = std::getenv("GLINT_LESSONS"); chosen && *chosen) return chosen;
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path installed = executable.parent_path() / ".." / "share" / "glint" / "lessons" / "lessons.json";
        if (fs::exists(installed, error)) return installed.lexically_normal().string();
    }
    return std::string(GLINT_SOURCE_LESSONS_DIR) + "/lessons.json";
}

int nextLessonIndex(int index, int count) { return std::clamp(index + 1, 0, std::max(count - 1, 0)); }
int previousLessonIndex(int index, int count) { return std::clamp(index - 1, 0, std::max(count - 1, 0)); }

}  // namespace glint
