// Report writers for a snapshot run: a self-contained HTML page (failures first, hover an image
// to swap actual and expected, the figures per case; images referenced relatively) and JUnit
// XML for CI systems. Text only: the caller writes the files. No timestamps, so reruns match.
#pragma once

#include <string>

#include "snapshot/snapshot_result.h"

namespace glint {

std::string htmlReport(const SnapshotReport& report);
std::string junitReport(const SnapshotReport& report);

}  // namespace glint
