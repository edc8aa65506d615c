// A check shared by the scene-file tests: parsing bad text must fail with a diagnostic naming
// the file, the line, a column, the key (quoted) and the message. No test cases here.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "scene/scene_json.h"

namespace glint::test {

// The diagnostic for bad text: it must name bad.json, `line` and `key`.
inline void expectLocatedError(const std::string& text, int line, const std::string& key, const std::string& message) {
    auto scene = parseScene(text, "bad.json");
    ASSERT_FALSE(scene.ok()) << text;
    const Diagnostic& error = scene.error();
    EXPECT_EQ(error.where.file, "bad.json");
    EXPECT_EQ(error.where.line, line) << error.format();
    EXPECT_GT(error.where.column, 0);
    EXPECT_NE(error.message.find("'" + key), std::string::npos) << error.format();
    EXPECT_NE(error.message.find(message), std::string::npos) << error.format();
}

}  // namespace glint::test
