// Lessons in the editor: the lesson window (View ▸ Lessons, L), stepping with Left/Right or
// PageUp/PageDown through the normal open path (unsaved work is asked about first), and the small
// overlay with the lesson's title and note. The list format lives in core/classroom/lessons.h.
#pragma once

#include "editor/editor_state.h"

namespace glint {

// Loads the shipped list on first use (errors are kept for the window, never fatal).
void ensureLessonList(EditorState& state);
// Opens lesson `index` (clamped to the list) through the unsaved-changes guard.
void openLesson(EditorState& state, int index);
// Left/Right (while a lesson is open), PageUp/PageDown and L; called once per frame after the panels.
void handleLessonKeys(EditorState& state);
// The lesson window and the title-and-note overlay over the viewport's top-left corner.
void drawLessonWindows(EditorState& state, float viewportLeft, float viewportTop);

}  // namespace glint
