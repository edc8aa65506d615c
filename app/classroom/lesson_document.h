// A lesson open in the editor is course material, read-only: its scene is loaded into the edit
// session with no path (Ctrl+S asks for a new name), edits live in the session until the next
// lesson or file, "Revert lesson" reloads it, and no save may write over a lesson file. Camera
// moves in a lesson are looking around, not edits: they never count as unsaved work. The lesson
// stays open until the session holds another document (Ctrl+N, File ▸ Open, Save as). The
// wireframe and normals overlays (W, N) are viewing aids like the camera and do not count either.
#pragma once

#include <string>

#include "editor/editor_state.h"

namespace glint {

// Loads lesson `index`'s scene read-only; false (and errorMessage says why) when it cannot be read.
bool openLessonDocument(EditorState& state, int index);
// The lesson whose scene the session holds, or -1 (another document replaced it).
int openLessonIndex(const EditorState& state);
// Forgets the lesson once the session holds another document; called once per frame.
void followLessonDocument(EditorState& state);
// Whether the work would be lost by replacing the document: the session's own dirty flag, except
// that in a lesson only edits other than the camera and the overlays count.
bool hasUnsavedWork(const EditorState& state);
// Lesson ▸ Revert: the lesson's file again, edits dropped (camera included).
void revertLesson(EditorState& state);
// True when `path` is the lesson list or one of its scenes: course material no save may overwrite.
bool isLessonFile(EditorState& state, const std::string& path);
// "Lesson 2 — 02_phong.json (read-only)" for the window title; empty outside a lesson.
std::string lessonDocumentName(const EditorState& state);

}  // namespace glint
