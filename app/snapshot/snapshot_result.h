// The outcome of a snapshot run: per case passed / failed / error with its figures and the
// images written for it, and the counts and summary line. Plain data; the HTML and JUnit
// writers are snapshot_report.h, the golden check is golden_check.h.
#pragma once

#include <string>
#include <vector>

#include "image/image_compare.h"

namespace glint {

// Failed: rendered, but the golden is missing, unreadable, another size, or differs beyond the
// tolerance (--update rewrites it). Error: the case could not be rendered (bad file, GL error).
enum class CaseOutcome { Passed, Failed, Error };

struct CaseResult {
    std::string name;
    std::string file;                 // the scene or material file
    CaseOutcome outcome = CaseOutcome::Error;
    std::string message;              // why it failed or errored; empty when it passed
    bool compared = false;            // `comparison` holds figures (same-size golden was read)
    CompareResult comparison;
    CompareTolerance tolerance;
    int width = 0, height = 0;        // of the render
    // Written for failing cases, relative to the report directory (empty when not written).
    std::string actualImage, expectedImage, diffImage;
    std::string goldenWritten;        // the golden path when --update wrote it
};

struct SnapshotReport {
    std::string suiteName;
    std::string suiteError;           // the suite itself could not be run (then `cases` is empty)
    std::vector<CaseResult> cases;    // in case-name order

    int count(CaseOutcome outcome) const;
    int goldensWritten() const;
    // "N passed, N failed, N errors" (and ", N goldens written" when --update wrote some).
    std::string summaryLine() const;
};

}  // namespace glint
