// Key presses seen this frame, recorded from GLFW's key callback. ImGui 1.86 samples key state
// once per frame, so a press and release that both arrive between two frames (fast typing,
// xdotool) would be missed by ImGui::IsKeyPressed; shortcuts and dialog keys use this instead.
#pragma once

namespace glint {

// Called from the GLFW key callback for GLFW_PRESS and GLFW_REPEAT.
void recordKeyPress(int key, int mods);
// True when `key` was pressed this frame with exactly the modifiers in `mods` (GLFW_MOD_*;
// Caps Lock and Num Lock ignored).
bool keyPressed(int key, int mods = 0);
// Like keyPressed, and removes the press so no later dialog in the same frame acts on it too.
bool takeKeyPress(int key, int mods = 0);
// Forgets this frame's presses (end of frame).
void clearKeyPresses();

}  // namespace glint
