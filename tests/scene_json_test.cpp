// Scene and material JSON: round trips, and every kind of bad input giving a message that names
// the file and the line (or key), never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "brdf/blinn_phong.h"
#include "scene/json_document.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

// A minimal valid scene with `lightJson` as its only light.
std::string sceneWithLight(const std::string& lightJson) {
    return R"({
  "format": "glint-scene",
  "version": 1,
  "lights": [
    )" + lightJson + R"(
  ],
  "materials": [{"name": "m", "model": "lambert"}],
  "objects": [{"shape": "sphere", "material": "m"}]
})";
}

Diagnostic expectError(const std::string& text) {
    auto scene = parseScene(text, "bad.json");
    EXPECT_FALSE(scene.ok());
    return scene.ok() ? Diagnostic{} : scene.error();
}

TEST(SceneJson, LoadsTheLambertSunScene) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    EXPECT_EQ(scene.width, 256);
    EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
    EXPECT_FLOAT_EQ(scene.camera.orthoHeight, 2.2f);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_NEAR(scene.lights[0].irradiance, kPi, 1e-6f);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].analytic()->values, (std::vector<float>{0.5f, 0.5f, 0.5f}));
}

TEST(SceneJson, SaveAndLoadRoundTrip) {
    const Scene original = test::loadTestScene("scenes/blinn_point.json");
    const std::string path = test::outputDirectory("scene_json") + "/round_trip.json";
    ASSERT_TRUE(saveScene(original, path).ok());
    auto loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    EXPECT_EQ(sceneToJson(*loaded), sceneToJson(original));
    EXPECT_EQ(loaded->materials[1].analytic()->values[7], static_cast<float>(BlinnForm::MaxCosine));
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
        EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << "temporary left: " << entry.path();
}

TEST(SceneJson, DefaultSceneRoundTrips) {
    const Scene scene = defaultScene();
    auto loaded = parseScene(sceneToJson(scene).dump(), "default.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    EXPECT_EQ(sceneToJson(*loaded), sceneToJson(scene));
}

TEST(SceneJson, MaterialFileRoundTrip) {
    Material material = Material::withDefaults("shiny", BrdfModel::BlinnPhong);
    material.analytic()->values[6] = 333.0f;
    const std::string path = test::outputDirectory("scene_json") + "/shiny.glintmat.json";
    ASSERT_TRUE(saveMaterial(material, path).ok());
    auto loaded = loadMaterial(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    EXPECT_EQ(loaded->analytic()->values, material.analytic()->values);
    EXPECT_EQ(loaded->name, "shiny");
}

TEST(SceneJsonErrors, MissingFile) {
    auto scene = loadScene("/no/such/scene.json");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().where.file, "/no/such/scene.json");
    EXPECT_NE(scene.error().message.find("No such file"), std::string::npos);
}

TEST(SceneJsonErrors, InvalidJsonNamesLineAndColumn) {
    const Diagnostic error = expectError("{\n  \"format\": \"glint-scene\",\n  \"version\": 1,,\n}");
    EXPECT_EQ(error.where.file, "bad.json");
    EXPECT_EQ(error.where.line, 3);
    EXPECT_EQ(error.where.column, 16);  // the second comma
    EXPECT_NE(error.message.find("invalid JSON"), std::string::npos);
}

TEST(SceneJsonErrors, UnknownKeyNamesLineAndKey) {
    const Diagnostic error = expectError(sceneWithLight(R"({"type": "directional", "irradiance": 1, "colour": [1, 1, 1]})"));
    EXPECT_EQ(error.where.line, 5);
    EXPECT_NE(error.message.find("'colour'"), std::string::npos) << error.format();
    EXPECT_NE(error.message.find("unknown key"), std::string::npos);
    EXPECT_NE(error.message.find("color"), std::string::npos) << "lists the known keys";
}

TEST(SceneJsonErrors, WrongType) {
    const Diagnostic error = expectError(sceneWithLight(R"({"type": "directional", "irradiance": "bright"})"));
    EXPECT_EQ(error.where.line, 5);
    EXPECT_NE(error.message.find("expected a number, found a string"), std::string::npos) << error.format();
}

TEST(SceneJsonErrors, NegativeIrradianceIsRefused) {
    const Diagnostic error = expectError(sceneWithLight(R"({"type": "directional", "irradiance": -2})"));
    EXPECT_EQ(error.where.line, 5);
    EXPECT_NE(error.message.find("'irradiance'"), std::string::npos);
    EXPECT_NE(error.message.find("out of range"), std::string::npos) << error.format();
}

TEST(SceneJsonErrors, NaNIsRefused) {
    // JSON has no NaN literal; a writer that emits one produces invalid JSON.
    const Diagnostic error = expectError(sceneWithLight(R"({"type": "point", "power": NaN})"));
    EXPECT_EQ(error.where.line, 5);
    EXPECT_NE(error.message.find("invalid JSON"), std::string::npos) << error.format();
}

TEST(SceneJsonErrors, OverflowingNumberIsRefused) {
    const Diagnostic error = expectError(sceneWithLight(R"({"type": "point", "power": 1e999})"));
    EXPECT_NE(error.format().find("bad.json:5:"), std::string::npos) << error.format();
}

TEST(SceneJsonErrors, UnknownModelAndOutOfRangeParameter) {
    auto unknown = parseMaterial(R"({"format": "glint-material", "version": 1, "model": "phonk"})", "m.json");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("unknown model 'phonk'"), std::string::npos);
    EXPECT_NE(unknown.error().message.find("lambert"), std::string::npos);
    auto outOfRange = parseMaterial("{\"format\": \"glint-material\", \"version\": 1,\n \"model\": \"lambert\",\n \"albedo\": [0.5, 1.5, 0.5]}", "m.json");
    ASSERT_FALSE(outOfRange.ok());
    EXPECT_EQ(outOfRange.error().where.line, 3);
    EXPECT_NE(outOfRange.error().message.find("albedo[1]"), std::string::npos) << outOfRange.error().format();
}

