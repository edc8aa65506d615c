// The editor: a GLFW window whose viewport shows the scene, with ImGui panels over it.
// Redraws only when something changed; blocks in glfwWaitEvents when idle (0% CPU).
#pragma once

#include <memory>
#include <string>

#include "platform/glfw_platform.h"
#include "scene/scene.h"

namespace glint {

// Runs until the window is closed; returns the process exit code.
// `meshPath`, when not empty, starts loading that mesh as a new object (as File ▸ Open mesh).
int runEditor(std::unique_ptr<GlfwPlatform> platform, Scene scene, const std::string& scenePath,
              const std::string& meshPath = {});

}  // namespace glint
