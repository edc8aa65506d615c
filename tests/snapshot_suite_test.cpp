// Snapshot suites without GL: manifest reading and its located errors, tolerance overrides,
// sharding, the one-pixel shift allowance, report escaping, the preview stage and text labels.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include "image/contact_sheet.h"
#include "scene/preview_stage.h"
#include "snapshot/case_source.h"
#include "snapshot/golden_check.h"
#include "snapshot/snapshot_report.h"
#include "util/text.h"
#include "snapshot/snapshot_suite.h"
#include "test_support.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

constexpr const char* kMaterial = R"({ "format": "glint-material", "version": 1, "model": "lambert" })";

// A fresh suite directory with material files a.json … e.json.
fs::path makeSuite(const std::string& name) {
    const fs::path directory = fs::path(test::outputDirectory("snapshot_suite_test")) / name;
    fs::remove_all(directory);
    for (const char* file : {"e", "c", "a", "d", "b"}) writeFile(directory / (std::string(file) + ".json"), kMaterial);
    return directory;
}

TEST(SnapshotSuite, DiscoversJsonFilesSortedWithDefaultTolerance) {
    const fs::path directory = makeSuite("discover");
    writeFile(directory / "notes.txt", "not a case");
    auto suite = loadSnapshotSuite(directory.string());
    ASSERT_TRUE(suite.ok()) << suite.error().format();
    ASSERT_EQ(suite->cases.size(), 5u);
    EXPECT_EQ(suite->cases[0].name, "a");
    EXPECT_EQ(suite->cases[4].name, "e");
    EXPECT_EQ(suite->cases[0].tolerance.channelTolerance, 5);
    EXPECT_DOUBLE_EQ(suite->cases[0].tolerance.failingFraction, 0.001);
    EXPECT_FALSE(suite->cases[0].tolerance.allowOnePixelShift);
    EXPECT_EQ(suite->goldenPath(suite->cases[1]), (directory / "goldens" / "b.png").string());
}

TEST(SnapshotSuite, ManifestOverridesPerSuiteAndPerCase) {
    const fs::path directory = makeSuite("manifest");
    writeFile(directory / "snapshot.json", R"({
  "format": "glint-snapshot-suite", "version": 1, "width": 64, "height": 48,
  "tolerance": { "channel": 3, "failing_percent": 1 },
  "cases": [
    { "file": "b.json" },
    { "file": "a.json", "name": "first", "width": 32, "height": 32, "tolerance": { "allow_shift": true, "channel": 9 } }
  ]
})");
    auto suite = loadSnapshotSuite((directory / "snapshot.json").string());
    ASSERT_TRUE(suite.ok()) << suite.error().format();
    ASSERT_EQ(suite->cases.size(), 2u);
    const SnapshotCase& b = suite->cases[0];
    const SnapshotCase& first = suite->cases[1];
    EXPECT_EQ(b.name, "b");
    EXPECT_EQ(b.width, 64);
    EXPECT_EQ(b.tolerance.channelTolerance, 3);
    EXPECT_DOUBLE_EQ(b.tolerance.failingFraction, 0.01);
    EXPECT_FALSE(b.tolerance.allowOnePixelShift);
    EXPECT_EQ(first.name, "first");
    EXPECT_EQ(first.width, 32);
    EXPECT_EQ(first.tolerance.channelTolerance, 9);
    EXPECT_DOUBLE_EQ(first.tolerance.failingFraction, 0.01);  // inherited from the suite
    EXPECT_TRUE(first.tolerance.allowOnePixelShift);
}

TEST(SnapshotSuite, ManifestMistakesAreLocated) {
    const fs::path directory = makeSuite("bad_manifest");
    const std::string manifest = (directory / "snapshot.json").string();
    auto expectError = [&](const std::string& text, const std::string& fragment) {
        writeFile(manifest, text);
        auto suite = loadSnapshotSuite(directory.string());
        ASSERT_FALSE(suite.ok()) << text;
        EXPECT_NE(suite.error().format().find(fragment), std::string::npos) << suite.error().format();
    };
    expectError("{\n \"format\": \"glint-snapshot-suite\", \"version\": 1,\n \"tolerence\": {}\n}", "snapshot.json:3:2: snapshot manifest 'tolerence': unknown key");
    expectError("{\n \"format\": \"glint-snapshot-suite\", \"version\": 1,\n \"tolerance\": { \"channel\": 300 }\n}", "snapshot.json:3:17: tolerance 'channel': 300 is out of range");
    expectError("{ \"format\": \"glint-snapshot-suite\", \"version\": 1,\n \"cases\": [ { \"file\": \"a.json\" },\n  { \"file\": \"x/a.json\" } ] }", "snapshot.json:3:3: case name 'a' is used twice");
    expectError("{ \"format\": \"glint-snapshot-suite\", \"version\": 1, \"cases\": [ { \"file\": \"a.json\", \"name\": \"../up\" } ] }", "may hold only letters");
    expectError("{ \"format\": \"glint-snapshot-suite\", \"version\": 1, \"width\": 64 }", "give both \"width\" and \"height\"");
    expectError("{ \"format\": \"glint-scene\", \"version\": 1 }", "'format': expected \"glint-snapshot-suite\"");
    EXPECT_FALSE(loadSnapshotSuite((directory / "no_such_dir").string()).ok());
}

