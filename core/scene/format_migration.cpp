// The migration chain for scene and material JSON (see format_migration.h).
#include "scene/format_migration.h"

namespace glint {

std::span<const MigrationStep> formatMigrations() { return {}; }

Status migrate(nlohmann::json& root, int fromVersion, int toVersion, std::span<const MigrationStep> steps,
               bool isScene) {
    if (fromVersion > toVersion)
        return makeError("the file is version " + std::to_string(fromVersion) +
                         ", written by a newer Glint; this one reads up to version " + std::to_string(toVersion));
    for (int version = fromVersion; version < toVersion; ++version) {
        const MigrationStep* step = nullptr;
        for (const MigrationStep& candidate : steps)
            if (candidate.fromVersion == version) step = &candidate;
        if (!step)
            return makeError("version " + std::to_string(version) + " cannot be upgraded: no migration from it to " +
                             std::to_string(version + 1));
        step->upgrade(root, isScene);
    }
    root["version"] = toVersion;
    return success();
}

}  // namespace glint
