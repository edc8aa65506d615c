// Helpers shared by Glint's tests: where the test data lives, a per-test output folder, and a
// shared OSMesa renderer (one GL context for the whole test binary).
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene_json.h"

namespace glint::test {

inline std::string dataPath(const std::string& relative) { return std::string(GLINT_TEST_DATA_DIR) + "/" + relative; }

// A fresh folder under the build tree for files a test writes.
inline std::string outputDirectory(const std::string& name) {
    const std::filesystem::path directory = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / name;
    std::filesystem::create_directories(directory);
    return directory.string();
}

inline Scene loadTestScene(const std::string& relative) {
    auto scene = loadScene(dataPath(relative));
    if (!scene) ADD_FAILURE() << scene.error().format();
    return scene ? *scene : Scene{};
}

}  // namespace glint::test
