// `glint lessons [LIST.json] [--check] [--render DIR] [--width N]`: lists the classroom lessons
// (core/classroom/lessons.h), checks that every lesson's scene loads, or renders one PNG per lesson.
// Stepping through lessons in the editor lives in app/classroom/lessons_view.cpp.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code: 0 listed / all loaded / all rendered, 1 some lesson failed to
// load or render, 2 bad arguments or an unreadable lesson list.
void addLessonsCommand(CLI::App& glint);

}  // namespace glint
