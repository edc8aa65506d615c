// Scene and material JSON versions: the migration chain upgrades older files one step at a
// time (tested with a synthetic chain, as version 1 is the first format), and files newer than
// this Glint are refused with a message naming both versions.
#include <gtest/gtest.h>

#include "scene/format_migration.h"
#include "scene/scene.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

using nlohmann::json;

// A synthetic history: version 1 called "diffuse_albedo" "kd"; version 2 added "display".
void renameKd(json& root, bool isScene) {
    json& material = isScene ? root["materials"][0] : root;
    if (material.contains("kd")) {
        material["diffuse_albedo"] = material["kd"];
        material.erase("kd");
    }
}
void addDisplay(json& root, bool isScene) {
    if (isScene && !root.contains("display")) root["display"] = {{"exposure", 0}};
}
constexpr MigrationStep kSyntheticSteps[] = {{1, "kd → diffuse_albedo", renameKd}, {2, "display added", addDisplay}};

TEST(FormatMigration, UpgradesOneStepAtATime) {
    json scene = {{"format", "glint-scene"}, {"version", 1}, {"materials", {{{"model", "blinn_phong"}, {"kd", 0.5}}}}};
    ASSERT_TRUE(migrate(scene, 1, 3, kSyntheticSteps, true).ok());
    EXPECT_EQ(scene["version"], 3);
    EXPECT_EQ(scene["materials"][0]["diffuse_albedo"], 0.5);
    EXPECT_FALSE(scene["materials"][0].contains("kd"));
    EXPECT_EQ(scene["display"]["exposure"], 0);
    json material = {{"format", "glint-material"}, {"version", 2}, {"kd", 0.5}};
    ASSERT_TRUE(migrate(material, 2, 3, kSyntheticSteps, false).ok());
    EXPECT_TRUE(material.contains("kd"));  // the 1 → 2 step does not run on a version-2 file
    EXPECT_FALSE(material.contains("display"));
}

TEST(FormatMigration, RefusesNewerFilesAndGapsInTheChain) {
    json root = {{"version", 5}};
    auto newer = migrate(root, 5, 3, kSyntheticSteps, true);
    ASSERT_FALSE(newer.ok());
    EXPECT_EQ(newer.error().message, "the file is version 5, written by a newer Glint; this one reads up to version 3");
    auto gap = migrate(root, 0, 3, kSyntheticSteps, true);
    ASSERT_FALSE(gap.ok());
    EXPECT_NE(gap.error().message.find("no migration from it to 1"), std::string::npos);
}

TEST(FormatMigration, TheRealChainReachesTheCurrentVersion) {
    for (int version = 1; version < kSceneFormatVersion; ++version) {
        bool found = false;
        for (const MigrationStep& step : formatMigrations()) found = found || step.fromVersion == version;
        EXPECT_TRUE(found) << "no migration from version " << version;
    }
    auto newer = parseMaterial(R"({"format": "glint-material", "version": 99, "model": "lambert"})", "m.json");
    ASSERT_FALSE(newer.ok());
    EXPECT_NE(newer.error().format().find("m.json:1:"), std::string::npos);
    EXPECT_NE(newer.error().format().find("written by a newer Glint"), std::string::npos);
}

}  // namespace
}  // namespace glint
