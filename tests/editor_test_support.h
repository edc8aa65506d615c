// A fixture for the editor's windowless tests: each test gets its own output folder and state
// directory (recovery file, settings), and writes its input files there; and a mesh loaded the
// way the editor loads one.
#pragma once

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "editor/mesh_loading.h"
#include "test_support.h"

namespace glint::test {

class EditorFixture : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = outputDirectory(std::string(suiteFolder()) + "/" +
                                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(directory_ + "/state");
        ::setenv("GLINT_STATE_DIR", (directory_ + "/state").c_str(), 1);
    }
    void TearDown() override { ::unsetenv("GLINT_STATE_DIR"); }
    std::string write(const std::string& name, const std::string& text) {
        const std::string path = directory_ + "/" + name;
        std::ofstream(path) << text;
        return path;
    }
    virtual const char* suiteFolder() const = 0;
    std::string directory_;
};

// Runs the frame loop's polling until the load finishes (at most 60 s).
inline void waitForMeshLoad(EditorState& state) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (pollMeshLoad(state) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_FALSE(state.meshLoad) << "the mesh load did not finish";
}

// Loads a mesh file the way the editor does and closes the undo step, as the frame loop would.
inline void loadMeshAndSettle(EditorState& state, const std::string& path) {
    startMeshLoad(state, path);
    waitForMeshLoad(state);
    state.session.settle(false);
}

}  // namespace glint::test
