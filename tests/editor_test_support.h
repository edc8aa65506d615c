// A fixture for the editor's windowless tests: each test gets its own output folder and state
// directory (recovery file, settings), and writes its input files there.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

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

}  // namespace glint::test
