// The golden check of one case (see golden_check.h) and the run's counts (snapshot_result.h).
#include "snapshot/golden_check.h"

#include <cstdio>
#include <filesystem>

#include "image/image_io.h"

namespace glint {

std::string describeComparison(const CompareResult& comparison, const CompareTolerance& tolerance) {
    char text[256];
    std::snprintf(text, sizeof text, "%ld of %ld pixels (%.3f%%) differ by more than %d/255%s; at most %.3g%% may (max difference %d/255)",
                  comparison.failingPixels, comparison.totalPixels, 100.0 * comparison.failingFraction(),
                  tolerance.channelTolerance, tolerance.allowOnePixelShift ? " (one-pixel shift allowed)" : "",
                  100.0 * tolerance.failingFraction, comparison.maxChannelDifference);
    return text;
}

GoldenCheck checkAgainstGolden(const DisplayImage& actual, const std::string& goldenPath, const CompareTolerance& tolerance) {
    GoldenCheck check;
    std::error_code error;
    if (!std::filesystem::exists(goldenPath, error)) {
        check.message = "no golden at " + goldenPath + " (run with --update to create it)";
        return check;
    }
    auto golden = readDisplayImage(goldenPath);
    if (!golden) {
        check.message = "golden unreadable: " + golden.error().format();
        return check;
    }
    check.golden = std::move(*golden);
    if (check.golden->width != actual.width || check.golden->height != actual.height) {
        check.message = "golden is " + std::to_string(check.golden->width) + "x" + std::to_string(check.golden->height) +
                        ", the render is " + std::to_string(actual.width) + "x" + std::to_string(actual.height);
        return check;
    }
    check.compared = true;
    check.comparison = compareImages(actual, *check.golden, tolerance);
    if (check.comparison.passed) check.outcome = CaseOutcome::Passed;
    else check.message = describeComparison(check.comparison, tolerance);
    return check;
}

int SnapshotReport::count(CaseOutcome outcome) const {
    int total = 0;
    for (const CaseResult& result : cases) total += result.outcome == outcome;
    return total;
}

int SnapshotReport::goldensWritten() const {
    int total = 0;
    for (const CaseResult& result : cases) total += !result.goldenWritten.empty();
    return total;
}

std::string SnapshotReport::summaryLine() const {
    const int errors = count(CaseOutcome::Error);
    std::string line = std::to_string(count(CaseOutcome::Passed)) + " passed, " + std::to_string(count(CaseOutcome::Failed)) +
                       " failed, " + std::to_string(errors) + (errors == 1 ? " error" : " errors");
    if (const int written = goldensWritten(); written > 0)
        line += ", " + std::to_string(written) + (written == 1 ? " golden written" : " goldens written");
    if (!suiteError.empty()) line += " (the suite could not be run)";
    return line;
}

}  // namespace glint
