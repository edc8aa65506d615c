// A snapshot suite: a directory of scene and material files with their goldens in
// goldens/NAME.png, and an optional snapshot.json manifest (case list, size, tolerances).
// Loading, per-case settings and sharding only; rendering and comparing live elsewhere.
#pragma once

#include <string>
#include <vector>

#include "image/image_compare.h"
#include "util/diagnostic.h"

namespace glint {

inline constexpr const char* kSnapshotManifestName = "snapshot.json";

struct SnapshotCase {
    std::string name;              // file stem unless the manifest names it; the golden is goldens/NAME.png
    std::string file;              // the scene or material file
    CompareTolerance tolerance;    // docs/architecture.md's defaults, then the suite's, then the case's overrides
    int width = 0, height = 0;     // 0: the scene's own size (materials: 256×256)
};

struct SnapshotSuite {
    std::string directory;         // holds the cases and goldens/
    std::string name;              // the directory's name, for reports
    std::vector<SnapshotCase> cases;  // sorted by name, names unique

    std::string goldenPath(const SnapshotCase& snapshotCase) const;
};

// `path` is a suite directory (its snapshot.json is read when present) or a manifest file (the
// suite is the directory holding it). A bad manifest gives a Diagnostic with file:line:column.
Result<SnapshotSuite> loadSnapshotSuite(const std::string& path);

// Parses "I/N" (0 ≤ I < N): shard I of N.
struct Shard {
    int index = 0, count = 1;
};
Result<Shard> parseShard(const std::string& text);

// Case k of the sorted list goes to shard k mod N, so N shards cover the suite exactly once.
std::vector<SnapshotCase> casesOfShard(const std::vector<SnapshotCase>& cases, Shard shard);

}  // namespace glint
