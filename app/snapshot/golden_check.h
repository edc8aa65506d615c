// Checks one rendered image against its golden PNG (read through OpenImageIO) and decides the
// case's outcome and message. Writes nothing: the snapshot command writes images and goldens.
#pragma once

#include <optional>
#include <string>

#include "image/image.h"
#include "snapshot/snapshot_result.h"

namespace glint {

struct GoldenCheck {
    CaseOutcome outcome = CaseOutcome::Failed;  // Passed or Failed
    std::string message;                        // empty when passed
    std::optional<DisplayImage> golden;         // the golden that was read, if any
    bool compared = false;
    CompareResult comparison;
};

GoldenCheck checkAgainstGolden(const DisplayImage& actual, const std::string& goldenPath, const CompareTolerance& tolerance);

// "12 of 4096 pixels (0.293%) differ by more than 5/255; at most 0.1% may (max difference 40/255)".
std::string describeComparison(const CompareResult& comparison, const CompareTolerance& tolerance);

}  // namespace glint
