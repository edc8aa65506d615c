// Lessons: the ordered list of saved scenes a teacher steps through in classroom mode
// (lessons/lessons.json: a title, a scene file and a short teaching note per lesson), where that
// list is found, and stepping through it. It loads the list only; scenes load through scene_json.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/diagnostic.h"

namespace glint {

struct Lesson {
    std::string title;      // "Lambert: f_r = ρ/π"
    std::string scenePath;  // absolute or relative to the working directory, resolved from the list's folder
    std::string note;       // one or two sentences the overlay shows
    // Where the surface probe starts: a point of the view as fractions of its width and height
    // (0..1, y down; "probe": [x, y]), or none.
    std::optional<glm::vec2> probePoint;
};

struct LessonList {
    std::string path;  // the list file itself
    std::vector<Lesson> lessons;
};

inline constexpr const char* kLessonListFormat = "glint-lessons";

// Parses a lesson list ("format": "glint-lessons", "version": 1, "lessons": [...]); scene paths
// are resolved against the folder of `file`. Errors name file:line:column and the key.
Result<LessonList> parseLessonList(const std::string& text, const std::string& file);
Result<LessonList> loadLessonList(const std::string& path);

// Where the shipped list lives: $GLINT_LESSONS (a lessons.json file) if set, else
// <executable folder>/../share/glint/lessons/lessons.json when it exists, else the source tree's
// lessons/lessons.json (the path this build was configured with).
std::string defaultLessonListPath();

// The lesson after / before `index` in a list of `count`, staying at the ends (no wrap-around:
// a teacher pressing Right on the last slide should not jump back to the first).
int nextLessonIndex(int index, int count);
int previousLessonIndex(int index, int count);

}  // namespace glint