TEST(SnapshotSuite, ShardsCoverEveryCaseExactlyOnce) {
    std::vector<SnapshotCase> cases;
    for (int i = 0; i < 7; ++i) cases.push_back({"case" + std::to_string(i), "", {}, 0, 0});
    for (int count = 1; count <= 4; ++count) {
        std::multiset<std::string> seen;
        for (int index = 0; index < count; ++index)
            for (const SnapshotCase& c : casesOfShard(cases, {index, count})) seen.insert(c.name);
        EXPECT_EQ(seen.size(), cases.size());
        for (const SnapshotCase& c : cases) EXPECT_EQ(seen.count(c.name), 1u);
    }
    EXPECT_EQ(casesOfShard(cases, {1, 3}).front().name, "case1");
    EXPECT_TRUE(parseShard("1/2").ok());
    EXPECT_FALSE(parseShard("2/2").ok());
    EXPECT_FALSE(parseShard("0/0").ok());
    EXPECT_FALSE(parseShard("half").ok());
}

TEST(SnapshotCompare, OnePixelShiftAllowanceForEdges) {
    // A vertical edge moved by one pixel: every pixel of one column fails without the allowance.
    DisplayImage golden(20, 20), actual(20, 20);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            for (int c = 0; c < 3; ++c) {
                golden.pixels[(y * 20 + x) * 3 + c] = x >= 10 ? 200 : 0;
                actual.pixels[(y * 20 + x) * 3 + c] = x >= 11 ? 200 : 0;
            }
    CompareTolerance strict;
    const CompareResult without = compareImages(actual, golden, strict);
    EXPECT_EQ(without.failingPixels, 20);
    EXPECT_EQ(without.maxChannelDifference, 200);
    CompareTolerance shifted;
    shifted.allowOnePixelShift = true;
    const CompareResult with = compareImages(actual, golden, shifted);
    EXPECT_EQ(with.failingPixels, 0);
    EXPECT_TRUE(with.passed);
    // A two-pixel shift is not allowed.
    for (int y = 0; y < 20; ++y)
        for (int c = 0; c < 3; ++c) actual.pixels[(y * 20 + 11) * 3 + c] = 0;
    EXPECT_EQ(compareImages(actual, golden, shifted).failingPixels, 20);
    EXPECT_NE(describeComparison(without, strict).find("20 of 400 pixels (5.000%) differ by more than 5/255"), std::string::npos);
}