// A material file whose third line holds `body` (after "model": ...).
Result<Material> materialFile(const std::string& model, const std::string& body) {
    return parseMaterial("{\"format\": \"glint-material\", \"version\": 1,\n \"model\": \"" + model + "\",\n " + body + "}",
                         "metal.json");
}

// The file is refused with a message that names it, the line (the body's by default) and `expected`.
void expectRefused(const Result<Material>& result, const std::string& expected, int line = 3) {
    ASSERT_FALSE(result.ok()) << expected;
    EXPECT_EQ(result.error().where.file, "metal.json");
    EXPECT_EQ(result.error().where.line, line) << result.error().format();
    EXPECT_NE(result.error().message.find(expected), std::string::npos) << result.error().format();
}

TEST(SceneJsonErrors, IndexOfRefractionMustBePositive) {
    for (const std::string bad : {"0", "-1.5", "[1.5, 0, 1.5]", "[1.5, 1.5, -0.2]"}) {
        const auto result = materialFile("cook_torrance", "\"ior\": " + bad);
        expectRefused(result, "'ior");
        expectRefused(result, "greater than 0");
    }
    expectRefused(materialFile("cook_torrance", "\"ior\": NaN"), "invalid JSON");
    expectRefused(materialFile("cook_torrance", "\"extinction\": -1"), "'extinction'");
    expectRefused(materialFile("cook_torrance", "\"distribution\": \"phong\""), "beckmann");
    expectRefused(materialFile("ward", "\"roughness_x\": 0"), "'roughness_x'");
    expectRefused(materialFile("moonlight", "\"ior\": 1.5"), "unknown model 'moonlight'", 2);
    auto good = materialFile("cook_torrance", "\"ior\": [0.18, 0.42, 1.37]");
    ASSERT_TRUE(good.ok()) << good.error().format();
    EXPECT_FLOAT_EQ(good->analytic()->values[4], 0.42f);
    auto noModel = parseMaterial("{\"format\": \"glint-material\", \"version\": 1,\n \"ior\": 1.5}", "metal.json");
    ASSERT_FALSE(noModel.ok());
    EXPECT_NE(noModel.error().message.find("'model'"), std::string::npos) << noModel.error().format();
}

