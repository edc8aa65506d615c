// `glint lessons [LIST.json] [--check] [--render DIR] [--width N]`: lists the classroom lessons
// (core/classroom/lessons.h), checks that every lesson's scene loads, or renders one PNG per lesson.
// Stepping through lessons in the editor lives in app/classroom/lessons_view.cpp.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Returns the process exit code: 0 listed / all loaded / all rendered, 1 some lesson failed to
// load or render, 2 bad arguments or an unreadable lesson list.
int runLessonsCommand(const std::vector<std::string>& arguments);

}  // namespace glint