TEST(SnapshotReport, EscapesMarkupAndCountsOutcomes) {
    EXPECT_EQ(escapeMarkup("a<b & \"c\" 'd'>\x01"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
    SnapshotReport report;
    report.suiteName = "s<1>";
    CaseResult passed, failed, broken;
    passed.name = "p", passed.outcome = CaseOutcome::Passed;
    failed.name = "f", failed.outcome = CaseOutcome::Failed, failed.message = "x < y";
    failed.actualImage = "images/f.actual.png";  // no golden: neither expected nor difference
    broken.name = "b", broken.outcome = CaseOutcome::Error, broken.message = "bad & worse";
    report.cases = {broken, failed, passed};
    EXPECT_EQ(report.summaryLine(), "1 passed, 1 failed, 1 error");
    const std::string junit = junitReport(report);
    EXPECT_NE(junit.find("tests=\"3\" failures=\"1\" errors=\"1\""), std::string::npos);
    EXPECT_NE(junit.find("<failure message=\"x &lt; y\">actual: images/f.actual.png</failure>"), std::string::npos) << junit;
    EXPECT_NE(junit.find("<error message=\"bad &amp; worse\">"), std::string::npos);
    const std::string html = htmlReport(report);
    EXPECT_LT(html.find("id=\"f\""), html.find("id=\"b\""));  // failures first, then errors, then passes
    EXPECT_LT(html.find("id=\"b\""), html.find("id=\"p\""));
    EXPECT_NE(html.find("s&lt;1&gt;"), std::string::npos);
}

TEST(PreviewStage, SphereOnAFadingFloorInTheStudio) {
    const Material material = Material::withDefaults("gold", BrdfModel::BlinnPhong);
    const Scene stage = previewStage(material, 200, 100);
    EXPECT_EQ(stage.width, 200);
    EXPECT_EQ(stage.height, 100);
    ASSERT_EQ(stage.lights.size(), 1u);
    EXPECT_EQ(stage.lights[0].type, LightType::Directional);
    EXPECT_TRUE(stage.lights[0].castsShadows);
    EXPECT_TRUE(stage.environment.enabled());
    EXPECT_EQ(stage.environment.kind, EnvironmentKind::Studio);
    EXPECT_EQ(stage.display.toneMap, ToneMap::PbrNeutral);
    EXPECT_EQ(stage.msaaSamples, 4);
    ASSERT_EQ(stage.objects.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<SphereShape>(stage.objects[0].shape));
    EXPECT_EQ(stage.materials[stage.objects[0].materialIndex].name, "gold");
    const auto* floor = std::get_if<PlaneShape>(&stage.objects[1].shape);
    ASSERT_NE(floor, nullptr);
    EXPECT_GT(floor->edgeFade, 0.0f) << "no edge or corner shows";
    EXPECT_EQ(stage.background.zenith.r, stage.background.zenith.b);  // a neutral backdrop
    EXPECT_EQ(stage.background.horizon.r, stage.background.horizon.b);
}

TEST(CaseSource, MaterialsGoOnTheStageAndOtherFormatsAreRefused) {
    const fs::path directory = fs::path(test::outputDirectory("snapshot_suite_test")) / "sources";
    writeFile(directory / "m.json", kMaterial);
    writeFile(directory / "other.json", "{\n  \"format\": \"glint-palette\", \"version\": 1 }");
    auto stage = loadRenderable((directory / "m.json").string());
    ASSERT_TRUE(stage.ok()) << stage.error().format();
    EXPECT_EQ(stage->width, kDefaultMaterialPreviewSize);
    EXPECT_TRUE(stage->environment.enabled()) << "the preview stage";
    auto scene = loadRenderable(test::dataPath("scenes/lambert_sun.json"), 40, 30);
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->width, 40);
    auto other = loadRenderable((directory / "other.json").string());
    ASSERT_FALSE(other.ok());
    EXPECT_NE(other.error().format().find("other.json:2:3: 'format': expected \"glint-scene\" or \"glint-material\""), std::string::npos)
        << other.error().format();
    EXPECT_FALSE(listJsonFiles((directory / "missing").string()).ok());
}

TEST(TextLabel, DrawsLegibleCoverageWithinTheImage) {
    auto font = LabelFont::load();
    ASSERT_TRUE(font.ok()) << font.error().format();
    EXPECT_GT(font->measure("Glint", 16), font->measure("G", 16));
    DisplayImage image(60, 20);
    font->draw(image, 2, 2, "Glint", 14, {255, 255, 255}, 56);
    int lit = 0;
    for (uint8_t value : image.pixels) lit += value > 128;
    EXPECT_GT(lit, 30);
    // Text too wide is cut with an ellipsis, never drawn past maxWidth.
    DisplayImage narrow(100, 20);
    font->draw(narrow, 0, 2, "a very long material name indeed", 14, {255, 255, 255}, 40);
    for (int y = 0; y < 20; ++y)
        for (int x = 41; x < 100; ++x) EXPECT_EQ(narrow.pixels[(y * 100 + x) * 3], 0) << x << "," << y;
    EXPECT_FALSE(LabelFont::load("/no/such/font.ttf").ok());
    EXPECT_FALSE(LabelFont::load(test::dataPath("scenes/lambert_sun.json")).ok());  // not a font
}

TEST(TextLabel, ACopyOutlivesItsOriginal) {
    std::optional<LabelFont> copy;
    {
        auto font = LabelFont::load();
        ASSERT_TRUE(font.ok());
        copy = *font;
    }
    EXPECT_GT(copy->measure("Glint", 16), 0);
}

TEST(ContactSheet, GridWithLabelSpace) {
    auto font = LabelFont::load();
    ASSERT_TRUE(font.ok());
    DisplayImage tile(32, 32);
    std::vector<LabelledImage> entries(5, LabelledImage{"m", &tile});
    const DisplayImage sheet = contactSheet(entries, 0, *font);  // 5 → 3 columns, 2 rows
    EXPECT_EQ(sheet.width, 8 + 3 * (32 + 8));
    EXPECT_GT(sheet.height, 2 * 32 + 3 * 8);
}

}  // namespace
}  // namespace glint
