// The one policy for files that files name (core/util/reference_confinement.h): what lies inside a
// file's folder, what is refused and how, the refusal log the editor asks from, and the ways to
// allow. The formats' own refusals are tests/hostile_references_test.sh.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test_support.h"
#include "util/reference_confinement.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// asset/scene.json beside asset/inside.png and a sibling folder outside/secret.png, with a link
// asset/linked → ../outside; each test uses its own folder (allowing a file lasts the process).
struct Folders {
    std::string asset, outside, scene;
    explicit Folders(const std::string& name) {
        const std::string root = test::outputDirectory("reference_confinement/" + name);
        asset = root + "/asset", outside = root + "/outside", scene = asset + "/scene.json";
        fs::create_directories(asset + "/maps");
        fs::create_directories(outside);
        std::error_code ignored;
        fs::create_directory_symlink("../outside", asset + "/linked", ignored);
        takeRefusedReferences();  // refusals other tests left
    }
};

TEST(ReferenceConfinement, TheFoldersOwnFilesAndBelowAreRead) {
    const Folders folders("inside");
    const std::vector<std::string> inside = {"inside.png", "maps/wood.png", "maps/../inside.png", folders.asset + "/inside.png"};
    for (const std::string& written : inside) {
        auto confined = confinedReference(written, {folders.scene, 3, 0});
        ASSERT_TRUE(confined.ok()) << written << ": " << confined.error().format();
        const std::string relative = written[0] == '/' ? "inside.png" : written;
        EXPECT_EQ(*confined, fs::path(folders.asset + "/" + relative).lexically_normal());
    }
    EXPECT_TRUE(takeRefusedReferences().empty());
    EXPECT_TRUE(confinedReference("/anywhere/at/all.png", {"", 0, 0}).ok()) << "no naming file: nothing to confine to";
}

TEST(ReferenceConfinement, OutsideIsRefusedByNameWhereItIsNamedAndRecordedOnce) {
    const Folders folders("outside");
    const std::vector<std::string> outside = {folders.outside + "/secret.png", "../outside/secret.png", "linked/secret.png"};
    for (const std::string& written : outside) {
        auto confined = confinedReference(written, {folders.scene, 7, 3});
        ASSERT_FALSE(confined.ok()) << written;
        EXPECT_EQ(confined.error().where.file, folders.scene);
        EXPECT_EQ(confined.error().where.line, 7);
        EXPECT_NE(confined.error().message.find("refused '" + written + "'"), std::string::npos)
            << confined.error().message;
        EXPECT_NE(confined.error().message.find("--allow-outside-references"), std::string::npos);
        EXPECT_TRUE(isReferenceRefusal(confined.error()));
    }
    EXPECT_FALSE(confinedReference("../outside/secret.png", {folders.scene, 9, 0}).ok());  // again: not listed twice
    const auto refused = takeRefusedReferences();
    ASSERT_EQ(refused.size(), 3u);
    EXPECT_EQ(refused[1].referencingFile, folders.scene);
    EXPECT_EQ(refused[1].written, "../outside/secret.png");
    EXPECT_TRUE(takeRefusedReferences().empty()) << "taking them empties the log";
}

TEST(ReferenceConfinement, AllowingOneFileLeavesOthersRefused) {
    const Folders folders("allow_once");
    allowOutsideReferencesOf(folders.scene);
    EXPECT_TRUE(confinedReference("../outside/secret.png", {folders.scene, 1, 0}).ok());
    EXPECT_FALSE(confinedReference("../outside/secret.png", {folders.asset + "/other.json", 1, 0}).ok());
}

TEST(ReferenceConfinement, TheAllowanceAndTheSettingAllowAll) {
    const Folders folders("allowance");
    {
        const OutsideReferencesAllowance allowed;
        EXPECT_TRUE(confinedReference("../outside/secret.png", {folders.scene, 1, 0}).ok());
    }
    EXPECT_FALSE(confinedReference("../outside/secret.png", {folders.scene, 1, 0}).ok()) << "only while it lives";
    setOutsideReferencesAllowed(true);
    EXPECT_TRUE(confinedReference("linked/secret.png", {folders.scene, 1, 0}).ok());
    setOutsideReferencesAllowed(false);
    EXPECT_FALSE(confinedReference("linked/secret.png", {folders.scene, 1, 0}).ok());
    EXPECT_EQ(takeRefusedReferences().size(), 2u);
}

}  // namespace
}  // namespace glint
