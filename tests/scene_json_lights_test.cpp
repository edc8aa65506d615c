// Scene JSON for the new lights, backgrounds and the mirror and glass models: round trips, and a
// located message for each new key's nonsense value. No GL.
#include <gtest/gtest.h>

#include "brdf/glass.h"
#include "scene/scene_json.h"
#include "located_error_support.h"
#include "test_support.h"

namespace glint {
namespace {

// A minimal scene with `lightJson` as its only light (on line 5) and `extra` members at the end.
std::string sceneWith(const std::string& lightJson, const std::string& extra = "") {
    return "{\n  \"format\": \"glint-scene\",\n  \"version\": 1,\n  \"lights\": [\n    " + lightJson +
           "\n  ],\n  \"materials\": [{\"name\": \"m\", \"model\": \"lambert\"}],\n"
           "  \"objects\": [{\"shape\": \"sphere\", \"material\": \"m\"}]" + extra + "\n}";
}

using test::expectLocatedError;

TEST(SceneJsonLights, SpotAmbientAttenuationAndSkyRoundTrip) {
    Scene scene = test::loadTestScene("scenes/spot_light.json");
    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& spot = scene.lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_FLOAT_EQ(spot.coneHalfAngleDegrees, 28.0f);
    EXPECT_FLOAT_EQ(spot.falloffExponent, 2.0f);
    EXPECT_FLOAT_EQ(spot.edgeWidthDegrees, 6.0f);
    EXPECT_NEAR(glm::length(spot.direction), 1.0f, 1e-6f);
    EXPECT_FALSE(spot.attenuation.enabled) << "the classic attenuation is off unless asked for";
    EXPECT_EQ(scene.lights[2].type, LightType::Ambient);
    EXPECT_FLOAT_EQ(scene.lights[2].ambientRadiance, 0.02f);
    scene.lights[1].attenuation = {true, {1.0f, 0.2f, 0.05f}};
    scene.background = {BackgroundKind::Sky, {}, {0.1f, 0.2f, 0.9f}, {0.8f, 0.8f, 0.8f}, {0.2f, 0.1f, 0.0f}};
    const std::string path = test::outputDirectory("scene_json_lights") + "/round_trip.json";
    ASSERT_TRUE(saveScene(scene, path).ok());
    auto loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    // Directions are normalised again on load (an ulp may move); everything else is exact.
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        EXPECT_NEAR(glm::distance(loaded->lights[i].direction, scene.lights[i].direction), 0.0f, 1e-6f);
        loaded->lights[i].direction = scene.lights[i].direction;
    }
    EXPECT_EQ(sceneToJson(*loaded), sceneToJson(scene));
    EXPECT_TRUE(loaded->lights[1].attenuation.enabled);
    EXPECT_EQ(loaded->background.kind, BackgroundKind::Sky);
    EXPECT_EQ(loaded->background.ground, glm::vec3(0.2f, 0.1f, 0.0f));
}

TEST(SceneJsonLights, GlassAndMirrorMaterialsLoad) {
    const Scene scene = test::loadTestScene("scenes/glass_sphere.json");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].analytic()->model, BrdfModel::Glass);
    const GlassParams glass = unpack<Glass>(scene.materials[0].analytic()->values.data());
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    EXPECT_EQ(glass.transparency, GlassTransparency::Fresnel);
    EXPECT_EQ(scene.materials[1].analytic()->model, BrdfModel::Mirror);
    EXPECT_EQ(scene.background.kind, BackgroundKind::Sky);
    // The constant background is still one array.
    EXPECT_EQ(test::loadTestScene("scenes/blinn_point.json").background.kind, BackgroundKind::Constant);
}

TEST(SceneJsonLightsErrors, SpotConeNonsenseIsRefusedWithItsLocation) {
    expectLocatedError(sceneWith(R"({"type": "spot", "cone_half_angle_degrees": -10})"), 5, "cone_half_angle_degrees", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "cone_half_angle_degrees": 0})"), 5, "cone_half_angle_degrees", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "cone_half_angle_degrees": 120})"), 5, "cone_half_angle_degrees", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "cone_half_angle_degrees": 20, "edge_width_degrees": 25})"), 5,
                       "edge_width_degrees", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "edge_width_degrees": -1})"), 5, "edge_width_degrees", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "falloff_exponent": -2})"), 5, "falloff_exponent", "out of range");
    expectLocatedError(sceneWith(R"({"type": "spot", "direction": [0, 0, 0]})"), 5, "direction", "zero vector");
    expectLocatedError(sceneWith(R"({"type": "spot", "power": -5})"), 5, "power", "out of range");
}

