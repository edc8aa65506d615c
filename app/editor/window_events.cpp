// The window's callbacks (see window_events.h).
#include "editor/window_events.h"

#include <GLFW/glfw3.h>

#include <cstdio>

#include "editor/key_events.h"

namespace glint {
namespace {

WindowEvents& eventsOf(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

WindowEvents& noteEvent(GLFWwindow* window) {
    WindowEvents& events = eventsOf(window);
    events.seen = true;
    ++events.count;
    return events;
}

}  // namespace

void trackWindowEvents(GLFWwindow* window, WindowEvents& events) {
    glfwSetWindowUserPointer(window, &events);
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { noteEvent(w); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { noteEvent(w); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { noteEvent(w); });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_PRESS || action == GLFW_REPEAT) recordKeyPress(key, mods);
        noteEvent(w);
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { noteEvent(w); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { noteEvent(w).exposed = true; });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { noteEvent(w).exposed = true; });
    glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
        glfwSetWindowShouldClose(w, GLFW_FALSE);  // the window stays open until the editor decides
        noteEvent(w).closeRequested = true;
    });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        WindowEvents& events = noteEvent(w);
        for (int i = 0; i < count; ++i) events.droppedPaths.emplace_back(paths[i]);
    });
}

// The pointer is asked for before the last poll: the query is a round trip to the X server, so
// every event sent before its answer is queued by then, and the poll finds it.
void logIdleUnlessEventWaits(GLFWwindow* window, WindowEvents& events) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    glfwPollEvents();
    if (events.seen) return;
    std::printf("glint idle %llu %.0f %.0f\n", static_cast<unsigned long long>(events.count), x, y);
    std::fflush(stdout);
}

}  // namespace glint
