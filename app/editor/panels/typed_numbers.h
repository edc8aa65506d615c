// Numbers typed into a widget (a Ctrl+click or double-click on a slider or a drag field, a colour's
// channel) reach the scene when the typing ends, not at each key: Enter or a click elsewhere
// commits them, Escape drops them. Until then they are held here, so "-" on the way to "-0.5" is
// never a value of its own (nor an undo step, nor a reduced preview frame). Dragging still applies
// at once.
#pragma once

#include <functional>

namespace glint {

// Draws `widget` (an ImGui widget editing `values`, returning ImGui's "changed") for `count` ≤ 4
// numbers. `label` is the widget's label, which identifies it (within the ID stack) while typed
// numbers are held. Returns true when `values` hold numbers to apply now: dragged ones at once,
// typed ones in the frame the typing ends (and only when they differ from what was there).
bool editNumbers(const char* label, float* values, int count, const std::function<bool(float*)>& widget);

}  // namespace glint
