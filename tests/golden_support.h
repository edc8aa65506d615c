// Golden-image checks shared by the GPU test files: a display image compared with
// tests/goldens/NAME.png under docs/architecture.md's tolerance; on failure the actual, expected and ×16
// difference images are written to the test output directory. Goldens change only with
// GLINT_UPDATE_GOLDENS=1.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "test_support.h"

namespace glint::test {

inline bool updatingGoldens() {
    const char* update = std::getenv("GLINT_UPDATE_GOLDENS");
    return update && std::string(update) == "1";
}

inline void expectMatchesGolden(const std::string& name, const DisplayImage& actual) {
    const std::string golden = dataPath("goldens/" + name + ".png");
    if (updatingGoldens()) {
        ASSERT_TRUE(writeDisplayImage(actual, golden).ok());
        std::printf("updated golden %s\n", golden.c_str());
        return;
    }
    auto expected = readDisplayImage(golden);
    ASSERT_TRUE(expected.ok()) << expected.error().format() << " (create it with GLINT_UPDATE_GOLDENS=1)";
    const CompareResult result = compareImages(actual, *expected);
    if (!result.passed) {
        const std::string directory = outputDirectory("snapshots");
        (void)writeDisplayImage(actual, directory + "/" + name + ".actual.png");
        (void)writeDisplayImage(*expected, directory + "/" + name + ".expected.png");
        if (result.sizesMatch) (void)writeDisplayImage(differenceImage(actual, *expected), directory + "/" + name + ".diff.png");
        ADD_FAILURE() << name << ": " << result.summary() << "; images written to " << directory;
    }
}

}  // namespace glint::test