TEST(SceneJsonErrors, VersionAndFormat) {
    EXPECT_NE(expectError(R"({"format": "glint-scene"})").message.find("version"), std::string::npos);
    EXPECT_NE(expectError(R"({"format": "glint-scene", "version": 7})").message.find("newer Glint"), std::string::npos);
    auto newerMaterial = parseMaterial(R"({"format": "glint-material", "version": 99, "model": "lambert"})", "m.json");
    ASSERT_FALSE(newerMaterial.ok());
    EXPECT_NE(newerMaterial.error().format().find("m.json:1:"), std::string::npos) << newerMaterial.error().format();
    EXPECT_NE(newerMaterial.error().format().find("written by a newer Glint"), std::string::npos);
    EXPECT_NE(expectError(R"({"format": "something", "version": 1})").message.find("glint-scene"), std::string::npos);
    EXPECT_NE(expectError(R"([1, 2, 3])").message.find("must be a JSON object"), std::string::npos);
}

TEST(SceneJsonErrors, ReferencesAndGeometry) {
    const std::string missingMaterial = R"({"format": "glint-scene", "version": 1,
      "objects": [{"shape": "sphere", "material": "ghost"}]})";
    EXPECT_NE(expectError(missingMaterial).message.find("no material named 'ghost'"), std::string::npos);
    const std::string zeroRadius = R"({"format": "glint-scene", "version": 1, "materials": [{"name": "m", "model": "lambert"}],
      "objects": [{"shape": "sphere", "radius": 0, "material": "m"}]})";
    EXPECT_NE(expectError(zeroRadius).message.find("greater than 0"), std::string::npos);
    const std::string badCamera = R"({"format": "glint-scene", "version": 1, "camera": {"position": [0, 0, 0], "target": [0, 0, 0]}})";
    EXPECT_NE(expectError(badCamera).message.find("must differ"), std::string::npos);
}

TEST(JsonDocument, LocatesNestedValues) {
    auto document = JsonDocument::parse("{\n  \"a\": [1,\n    {\"b/c\": true}]\n}", "x.json");
    ASSERT_TRUE(document.ok());
    EXPECT_EQ(document->locate("/a").line, 2);
    EXPECT_EQ(document->locate("/a/1").line, 3);
    const SourceLocation key = document->locate("/a/1/b~1c");
    EXPECT_EQ(key.line, 3);
    EXPECT_EQ(key.column, 6);
    EXPECT_EQ(document->locate("/missing").line, 0);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST(SceneJson, ToneMapRoundTripsAndUnknownCurvesAreRefused) {
    Scene scene = defaultScene();
    scene.display.toneMap = ToneMap::AcesFilmic;
    auto reread = parseScene(sceneToJson(scene).dump(2), "tone.json");
    ASSERT_TRUE(reread.ok()) << reread.error().format();
    EXPECT_EQ(reread->display.toneMap, ToneMap::AcesFilmic);
    nlohmann::json text = sceneToJson(scene);
    text["display"]["tone_map"] = "filmic-ish";
    auto refused = parseScene(text.dump(2), "tone.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().format().find("tone_map"), std::string::npos) << refused.error().format();
}

// `glint bench --scene-file tests/bench/scenes/editor_default.json` times the scene the editor opens with.
TEST(SceneJson, TheEditorBenchSceneIsTheDefaultScene) {
    auto scene = loadScene(std::string(GLINT_TEST_DATA_DIR) + "/bench/scenes/editor_default.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    EXPECT_EQ(sceneToJson(*scene), sceneToJson(defaultScene())) << sceneToJson(defaultScene()).dump(2);
}

}  // namespace
}  // namespace glint
