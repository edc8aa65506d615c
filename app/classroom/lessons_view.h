// Lessons in the editor: the lesson window (View ▸ Lessons, L), stepping with Left/Right or
// PageUp/PageDown behind the unsaved-changes guard (camera moves in a lesson are not unsaved
// work), and the overlay with the lesson's title and note. Lessons open read-only
// (classroom/lesson_document.h); the list format lives in core/classroom/lessons.h.
#pragma once

#include "editor/editor_state.h"

namespace glint {

// Loads the shipped list on first use (errors are kept for the window, never fatal).
void ensureLessonList(EditorState& state);
// Opens lesson `index` (ignored outside the list) read-only, through the unsaved-changes guard.
void openLesson(EditorState& state, int index);
// Left/Right (while a lesson is open), PageUp/PageDown and L; called once per frame after the panels.
void handleLessonKeys(EditorState& state);
// The lesson window and the title-and-note overlay in a top corner of the viewport (a reserved
// rectangle: no window opens over it).
void drawLessonWindows(EditorState& state, float viewportLeft, float viewportTop, float viewportWidth, float viewportHeight);

}  // namespace glint
