// Classroom mode's hooks into the editor: one call per frame (lesson windows and keys, the
// presentation-mode key, the colour windows) and the View menu's classroom items. What each
// feature does lives in its own file beside this one.
#pragma once

#include "editor/editor_state.h"

namespace glint {

// Once per frame, after the panels; the viewport's rectangle places the lesson note.
void drawClassroom(EditorState& state, float viewportLeft, float viewportTop, float viewportWidth, float viewportHeight);
// Inside the View menu: Lessons, Presentation mode and its scale, the colour windows.
void drawClassroomViewMenuItems(EditorState& state);

}  // namespace glint
