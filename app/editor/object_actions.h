// Object actions of the editor: add an object of a kind, duplicate, remove, toggle the overlays.
// Each is one undo step through the EditSession (the caller's frame loop settles it); new objects
// get their own default material and become the selection. No drawing here (panels/object_panel.cpp).
#pragma once

#include <optional>
#include <string>

#include "editor/editor_state.h"

namespace glint {

enum class ObjectKind { Sphere, Plane, Cube, Torus };

const char* objectKindLabel(ObjectKind kind);
// A label for the shape an object holds ("Sphere", "Plane", ...).
const char* shapeLabel(const Shape& shape);

// Adds an object of `kind` in front of the camera (at its target, offset to the right so it
// does not sit inside what is already there), with a new Lambert material.
void addObject(EditorState& state, ObjectKind kind);
// The same for a given shape (a loaded mesh), with `material` where given (an .obj's own) instead
// of a Lambert one; `baseName` gets a number when taken. The shape's centre is replaced by the new
// object's place; its interpolation is the shape's default.
void addObjectWithShape(EditorState& state, const std::string& baseName, Shape shape,
                        std::optional<Material> material = std::nullopt);
// Copies the object and its material beside the original; false when the index is out of range.
bool duplicateObject(EditorState& state, int objectIndex);
// Removes the object (its material stays in the scene's list); false when out of range.
bool removeObject(EditorState& state, int objectIndex);
// Keeps the selected object within the scene (0 when it has none): an undo, redo or open may have
// removed it. The frame loop calls it before anything reads the selection, and after the shortcuts.
void keepSelectionInScene(EditorState& state);

void toggleWireframe(EditorState& state);
void toggleNormals(EditorState& state);

}  // namespace glint
