// One image against its golden PNG in tests/goldens (DESIGN.md's tolerance), for GPU tests
// outside the snapshot suite: GLINT_UPDATE_GOLDENS=1 rewrites the golden instead; on failure the
// actual image is written to failureDirectory. Renders nothing itself.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "image/image_io.h"
#include "snapshot/golden_check.h"
#include "test_support.h"

namespace glint::test {

inline void expectMatchesGoldenPng(const std::string& name, const DisplayImage& actual, const std::string& failureDirectory) {
    const std::string golden = dataPath("goldens/" + name + ".png");
    const char* update = std::getenv("GLINT_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        ASSERT_TRUE(writeDisplayImage(actual, golden).ok());
        return;
    }
    const GoldenCheck check = checkAgainstGolden(actual, golden, CompareTolerance{});
    if (check.outcome != CaseOutcome::Passed) {
        (void)writeDisplayImage(actual, failureDirectory + "/" + name + ".actual.png");
        ADD_FAILURE() << name << ": " << check.message;
    }
}

}  // namespace glint::test
