// Upgrading scene and material JSON written by an older Glint: a chain of steps, each taking a
// document from version N to N+1, applied before the reader sees it. It does not read or
// validate the document (scene_json.cpp does), and refuses files newer than this Glint.
#pragma once

#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "util/diagnostic.h"

namespace glint {

// One schema change: rewrites a document of version `fromVersion` into version fromVersion + 1.
// `isScene` tells a scene ("glint-scene") from a material file ("glint-material").
struct MigrationStep {
    int fromVersion;
    const char* change;  // what changed, for the docs and messages
    void (*upgrade)(nlohmann::json& root, bool isScene);
};

// The steps this Glint knows, oldest first. Version 1 is the first format, so the list is empty
// until the format changes; each change bumps kSceneFormatVersion and adds one step here.
std::span<const MigrationStep> formatMigrations();

// Upgrades `root` (a parsed scene or material whose "version" is `fromVersion`) one step at a
// time up to `toVersion` using `steps`, and sets its "version" to `toVersion`. Refuses a
// version newer than `toVersion` ("written by a newer Glint") and a gap in the chain.
Status migrate(nlohmann::json& root, int fromVersion, int toVersion, std::span<const MigrationStep> steps,
               bool isScene);

}  // namespace glint
