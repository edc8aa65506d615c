// WindowEvents: what the window's GLFW callbacks tell the editor's loop. Any input asks for a few
// more frames; a close request and dropped files wait for the loop to act on them; an exposed or
// resized window must be drawn whole again. Held by the loop, reached by the callbacks through
// the window's user pointer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace glint {

struct WindowEvents {
    bool seen = false;          // an event since the loop last cleared this
    std::uint64_t count = 0;    // since start, for GLINT_LOG_IDLE
    bool exposed = true;        // the window's pixels must all be drawn again (mapped, exposed, resized)
    bool closeRequested = false;  // the close button: the editor decides (unsaved-changes prompt)
    std::vector<std::string> droppedPaths;
};

// Installs the callbacks that fill `events`, before ImGui's backend (which chains to them).
void trackWindowEvents(GLFWwindow* window, WindowEvents& events);

// "glint idle N X Y": the window events handled since start and where the pointer is, printed when
// the editor sleeps with everything drawn; the GUI tests' sign that what they sent is handled and
// on screen (tests/gui_test_support.py: wait_idle). Polls once: nothing is printed when an event
// was waiting.
void logIdleUnlessEventWaits(GLFWwindow* window, WindowEvents& events);

}  // namespace glint
