// The editor: a GLFW window whose viewport shows the scene, with ImGui panels over it.
// Redraws only when something changed; blocks in glfwWaitEvents when idle (0% CPU).
#pragma once

#include <memory>
#include <string>

#include "platform/glfw_platform.h"

namespace glint {

// Runs until the window is closed; returns the process exit code. Starts on the default scene;
// `openPath`, when not empty, is then opened as File ▸ Open and a drop open it (document.h
// openDroppedFile: a scene, a material, .brdf, .mtl, .gltf, .glb, .binary or a mesh), a failure
// shown in the editor's error dialog.
// `presentLessonList`, when not empty, starts in presentation mode on that list's first lesson
// (`glint present LIST.json`).
int runEditor(std::unique_ptr<GlfwPlatform> platform, const std::string& openPath = {},
              const std::string& presentLessonList = {});

}  // namespace glint