TEST(SceneJsonLightsErrors, AmbientAndAttenuationNonsenseIsRefused) {
    expectLocatedError(sceneWith(R"({"type": "ambient", "radiance": -0.1})"), 5, "radiance", "out of range");
    expectLocatedError(sceneWith(R"({"type": "ambient", "position": [0, 1, 0]})"), 5, "position", "unknown key");
    expectLocatedError(sceneWith(R"({"type": "point", "attenuation": [1, -0.5, 0]})"), 5, "attenuation", "out of range");
    expectLocatedError(sceneWith(R"({"type": "point", "attenuation": [0, 0, 0]})"), 5, "attenuation", "must not all be zero");
    expectLocatedError(sceneWith(R"({"type": "directional", "attenuation": [1, 0, 0]})"), 5, "attenuation", "unknown key");
}

TEST(SceneJsonLightsErrors, BackgroundNonsenseIsRefused) {
    const std::string light = R"({"type": "ambient"})";
    expectLocatedError(sceneWith(light, ",\n  \"background\": {\"type\": \"sky\", \"zenith\": [0, -1, 0]}"), 9, "zenith", "out of range");
    expectLocatedError(sceneWith(light, ",\n  \"background\": {\"type\": \"starfield\"}"), 9, "type", "unknown value 'starfield'");
    expectLocatedError(sceneWith(light, ",\n  \"background\": {\"type\": \"constant\", \"zenith\": [1, 1, 1]}"), 9, "zenith", "unknown key");
}

TEST(SceneJsonLightsErrors, GlassAndMirrorNonsenseIsRefused) {
    const auto material = [](const std::string& body) {
        return parseMaterial("{\"format\": \"glint-material\", \"version\": 1,\n" + body + "}", "glass.json");
    };
    for (const char* body : {R"("model": "glass", "ior": -1.5)", R"("model": "glass", "ior": 0.5)",
                             R"("model": "glass", "absorption": [0, -1, 0])", R"("model": "glass", "transmission": 1.5)",
                             R"("model": "mirror", "ior": [0, 1, 1])", R"("model": "mirror", "extinction": -1)"}) {
        auto result = material(body);
        ASSERT_FALSE(result.ok()) << body;
        EXPECT_EQ(result.error().where.line, 2) << result.error().format();
        EXPECT_NE(result.error().message.find("out of range"), std::string::npos) << result.error().format();
    }
    auto nan = material(R"("model": "glass", "ior": NaN)");
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.error().where.line, 2);
    auto unknownMode = material(R"("model": "glass", "transparency": "frosted")");
    ASSERT_FALSE(unknownMode.ok());
    EXPECT_NE(unknownMode.error().message.find("frosted"), std::string::npos);
}

TEST(SceneJsonMaterials, PerChannelQuantitiesTakeOneNumberOrThreeAndRoundTrip) {
    auto mirror = parseMaterial("{\"format\": \"glint-material\", \"version\": 1, \"model\": \"mirror\",\n"
                                "\"ior\": 1.5, \"extinction\": [0.5, 1, 2]}", "mirror.json");
    ASSERT_TRUE(mirror.ok()) << mirror.error().format();
    EXPECT_EQ(std::vector<float>(mirror->analytic()->values.begin(), mirror->analytic()->values.begin() + 6),
              (std::vector<float>{1.5f, 1.5f, 1.5f, 0.5f, 1.0f, 2.0f}));
    const nlohmann::json saved = materialToJson(*mirror);
    EXPECT_EQ(saved.at("ior"), nlohmann::json({1.5f, 1.5f, 1.5f}));
    EXPECT_EQ(saved.at("extinction"), nlohmann::json({0.5f, 1.0f, 2.0f}));
    // The old mirror keys are gone: every model calls the complex index ior + extinction.
    auto old = parseMaterial("{\"format\": \"glint-material\", \"version\": 1, \"model\": \"mirror\",\n"
                             "\"eta\": 1.5}", "mirror.json");
    ASSERT_FALSE(old.ok());
    EXPECT_EQ(old.error().where.line, 2);
    EXPECT_NE(old.error().message.find("unknown key"), std::string::npos) << old.error().format();
}

}  // namespace
}  // namespace glint
